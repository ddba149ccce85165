#include "app/output_plan.h"

#include "app/frame_selection.h"
#include "core/errors.h"
#include "output/image_writer.h"
#include "output/video_encoder.h"
#include "render/camera_path.h"

namespace clr {
namespace {

void plan_images(const Options& options, const Scene& scene, OutputPlan& plan) {
    plan.image_target = options.output_path;
    plan.image_is_pattern = !plan.image_target.empty() && is_frame_pattern(plan.image_target);
    bool animated = plan.frame_count > 1;
    if (plan.image_target.empty() && !animated) plan.image_target = scene.name + ".png";
    if (animated && !plan.image_target.empty() && !plan.image_is_pattern && plan.frames.size() > 1)
        throw UsageError("-o " + plan.image_target + ": the animation has " + std::to_string(plan.frames.size()) +
                         " frames to write; give a frame pattern such as frames/" + scene.name + "_%04d.png");
    if (!plan.image_target.empty()) image_format_for(plan.image_path(plan.frames.front()));
}

void plan_video(const Options& options, const Scene& scene, OutputPlan& plan) {
    plan.video_path = options.video_path;
    if (plan.frame_count == 1) {
        if (!plan.video_path.empty())
            throw UsageError("--video " + plan.video_path + ": " + scene.path + " is a still (one camera key); "
                             "a video needs eyeLocations with two or more keys");
        return;
    }
    if (plan.video_path.empty() && options.output_path.empty()) plan.video_path = scene.name + ".mp4";
    if (plan.video_path.empty()) return;
    video_format_for(plan.video_path);
    plan.encoder = find_encoder();  // before any rendering: a missing encoder must not waste a render
}

}  // namespace

std::string OutputPlan::image_path(int frame) const {
    if (image_target.empty()) return "";
    return image_is_pattern ? frame_path(image_target, frame) : image_target;
}

OutputPlan plan_outputs(const Options& options, const Scene& scene) {
    OutputPlan plan;
    plan.frame_count = animation_frame_count(scene);
    if (options.frames.empty()) {
        for (int frame = 0; frame < plan.frame_count; ++frame) plan.frames.push_back(frame);
    } else {
        plan.frames = parse_frame_list(options.frames, plan.frame_count);
    }
    plan_images(options, scene, plan);
    plan_video(options, scene, plan);
    plan.assemble = options.assemble;
    if (options.resume && !plan.image_is_pattern)
        throw UsageError("--resume needs -o with a frame pattern: it skips the frames whose files exist");
    if (plan.assemble && (!plan.image_is_pattern || plan.video_path.empty() || options.video_path.empty()))
        throw UsageError("--assemble needs -o with the frame pattern to read and --video with the video to write");
    return plan;
}

}  // namespace clr
