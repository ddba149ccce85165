#include "app/output_plan.h"

#include <algorithm>
#include <filesystem>
#include <set>

#include "app/finished_frames.h"
#include "app/frame_selection.h"
#include "app/tile_join.h"
#include "core/errors.h"
#include "core/printable_text.h"
#include "output/image_writer.h"
#include "output/output_folders.h"
#include "output/output_roles.h"
#include "output/output_target.h"
#include "output/temp_files.h"
#include "output/encoder_timeout.h"
#include "output/video_encoder.h"
#include "output/video_probe.h"
#include "scene/camera_path.h"

namespace clr {
namespace {

// Digits of the default frame names: 4, more when the animation's last frame needs them, so
// that the names sort in frame order.
int default_frame_digits(int frame_count) {
    return std::max(4, static_cast<int>(std::to_string(frame_count - 1).size()));
}

// --frames selects part of an animation: without -o and --video its frames are written as
// images beside where a still's image would go, and no video is made (a video of a selection
// would silently replace the whole animation's video) (docs/command-line.md, Outputs).
bool writes_default_frames(const Options& options, bool animated) {
    return animated && !options.frames.empty() && options.output_path.empty() && options.video_path.empty();
}

void plan_images(const Options& options, const Scene& scene, OutputPlan& plan) {
    plan.image_target = options.output_path;
    plan.image_is_pattern = !plan.image_target.empty() && is_frame_pattern(plan.image_target);
    bool animated = plan.frame_count > 1;
    if (plan.image_target.empty() && !animated) plan.image_target = scene.name + ".png";
    if (writes_default_frames(options, animated)) {
        plan.default_frame_digits = default_frame_digits(plan.frame_count);
        plan.default_frame_stem = scene.name + "_";
        plan.image_target = plan.default_frame_stem + std::string(plan.default_frame_digits, 'N') + ".png";
        plan.image_is_pattern = true;
    }
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
    if (plan.video_path.empty() && options.output_path.empty() && options.frames.empty())
        plan.video_path = scene.name + ".mp4";
    if (plan.video_path.empty()) return;
    plan.video_name = plan.video_path;
    // The scene's fps must fit the format, or ffmpeg fails (or silently retimes a GIF) after the render.
    if (const std::string problem = video_fps_problem(scene.animation.fps, video_format_for(plan.video_path));
        !problem.empty())
        throw SceneError(printable(scene.path), "/clrender/fps", "fps: --video " + printable(plan.video_path) + ": " + problem);
    plan.encoder = find_encoder();  // before any rendering: a missing encoder must not waste a render
    // The encoder's settings and checker too (the encoder asks for them again when it starts),
    // so that --check finds them without a device.
    encoder_stall_timeout();
    find_video_prober(plan.encoder);
}

// "-" as an output name: --stats - writes the report to standard output, where nothing else
// of clrender's goes; images and videos are files only, so -o - and --video - are refused
// (docs/command-line.md, Outputs). A file named "-" is written as ./-.
constexpr const char* kStandardOutput = "-";

void plan_standard_output(const Options& options, OutputPlan& plan) {
    for (const auto& [option, value] : {std::pair{"-o", options.output_path}, std::pair{"--video", options.video_path}}) {
        if (value == kStandardOutput)
            throw UsageError(std::string(option) + " -: clrender writes images and videos only to files; give a file "
                             "name (./- for a file named '-'); --stats - writes the report to standard output");
    }
    plan.stats_to_standard_output = options.stats_path == kStandardOutput;
    if (!plan.stats_to_standard_output) plan.stats_path = options.stats_path;
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
            roles.add_output(name + (options.output_path.empty() ? " (the default output name)" : " (-o)"), path);
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
    for (const std::string& tile : options.join) roles.add_input("tile (--join)", tile);
    add_images(options, plan, roles);
    if (!plan.video_path.empty()) roles.add_output("video (--video)", plan.video_path);
    if (!plan.stats_path.empty()) roles.add_output("--stats report", plan.stats_path);

    for (const std::string& target : one_target_per_folder) {
        std::vector<std::string> missing = missing_folders_of(target);
        if (missing.empty()) {
            if (options.check || options.plan)
                probe_output_folder(target);
            else
                prepare_output_folder(target);
        } else {
            plan.missing_folders.push_back({target, std::move(missing)});
        }
    }
}

}  // namespace

void add_scene_inputs(const Scene& scene, OutputRoles& roles) {
    roles.add_input("scene file", scene.path);
    for (const Billboard& billboard : scene.billboards)
        if (billboard.image) roles.add_input("texture", billboard.image->path);
    for (const Impostor& impostor : scene.impostors)
        for (const ImpostorView& view : impostor.views)
            if (view.image) roles.add_input("impostor image", view.image->path);
    std::set<const std::vector<std::string>*> listed;  // the placements of a file share its list
    for (const Mesh& mesh : scene.meshes) {
        if (!mesh.path.empty()) roles.add_input("mesh", mesh.path);
        if (mesh.material_paths && listed.insert(mesh.material_paths.get()).second)
            for (const std::string& material : *mesh.material_paths) roles.add_input("mesh material", material);
    }
    for (const std::string& texture : scene.mesh_texture_paths) roles.add_input("mesh texture", texture);
}

std::string OutputPlan::image_path(int frame) const {
    if (image_target.empty()) return "";
    if (default_frame_digits > 0) {
        std::string number = std::to_string(frame);
        if (static_cast<int>(number.size()) < default_frame_digits) number.insert(0, default_frame_digits - number.size(), '0');
        return default_frame_stem + number + ".png";
    }
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
    plan_standard_output(options, plan);
    check_join_request(options, plan);  // before the images' and video's checks, which ask for other things
    plan_images(options, scene, plan);
    plan_video(options, scene, plan);
    plan.assemble = options.assemble;
    if (options.resume && !plan.image_is_pattern && !(plan.frames.size() == 1 && !plan.image_target.empty()))
        throw UsageError("--resume needs -o with a frame pattern (or --frames without -o and --video), or a run "
                         "that writes one image: it skips the frames whose files are finished");
    find_finished_frames(options, scene, plan);
    if (plan.assemble && (!plan.image_is_pattern || plan.video_path.empty() || options.video_path.empty()))
        throw UsageError("--assemble needs -o with the frame pattern to read and --video with the video to write");
    check_targets(options, scene, plan);
    return plan;
}

void make_missing_folders(const OutputPlan& plan) {
    for (const OutputPlan::MissingFolders& missing : plan.missing_folders)
        make_output_folders(missing.folders, missing.output);
}

}  // namespace clr
