// POV-Ray's render settings for a converted clrender scene, as an .ini file beside the scene
// text (docs/benchmarks.md, Against POV-Ray): the image size, the sampling that matches
// clrender's samples per pixel, and output without any gamma conversion.
#pragma once

#include <string>

#include "scene/scene.h"

namespace clr::bench {

// How POV-Ray samples a pixel for clrender's `samples_per_pixel`.
struct PovraySampling {
    bool antialias = false;  // false: one ray through the pixel's centre, clrender's single sample
    int depth = 0;           // with antialias: a depth x depth jittered grid in each pixel that needs it
};

// One sample: no antialiasing, the same one ray per pixel. n samples: POV-Ray's method 1 with
// threshold 0, depth round(sqrt(n)) (at least 2): every pixel that differs at all from a
// neighbour gets depth^2 jittered samples, close to clrender's n; a pixel equal to its
// neighbours keeps its one ray, where clrender still traces n.
PovraySampling povray_sampling(int samples_per_pixel);

// The .ini text that renders the scene file `pov_path` at the scene's size with that sampling.
// The output file is named on POV-Ray's command line (+O).
std::string povray_ini_text(const Scene& scene, const std::string& pov_path);

}  // namespace clr::bench
