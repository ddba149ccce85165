// --resume's rule for the files already under an output's name (docs/command-line.md,
// Resuming): a PNG counts as finished only when its description is exactly what this run
// writes for that frame (and crop), at this run's size and alpha channel; a PNG that differs or
// cannot be read is rendered again, with a warning. PPM and EXR files carry no description:
// any regular file counts. A folder or FIFO under the name is no frame at all: it is planned
// as an output, and refused as one.
#pragma once

#include <optional>
#include <string>

#include "app/options.h"
#include "app/output_plan.h"
#include "output/image_writer.h"
#include "scene/scene.h"

namespace clr {

// What this run writes for one frame.
struct ExpectedImage {
    ImageText text;
    int width = 0, height = 0;
    bool alpha = false;
};

// Why the PNG at `path` is not this run's finished frame ("made by another render (Samples
// per pixel: 16 in the file, 64 in this run)", "cannot be read (not a PNG file)"); nullopt when
// it is. Reads only the chunks before the pixel data, and the file's end.
std::optional<std::string> why_not_finished(const std::string& path, const ExpectedImage& expected);

// Fills plan.finished_frames and plan.warnings (one per file to render again) for --resume.
void find_finished_frames(const Options& options, const Scene& scene, OutputPlan& plan);

}  // namespace clr
