#include "app/compare_command.h"

#include <cstdio>
#include <iostream>

#include "app/compare_report.h"
#include "app/compared_image.h"
#include "app/difference_heat_map.h"
#include "app/frame_selection.h"
#include "app/image_difference.h"
#include "app/output_plan.h"
#include "app/run.h"
#include "core/errors.h"
#include "core/interruption.h"
#include "core/printable_text.h"
#include "output/image_writer.h"
#include "output/output_folders.h"
#include "output/output_roles.h"
#include "output/output_target.h"
#include "output/temp_files.h"
#include "scene/camera_path.h"

namespace clr {
namespace {

// The one frame --frames names (default 0); a list or range is a usage error.
int compared_frame(const std::string& frames, const Scene& scene) {
    if (frames.empty()) return 0;
    const std::vector<int> selected = parse_frame_list(frames, animation_frame_count(scene));
    if (selected.size() != 1)
        throw UsageError("--frames " + frames + ": compare renders one frame; give one frame number, e.g. --frames " +
                         std::to_string(selected.front()));
    return selected.front();
}

// The heat map is a picture, not linear colours; it is an output like -o of a run: never the
// scene, one of its images or IMAGE, never a folder or FIFO. Returns the folders to make.
std::vector<std::string> check_heat_map_target(const CompareRequest& request, const Scene& scene) {
    const std::string& path = request.heat_map_path;
    if (path == "-") throw UsageError("-o -: the heat map is written only to a file; give a file name (./- for '-')");
    if (image_format_for(path) == ImageFormat::Exr)
        throw UsageError("-o " + path + ": the heat map is a picture of the differences, not linear colours; "
                         "write it as .png or .ppm");
    const std::string target = resolve_output_target(path);
    OutputRoles roles;
    add_scene_inputs(scene, roles);
    roles.add_input("image compared with (IMAGE)", request.image_path);
    roles.add_output("heat map (-o)", path);
    std::vector<std::string> missing = missing_folders_of(target);
    if (missing.empty()) prepare_output_folder(target);
    return missing;
}

void warn_about_alpha(const Image& image) {
    if (image.has_transparency())
        std::cerr << "clrender: warning: " << printable(image.path)
                  << ": the image has transparent pixels; compare looks at R, G and B only (a render is opaque)\n";
}

// The report on standard output: a closed pipe or a full disk is an output error.
void print_report(const std::string& report) {
    if (std::fwrite(report.data(), 1, report.size(), stdout) != report.size() || std::fflush(stdout) != 0)
        throw OutputError("standard output: cannot write the comparison (disk full or pipe closed?)");
}

}  // namespace

int run_compare(const CompareRequest& request) {
    install_interruption_handlers();
    const Scene scene = load_scene_for_run(request.render);
    const int frame = compared_frame(request.render.frames, scene);
    std::vector<std::string> missing_folders;
    if (!request.heat_map_path.empty()) missing_folders = check_heat_map_target(request, scene);
    // IMAGE is read and checked before the render, so that a wrong file costs no rendering.
    const Image image = read_compared_image(request.image_path, scene.width, scene.height);
    warn_about_alpha(image);
    throw_if_interrupted();
    const Image rendered = render_one_frame(request.render, scene, frame);
    throw_if_interrupted();
    const ImageDifference difference = difference_of(rendered, image, request.tolerance);
    if (!request.heat_map_path.empty()) {
        make_output_folders(missing_folders, request.heat_map_path);
        write_image(request.heat_map_path, difference_heat_map(rendered, image, request.tolerance));
    }
    const CompareFacts facts{scene.path, frame, request.image_path, request.heat_map_path};
    print_report(request.json ? compare_report_json(facts, difference) : compare_report_text(facts, difference));
    return difference.differing > 0 ? kExitImagesDiffer : kExitOk;
}

}  // namespace clr
