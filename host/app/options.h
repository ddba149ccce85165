// What the user asked for on the command line (docs/command-line.md, Options).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "scene/scene_overrides.h"

#include "core/pixel_rect.h"

namespace clr {

struct Options {
    std::string scene_path;
    std::string output_path;     // image, or frame pattern (%04d, ####) for an animation
    std::string video_path;      // --video: .mp4 or .gif
    std::string frames;          // --frames: "7", "0-99", "5,7,10-20"; empty: every frame
    bool assemble = false;       // --assemble: encode the frames named by -o instead of rendering
    bool resume = false;         // --resume: frames whose file is finished are not rendered again
    int quality = 18;            // --quality: x264 CRF of MP4 videos (0 best .. 51 worst)
    std::string device;          // selector; empty: CLRENDER_DEVICE, else the first CPU device
    std::optional<int> width;    // --size
    std::optional<int> height;
    std::optional<int> samples_per_pixel;  // --spp
    bool double_precision = false;         // --precision double
    bool list_devices = false;
    bool print_frame_count = false;  // --frame-count: print the animation's frame count, exit
    bool reference = false;      // render with the double-precision host reference
    bool placeholders = false;   // stand-in images for missing ones
    bool quiet = false;
    std::string stats_path;      // JSON timing report
    std::string kernel_dir;      // load kernels from this folder (kernel development)
    // HDR and alpha outputs (docs/command-line.md): EXR is chosen by -o's extension.
    bool alpha = false;          // --alpha: the background transparent (coverage as alpha)
    // Progress and control (docs/command-line.md, Progress; Threads; Crop).
    std::string progress = "bar";   // --progress: bar (on a terminal), none, json
    std::optional<int> threads;     // -t: compute units of the CPU device
    std::optional<PixelRect> crop;  // --crop x0,x1,y0,y1: only these pixels, half-open

    // The pixel explainer (docs/explain-pixel.md): --explain-pixel X,Y prints how the
    // reference computes that pixel, and the kernels' bytes for it, instead of writing files.
    struct PixelPosition {
        int x = 0;  // column from the left, 0-based
        int y = 0;  // row from the top, 0-based
    };
    std::optional<PixelPosition> explain_pixel;
    // Scene overrides and checks (docs/command-line.md, Scene overrides and checks)
    std::vector<SceneOverride> overrides;  // -D key=value, in command-line order
    std::optional<unsigned> seed;          // --seed: the sample pattern's seed (clrender.seed)
    bool strict = false;                   // --strict: a warning fails the run (exit 2)
    bool check = false;                    // --check: validate and summarise, no device, nothing written
    bool plan = false;                     // --plan: validate as --check, print the run's plan as JSON
    // Joining tiles (docs/command-line.md, Joining tiles): --join TILE, repeatable; the image
    // is made from these --crop tiles instead of rendered.
    std::vector<std::string> join;
    // Streaming to tev (docs/command-line.md): HOST:PORT of a running tev viewer that shows
    // each rendered frame; empty: none.
    std::string display_server;
};

// Parses argv. Returns the options, or an exit code when parsing alone decided the outcome
// (--help: 0, a usage error: 1, after printing the message).
struct ParsedOptions {
    Options options;
    std::optional<int> exit_code;
};
ParsedOptions parse_options(int argc, const char* const* argv);

// --size's "WIDTHxHEIGHT" with positive integers (of at most six digits); false otherwise.
bool parse_image_size(const std::string& text, int& width, int& height);

}  // namespace clr
