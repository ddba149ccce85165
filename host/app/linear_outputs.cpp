#include "app/linear_outputs.h"

#include "core/errors.h"
#include "output/alpha_convention.h"
#include "output/image_writer.h"

namespace clr {
namespace {

bool writes_exr(const OutputPlan& plan) {
    return !plan.image_target.empty() && image_format_for(plan.image_path(plan.frames.front())) == ImageFormat::Exr;
}

}  // namespace

bool needs_linear_frames(const Options& options, const OutputPlan& plan) {
    return options.alpha || (writes_exr(plan) && !plan.assemble);
}

void check_linear_outputs(const Options& options, const OutputPlan& plan) {
    if (writes_exr(plan) && (plan.assemble || (options.resume && !plan.video_path.empty())))
        throw UsageError("-o " + plan.image_target + ": EXR frames cannot be read back into a video (" +
                         (plan.assemble ? "--assemble" : "--resume") +
                         "); render the video with the frames, or write PNG frames to assemble");
    if (!options.alpha) return;
    if (!plan.video_path.empty())
        throw UsageError("--alpha: the video " + plan.video_path +
                         " would have no alpha channel; write frames with -o (PNG or EXR) instead");
    if (plan.image_target.empty()) throw UsageError("--alpha needs an image output (-o x.png or -o x.exr)");
    if (image_format_for(plan.image_path(plan.frames.front())) == ImageFormat::Ppm)
        throw UsageError("--alpha: " + plan.image_target + " is a PPM, which has no alpha channel; use .png or .exr");
}

void prepare_linear_frame(Image& image, const Options& options, const OutputPlan& /*plan*/, const Scene& scene) {
    if (!options.alpha) return;
    apply_alpha_convention(image, scene.background, scene.sampling.samples_per_pixel);
}

}  // namespace clr
