#include "app/plan_json.h"

#include <filesystem>
#include <set>

#include <nlohmann/json.hpp>

namespace clr {
namespace {

using json = nlohmann::ordered_json;  // the keys in the order written here, for people reading the plan

json or_null(const std::string& text) { return text.empty() ? json(nullptr) : json(text); }

// How the run's work divides: an animation by frames, a still by rows; --join and --assemble
// render nothing.
json split(const Options& options, const Scene& scene, const OutputPlan& plan) {
    if (!options.join.empty() || plan.assemble) return {{"by", "none"}};
    if (plan.frame_count > 1) return {{"by", "frames"}, {"frames", plan.frames}};
    // The rectangle the run renders (the crop, else the whole frame), to cut into bands of rows.
    const PixelRect rect = options.crop ? *options.crop : PixelRect{0, scene.width, 0, scene.height};
    return {{"by", "rows"}, {"x0", rect.x0}, {"x1", rect.x1}, {"y0", rect.y0}, {"y1", rect.y1}};
}

// Whether a file of a mesh that a placeholder stands in for was read: an OBJ refused for a bad
// line and the .mtl files it names were; a missing file, a folder or a FIFO was not.
bool read_for_placeholder(const std::string& path) {
    std::error_code error;
    return std::filesystem::is_regular_file(path, error);
}

// Every file the render reads, each once: the scene, its images, its OBJ files and the .mtl
// files they name (what a node needs besides the program). A missing file that --placeholders
// stands in for is not read, so not listed.
json inputs(const Scene& scene) {
    json files = json::array();
    std::set<std::string> listed;
    const auto add = [&](const std::string& path) {
        if (!path.empty() && listed.insert(path).second) files.push_back(path);
    };
    add(scene.path);
    for (const ImageFileInfo& image : scene.image_files)
        if (image.format != "placeholder") add(image.path);
    std::set<const std::vector<std::string>*> seen;  // the placements of a file share its list
    for (const Mesh& mesh : scene.meshes) {
        if (!mesh.placeholder || read_for_placeholder(mesh.path)) add(mesh.path);
        if (mesh.material_paths && seen.insert(mesh.material_paths.get()).second)
            for (const std::string& material : *mesh.material_paths)
                if (!mesh.placeholder || read_for_placeholder(material)) add(material);
    }
    return files;
}

}  // namespace

std::string plan_json(const Options& options, const Scene& scene, const OutputPlan& plan) {
    json images = json::array();     // the image file of each frame, written or read back
    json writes = json::array();     // every file the run writes
    json reads_back = json::array();  // files of earlier runs the run reads (--assemble, --resume, --join)
    for (int frame : plan.frames) {
        const std::string path = plan.image_path(frame);
        if (path.empty()) continue;
        const bool read = plan.assemble || (options.resume && plan.frame_on_disk(frame));
        images.push_back({{"frame", frame}, {"path", path}, {"written", !read}});
        (read ? reads_back : writes).push_back(path);
    }
    for (const std::string& tile : options.join) reads_back.push_back(tile);
    if (!plan.video_name.empty()) writes.push_back(plan.video_name);
    if (!plan.stats_path.empty()) writes.push_back(plan.stats_path);
    const bool pattern_given = plan.image_is_pattern && plan.default_frame_digits == 0;
    const bool renders = options.join.empty() && !plan.assemble;
    json result = {
        {"scene", scene.path},
        {"paths", "as given; relative ones are relative to the working folder"},
        {"still", plan.frame_count == 1},
        {"frame_count", plan.frame_count},
        {"frames", plan.frames},
        {"frame_width", scene.width},
        {"frame_height", scene.height},
        {"width", options.crop ? options.crop->width() : scene.width},
        {"height", options.crop ? options.crop->height() : scene.height},
        {"frame_pattern", pattern_given ? json(plan.image_target) : json(nullptr)},
        {"images", images},
        {"video", or_null(plan.video_name)},
        {"stats", plan.stats_to_standard_output ? json("-") : or_null(plan.stats_path)},
        {"reads", inputs(scene)},
        {"writes", writes},
        {"reads_back", reads_back},
        // The device selector the render would use (-d, else $CLRENDER_DEVICE); --plan opens
        // no OpenCL platform, so whether it names a device is not known here.
        {"device", renders && !options.reference ? or_null(options.device) : json(nullptr)},
        {"split", split(options, scene, plan)},
    };
    // A file name need not be UTF-8: invalid bytes become U+FFFD, so that the plan stays JSON.
    return result.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
}

}  // namespace clr
