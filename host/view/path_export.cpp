#include "view/path_export.h"

#include <malloc.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <system_error>

#include "core/errors.h"
#include "core/interruption.h"
#include "output/output_roles.h"
#include "scene/file_names.h"
#include "scene/json_reader.h"
#include "scene/scene_loader.h"
#include "scene/scene_overrides.h"
#include "view/unused_name_file.h"
#include "view/view_parameters.h"

namespace clr {
namespace {

namespace fs = std::filesystem;

nlohmann::json array_of(const Vec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); }

// Every image name (billboards' and impostors' "filename", and the names the loader takes for
// it: "image", "file", "texture") is relative to the scene's folder. The exported scene is
// shown in the page, offered as a download and saved wherever the user likes, so relative
// names become absolute ones: the scene then finds its images and meshes from any folder.
void make_image_paths_absolute(nlohmann::json& value, const fs::path& scene_folder) {
    if (value.is_array()) {
        for (nlohmann::json& element : value) make_image_paths_absolute(element, scene_folder);
        return;
    }
    if (!value.is_object()) return;
    for (auto& [key, member] : value.items()) {
        const bool names_image = key == "filename" || key == "image" || key == "file" || key == "texture";
        if (names_image && member.is_string()) {
            const fs::path image = member.get<std::string>();
            if (image.empty() || image.is_absolute()) continue;
            member = path_in_folder(scene_folder, image);  // the file the scene's load read
        } else {
            make_image_paths_absolute(member, scene_folder);
        }
    }
}

// At its end, what the export's trees took goes back to the system: glibc keeps freed memory
// in the arena of the thread that freed it, so each server thread that once exported would keep
// a scene's trees (8 exports at once, one at a time, left 1.6 GB).
struct MemoryGivenBack {
    MemoryGivenBack() = default;
    MemoryGivenBack(const MemoryGivenBack&) = delete;
    MemoryGivenBack& operator=(const MemoryGivenBack&) = delete;
    ~MemoryGivenBack() { ::malloc_trim(0); }
};

// The scene's folder as the loader found it, by its physical absolute path. Taken once, at
// start: the folder the viewer was started in may be gone by the time of an export (getcwd
// fails then), and a name through it ("START/../scenes") would break with it.
fs::path absolute_scene_folder(const std::string& scene_path) {
    return fs::canonical(fs::absolute(fs::path(scene_path)).parent_path());
}

}  // namespace

PathExporter::PathExporter(const Scene& scene, std::string scene_text, const Options& options, std::string output_dir)
    : scene_(scene),
      scene_text_(std::move(scene_text)),
      options_(options),
      output_dir_(std::move(output_dir)),
      scene_folder_(absolute_scene_folder(scene.path)) {}

std::string PathExporter::scene_text_for(const CameraKeysRequest& request) const {
    std::vector<std::string> warnings;
    Diagnostics diagnostics{scene_.path, &warnings};
    nlohmann::json document = parse_json_text(scene_text_, diagnostics);  // parsed once before: cannot fail
    apply_scene_overrides(document, options_.overrides);
    for (const char* key : {"eye", "lookat", "eyeLocations", "lookatLocations"}) document.erase(key);
    nlohmann::json eyes = nlohmann::json::array(), lookats = nlohmann::json::array();
    for (const CameraKey& key : request.keys) {
        eyes.push_back(array_of(key.eye));
        lookats.push_back(array_of(key.lookat));
    }
    document["eyeLocations"] = eyes;
    document["lookatLocations"] = lookats;
    if (request.up) document["up"] = array_of(*request.up);
    if (request.fov_degrees) document["fov_angle"] = *request.fov_degrees;
    // What the command line set outside the file is what the page showed.
    if (options_.width) document["width"] = *options_.width;
    if (options_.height) document["height"] = *options_.height;
    if (options_.samples_per_pixel) document["clrender"]["spp"] = *options_.samples_per_pixel;
    if (options_.seed) document["clrender"]["seed"] = *options_.seed;
    make_image_paths_absolute(document, scene_folder_);
    return document.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

void PathExporter::check_output(const std::string& role, const std::string& path) const {
    OutputRoles roles;
    roles.add_input("scene file", scene_.path);
    for (const ImageFileInfo& image : scene_.image_files)
        if (image.format != "placeholder") roles.add_input("image '" + image.path + "'", image.path);
    std::set<const std::vector<std::string>*> listed;  // the placements of a file share its list
    for (const Mesh& mesh : scene_.meshes) {
        if (!mesh.path.empty()) roles.add_input("mesh '" + mesh.path + "'", mesh.path);
        if (mesh.material_paths && listed.insert(mesh.material_paths.get()).second)
            for (const std::string& material : *mesh.material_paths)
                roles.add_input("mesh material '" + material + "'", material);
    }
    for (const std::string& texture : scene_.mesh_texture_paths)
        roles.add_input("mesh texture '" + texture + "'", texture);
    roles.add_output(role, path);
}

ExportedScene PathExporter::export_keys(const CameraKeysRequest& request, const std::vector<std::string>& also_unused,
                                       const std::function<void(const std::string& text)>& before_write) const {
    const std::lock_guard<std::mutex> one_at_a_time(one_at_a_time_);
    // Exports sent together wait here for their turn: at a stop, those still waiting write
    // nothing (503), rather than run one after another after the signal, writing files no client
    // hears of, until the watchdog ends the viewer.
    throw_if_interrupted();
    const MemoryGivenBack given_back;
    const std::string base = request.name.empty() ? default_name() : request.name;
    // Checked under the requested name: the text names neither the file nor its folder.
    const std::string checked_path = (fs::path(output_dir_) / (base + ".json")).string();
    ExportedScene exported;
    exported.text = scene_text_for(request);
    // The loader's checks, as `clrender` will run them on the file: every key in range, a view
    // direction and a roll at every key and between keys, the animation's length. Images are
    // checked from their headers only. The meshes, read at start, are not read again: the keys
    // do not change them, and each export (several may come at once) would hold its own copy.
    LoadOptions check;
    check.decode_images = false;
    check.read_meshes = false;
    check.placeholder_images = options_.placeholders;
    try {
        parse_scene(exported.text, checked_path, check);
    } catch (const SceneError& error) {
        throw ParameterError("keys", error.location().empty() ? error.detail() : error.location() + ": " + error.detail());
    }
    throw_if_interrupted();  // the check takes seconds on a large scene: a stop meanwhile writes nothing
    if (before_write) before_write(exported.text);
    // A name that an input of the scene holds though no file is there (a texture that a .mtl
    // names, which clrender never reads) is passed over, for the scene and for the outputs that
    // follow under its name: the export was refused (409, "choose another output name", which
    // the page cannot), and a video's scene was written before its MP4's name was refused.
    const auto usable = [this, &also_unused](const std::string& path) {
        const std::string stem = path.substr(0, path.size() - std::string(".json").size());
        try {
            check_output("exported scene", path);
            for (const std::string& suffix : also_unused) check_output("output", stem + suffix);
        } catch (const OutputError& clash) {
            throw UnusableName(clash.what());
        }
    };
    const UnusedNameFile written =
        write_under_unused_name(output_dir_, base, ".json", also_unused, exported.text, usable);
    exported.name = written.name;
    exported.path = written.path;
    return exported;
}

}  // namespace clr
