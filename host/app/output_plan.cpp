#include "app/output_plan.h"

#include <filesystem>
#include <set>

#include "app/frame_selection.h"
#include "core/errors.h"
#include "output/image_writer.h"
#include "output/output_roles.h"
#include "output/output_target.h"
#include "output/temp_files.h"
#include "output/video_encoder.h"
#include "scene/camera_path.h"

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

// Every file the scene reads: the scene and its images (placeholders keep the missing path).
void add_scene_inputs(const Scene& scene, OutputRoles& roles) {
    roles.add_input("scene file", scene.path);
    for (const Billboard& billboard : scene.billboards)
        if (billboard.image) roles.add_input("texture", billboard.image->path);
    for (const Impostor& impostor : scene.impostors)
        for (const ImpostorView& view : impostor.views)
            if (view.image) roles.add_input("impostor image", view.image->path);
}

// Image outputs, and the frames that --assemble and --resume read back instead.
void add_images(const Options& options, const OutputPlan& plan, OutputRoles& roles) {
    if (plan.image_target.empty()) return;
    if (!plan.image_is_pattern) {
        roles.add_output(options.output_path.empty() ? "image (the default output name)" : "image (-o)",
                         plan.image_target);
        return;
    }
    for (int frame : plan.frames) {
        const std::string path = plan.image_path(frame);
        const std::string name = "frame " + std::to_string(frame);
        if (plan.assemble) {
            roles.add_input(name + " (read by --assemble)", path);
        } else if (options.resume && plan.frame_on_disk(frame)) {
            roles.add_input(name + " (read back by --resume)", path);
        } else {
            roles.add_output(name + " (-o)", path);
        }
    }
}

// The files this run writes (frames that are only read back are not).
std::vector<std::string> written_files(const Options& options, const OutputPlan& plan) {
    std::vector<std::string> paths;
    if (!plan.image_target.empty() && !plan.assemble) {
        for (int frame : plan.frames) {
            const std::string path = plan.image_path(frame);
            if (!(options.resume && plan.frame_on_disk(frame))) paths.push_back(path);
        }
    }
    if (!plan.video_path.empty()) paths.push_back(plan.video_path);
    if (!plan.stats_path.empty()) paths.push_back(plan.stats_path);
    return paths;
}

// Refuses unsafe targets before anything renders, then readies each output folder once.
void check_targets(const Options& options, const Scene& scene, OutputPlan& plan) {
    const std::vector<std::string> outputs = written_files(options, plan);
    std::set<std::string> folders;
    std::vector<std::string> one_target_per_folder;
    for (const std::string& path : outputs) {
        const std::string target = resolve_output_target(path);
        if (folders.insert(std::filesystem::path(target).parent_path().string()).second)
            one_target_per_folder.push_back(target);
    }
    if (!plan.video_path.empty()) plan.video_path = resolve_output_target(plan.video_path);  // the encoder renames onto it

    OutputRoles roles;
    add_scene_inputs(scene, roles);
    add_images(options, plan, roles);
    if (!plan.video_path.empty()) roles.add_output("video (--video)", plan.video_path);
    if (!plan.stats_path.empty()) roles.add_output("--stats report", plan.stats_path);

    for (const std::string& target : one_target_per_folder) prepare_output_folder(target);
}

}  // namespace

std::string OutputPlan::image_path(int frame) const {
    if (image_target.empty()) return "";
    return image_is_pattern ? frame_path(image_target, frame) : image_target;
}

bool OutputPlan::frame_on_disk(int frame) const {
    std::error_code ignored;
    return image_is_pattern && std::filesystem::is_regular_file(image_path(frame), ignored);
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
    plan.stats_path = options.stats_path;
    if (options.resume && !plan.image_is_pattern)
        throw UsageError("--resume needs -o with a frame pattern: it skips the frames whose files exist");
    if (plan.assemble && (!plan.image_is_pattern || plan.video_path.empty() || options.video_path.empty()))
        throw UsageError("--assemble needs -o with the frame pattern to read and --video with the video to write");
    check_targets(options, scene, plan);
    return plan;
}

}  // namespace clr
