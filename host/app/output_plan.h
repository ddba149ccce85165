// What a run will produce, decided and checked before anything renders: which frames, which
// image files, which video, that the encoder exists (docs/command-line.md, Outputs), and that every output
// is a safe place to write: not an input or another output of the run, not a FIFO, device or
// folder (output_roles.h, output_target.h), in a folder where a file can be created.
#pragma once

#include <set>
#include <string>
#include <vector>

#include "app/options.h"
#include "output/output_roles.h"
#include "scene/scene.h"

namespace clr {

struct OutputPlan {
    std::vector<int> frames;   // animation frames to produce, ascending
    int frame_count = 1;       // frames in the whole animation (1 for a still)
    std::string image_target;  // image path, or frame pattern when image_is_pattern; empty: none
    bool image_is_pattern = false;
    // --frames without -o or --video: frames named <scene name>_NNNN.png, with this many
    // digits (0: image_target is the pattern). Built without a pattern, so that a '%' or '#'
    // in the scene's name is never read as a placeholder.
    int default_frame_digits = 0;
    std::string default_frame_stem;  // "<scene name>_"
    std::string video_path;    // empty: no video; a symbolic link is resolved to its target
    std::string video_name;    // the video as named (--video, or the default name), before that
    std::string stats_path;    // --stats report; empty: none (or standard output)
    bool stats_to_standard_output = false;  // --stats -
    std::string encoder;       // the ffmpeg program, when there is a video
    bool assemble = false;     // read the frames from image_target instead of rendering them
    // Folders to make before the first output is written (output_folders.h), each list with
    // the output that needs it, for messages.
    struct MissingFolders {
        std::string output;
        std::vector<std::string> folders;  // outermost first
    };
    std::vector<MissingFolders> missing_folders;
    // --resume: the frames whose file is finished (finished_frames.h), and a warning for each
    // file under a frame's name that is rendered again; printed before rendering.
    std::set<int> finished_frames;
    std::vector<std::string> warnings;

    // The image file of `frame`, or empty when no image is written.
    std::string image_path(int frame) const;
    // A single image file (a still) is renamed into place only together with the --stats
    // report, once both are written; frames of a pattern each as soon as they are finished
    // (so that --resume finds them after an interruption).
    bool image_waits_for_stats() const { return !image_is_pattern; }
    // --resume: whether `frame` was written already by a render like this run's
    // (finished_frames.h). A folder or FIFO under a frame's name is no frame: it is planned as
    // an output, and refused as one, instead of being skipped and leaving the frame missing.
    bool frame_on_disk(int frame) const { return finished_frames.count(frame) > 0; }
    // --resume with one image (a still, a tile, one frame) that is finished: nothing to render.
    bool only_image_finished() const {
        return frames.size() == 1 && video_path.empty() && frame_on_disk(frames.front());
    }
};

// Throws UsageError for contradictory or incomplete requests, OutputError when a video is
// asked for and no encoder is found, and OutputError when an output would replace an input
// or another output, is not a regular file, or its folder cannot take a new file. Removes
// the temporary files that crashed runs left in the output folders (temp_files.h), except
// for --check and --plan, which change nothing.
OutputPlan plan_outputs(const Options& options, const Scene& scene);

// Registers every file the scene reads as an input: the scene and its images (placeholders
// keep the missing path), so that no output replaces one.
void add_scene_inputs(const Scene& scene, OutputRoles& roles);

// Makes the plan's missing output folders. Called once every check of the run has passed (the
// device chosen and the program built), so that a refused run leaves no empty folder behind.
// Throws OutputError.
void make_missing_folders(const OutputPlan& plan);

}  // namespace clr
