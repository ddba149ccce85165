// What a run will produce, decided and checked before anything renders: which frames, which
// image files, which video, that the encoder exists (docs/command-line.md, Outputs), and that every output
// is a safe place to write: not an input or another output of the run, not a FIFO, device or
// folder (output_roles.h, output_target.h), in a folder where a file can be created.
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
    std::string video_path;    // empty: no video; a symbolic link is resolved to its target
    std::string stats_path;    // --stats report; empty: none
    std::string encoder;       // the ffmpeg program, when there is a video
    bool assemble = false;     // read the frames from image_target instead of rendering them

    // The image file of `frame`, or empty when no image is written.
    std::string image_path(int frame) const;
    // A single image file (a still) is renamed into place only together with the --stats
    // report, once both are written; frames of a pattern each as soon as they are finished
    // (so that --resume finds them after an interruption).
    bool image_waits_for_stats() const { return !image_is_pattern; }
    // --resume: whether `frame` was written already, i.e. its file is a regular file (or a
    // link to one). A folder or FIFO under a frame's name is no frame: it is planned as an
    // output, and refused as one, instead of being skipped and leaving the frame missing.
    bool frame_on_disk(int frame) const;
};

// Throws UsageError for contradictory or incomplete requests, OutputError when a video is
// asked for and no encoder is found, and OutputError when an output would replace an input
// or another output, is not a regular file, or its folder cannot take a new file. Removes
// the temporary files that crashed runs left in the output folders (temp_files.h).
OutputPlan plan_outputs(const Options& options, const Scene& scene);

}  // namespace clr
