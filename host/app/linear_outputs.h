// EXR images and --alpha (docs/command-line.md, HDR and alpha outputs): both need a frame's
// linear colours and coverage, which the kernels produce only in their float output mode.
#pragma once

#include "app/options.h"
#include "app/output_plan.h"
#include "core/image.h"
#include "scene/scene.h"

namespace clr {

// Whether frames must be rendered with linear colours (Image::linear): an EXR image or --alpha.
bool needs_linear_frames(const Options& options, const OutputPlan& plan);

// Throws UsageError, before anything renders, for what these outputs cannot do: --alpha
// without an image, into a PPM (no alpha channel) or with a video (H.264 yuv420p and GIF
// frames have none); EXR frames read back as a video's frames (--assemble, or --resume with
// --video): clrender does not read EXR, and the frames' linear colours would need a tone
// mapping of their own, so the video is made from the display colours when the frames render.
void check_linear_outputs(const Options& options, const OutputPlan& plan);

// Readies a rendered frame for the image output: --alpha's convention for its format.
void prepare_linear_frame(Image& image, const Options& options, const OutputPlan& plan, const Scene& scene);

}  // namespace clr
