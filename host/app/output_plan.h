// What a run will produce, decided and checked before anything renders: which frames, which
// image files, which video, and that the encoder exists (SPEC 3 and 4).
#pragma once

#include <string>
#include <vector>

#include "app/options.h"
#include "scene/scene.h"

namespace clr {

struct OutputPlan {
    std::vector<int> frames;   // animation frames to produce, ascending
    int frame_count = 1;       // frames in the whole animation (1 for a still)
    std::string image_target;  // image path, or frame pattern when image_is_pattern; empty: none
    bool image_is_pattern = false;
    std::string video_path;    // empty: no video
    std::string encoder;       // the ffmpeg program, when there is a video
    bool assemble = false;     // read the frames from image_target instead of rendering them

    // The image file of `frame`, or empty when no image is written.
    std::string image_path(int frame) const;
};

// Throws UsageError for contradictory or incomplete requests and OutputError when a video is
// asked for and no encoder is found.
OutputPlan plan_outputs(const Options& options, const Scene& scene);

}  // namespace clr
