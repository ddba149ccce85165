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
    nlohmann::json path = nlohmann::json::array();
    for (const CameraKey& key : scene.camera_path) path.push_back(camera_json(scene, key));
    const nlohmann::json summary = {
        {"camera", camera_json(scene, scene.camera_path.front())},
        {"size", {scene.width, scene.height}},
        {"spp", scene.sampling.samples_per_pixel},
        {"frames", animation_frame_count(scene)},
        {"fps", scene.animation.fps},
        {"path", path},
        {"name", shown_name(std::filesystem::path(scene.path).filename().string())},
    };
    return summary.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string frame_camera_json(const Scene& scene, int frame) {
    nlohmann::json camera = camera_json(scene, camera_at_frame(scene, frame));
    camera["frame"] = frame;
    // Doubles are written in their shortest exact form: the page reads back the very camera.
    return camera.dump();
}

}  // namespace clr
