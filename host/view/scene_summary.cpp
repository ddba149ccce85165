#include "view/scene_summary.h"

#include <filesystem>
#include <nlohmann/json.hpp>

#include "core/printable_text.h"
#include "scene/camera_path.h"

namespace clr {
namespace {

nlohmann::json array_of(const Vec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); }

nlohmann::json camera_json(const Scene& scene, const CameraKey& key) {
    return {{"eye", array_of(key.eye)}, {"lookat", array_of(key.lookat)}, {"up", array_of(scene.up)},
            {"fov", scene.fov_degrees}};
}

}  // namespace

std::string shown_name(const std::string& name) { return printable(name); }

std::string scene_summary_json(const Scene& scene) {
    // A path may have a million keys (a scene file of 21 MB): as one tree the summary took about
    // 1.6 KB a key (1.6 GB for that scene, which glibc then kept). Each key is a small tree of
    // its own, written at once; the members come in the order nlohmann writes an object's (by
    // name), so the text is the one the whole tree gave.
    const auto text_of = [](const nlohmann::json& value) {
        return value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    };
    std::string path = "[";
    for (std::size_t i = 0; i < scene.camera_path.size(); ++i) {
        if (i > 0) path += ',';
        path += text_of(camera_json(scene, scene.camera_path[i]));
    }
    path += ']';
    return "{\"camera\":" + text_of(camera_json(scene, scene.camera_path.front())) +
           ",\"fps\":" + text_of(scene.animation.fps) + ",\"frames\":" + text_of(animation_frame_count(scene)) +
           ",\"name\":" + text_of(shown_name(std::filesystem::path(scene.path).filename().string())) +
           ",\"path\":" + path + ",\"size\":" + text_of({scene.width, scene.height}) +
           ",\"spp\":" + text_of(scene.sampling.samples_per_pixel) + "}";
}

std::string frame_camera_json(const Scene& scene, int frame) {
    nlohmann::json camera = camera_json(scene, camera_at_frame(scene, frame));
    camera["frame"] = frame;
    // Doubles are written in their shortest exact form: the page reads back the very camera.
    return camera.dump();
}

}  // namespace clr
