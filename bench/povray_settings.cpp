#include "bench/povray_settings.h"

#include <algorithm>
#include <cmath>

namespace clr::bench {

PovraySampling povray_sampling(int samples_per_pixel) {
    if (samples_per_pixel <= 1) return {};
    const int depth = static_cast<int>(std::lround(std::sqrt(static_cast<double>(samples_per_pixel))));
    return {true, std::clamp(depth, 2, 9)};  // POV-Ray takes a depth from 1 to 9
}

std::string povray_ini_text(const Scene& scene, const std::string& pov_path) {
    const PovraySampling sampling = povray_sampling(scene.sampling.samples_per_pixel);
    std::string text = "; POV-Ray settings written by clrender_to_povray (docs/benchmarks.md, Against POV-Ray)\n";
    text += "Input_File_Name=\"" + pov_path + "\"\n";
    text += "Width=" + std::to_string(scene.width) + "\nHeight=" + std::to_string(scene.height) + "\n";
    if (sampling.antialias) {
        text += "Antialias=on\nSampling_Method=1\nAntialias_Threshold=0.0\nAntialias_Depth=" +
                std::to_string(sampling.depth) + "\nJitter=on\n";
    } else {
        text += "Antialias=off\n";
    }
    // Colours are display values in and out (docs/scene-format.md, Conventions: Colour).
    text += "File_Gamma=1.0\nOutput_File_Type=N\nOutput_Alpha=off\nBits_Per_Color=8\nDisplay=off\n";
    return text;
}

}  // namespace clr::bench
