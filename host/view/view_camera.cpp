#include "view/view_camera.h"

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/errors.h"
#include "scene/camera_path.h"
#include "scene/scene_loader.h"

namespace clr {
namespace {

nlohmann::json array_of(const Vec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); }

// The query parameter that a location in the camera-only scene comes from.
std::string parameter_at(const std::string& location) {
    if (location.rfind("/eye", 0) == 0) return "eye";
    if (location.rfind("/lookat", 0) == 0) return "lookat";
    if (location.rfind("/up", 0) == 0) return "up";
    if (location.rfind("/fov_angle", 0) == 0) return "fov";
    if (location.rfind("/clrender/spp", 0) == 0) return "spp";
    return "size";  // /width, /height, or the pixel count of both
}

// The parameter to name for a fault at `location`: its own where the query gave it, else the
// query's value that the fault also depends on. The view direction is eye to lookat, which up
// must not be parallel to, and the narrowest fov is the size's: a query that moved only the
// look-at point onto the scene's eye was told `eye`, one whose size was too large for the
// scene's fov `fov`.
std::string parameter_for(const std::string& location, const ViewQuery& query) {
    const std::string own = parameter_at(location);
    const auto given = [&query](const std::string& name) {
        if (name == "eye") return query.eye.has_value();
        if (name == "lookat") return query.lookat.has_value();
        if (name == "up") return query.up.has_value();
        if (name == "fov") return query.fov_degrees.has_value();
        if (name == "spp") return query.samples_per_pixel.has_value();
        return query.width.has_value();
    };
    if (given(own)) return own;
    const std::vector<std::string> also = own == "eye"   ? std::vector<std::string>{"lookat"}
                                          : own == "up"  ? std::vector<std::string>{"eye", "lookat"}
                                          : own == "fov" ? std::vector<std::string>{"size"}
                                                         : std::vector<std::string>{};
    for (const std::string& other : also)
        if (given(other)) return other;
    return own;
}

// A scene's message about a key it made from the query, in the query's terms.
std::string in_query_terms(std::string detail) {
    for (const auto& [scene_word, query_word] : {std::pair<std::string, std::string>{"fov_angle", "fov"}}) {
        for (std::size_t at; (at = detail.find(scene_word)) != std::string::npos;)
            detail.replace(at, scene_word.size(), query_word);
    }
    return detail;
}

}  // namespace

ViewCamera resolve_view_camera(const Scene& scene, const ViewQuery& query) {
    ViewCamera view;
    const int frames = animation_frame_count(scene);
    view.frame = query.frame.value_or(0);
    if (view.frame >= frames)
        throw ParameterError("frame", "frame " + std::to_string(view.frame) + " is not in the scene's animation: it has " +
                                          std::to_string(frames) + (frames == 1 ? " frame (0)" : " frames (0 to " +
                                          std::to_string(frames - 1) + ")"));
    view.key = camera_at_frame(scene, view.frame);
    if (query.eye) view.key.eye = *query.eye;
    if (query.lookat) view.key.lookat = *query.lookat;
    view.up = query.up.value_or(scene.up);
    view.fov_degrees = query.fov_degrees.value_or(scene.fov_degrees);
    view.width = query.width.value_or(scene.width);
    view.height = query.height.value_or(scene.height);
    view.sampling = scene.sampling;
    if (query.samples_per_pixel) view.sampling.samples_per_pixel = *query.samples_per_pixel;

    // The loader's own checks, on a scene of just this camera: positions in range, a view
    // direction, an up vector neither zero nor parallel to it, the field of view's range and
    // its narrowest for the size, the size's limits, the samples' range.
    const nlohmann::json camera_only = {
        {"eye", array_of(view.key.eye)},          {"lookat", array_of(view.key.lookat)},
        {"up", array_of(view.up)},                {"fov_angle", view.fov_degrees},
        {"width", view.width},                    {"height", view.height},
        {"clrender", {{"spp", view.sampling.samples_per_pixel}}},
    };
    try {
        parse_scene(camera_only.dump(), "view request");
    } catch (const SceneError& error) {
        throw ParameterError(parameter_for(error.location(), query), in_query_terms(error.detail()));
    }
    return view;
}

Scene scene_seen_by(const Scene& scene, const ViewCamera& view) {
    Scene seen = scene;
    seen.camera_path = {view.key};
    seen.up = view.up;
    seen.fov_degrees = view.fov_degrees;
    seen.width = view.width;
    seen.height = view.height;
    seen.sampling = view.sampling;
    return seen;
}

}  // namespace clr
