#include "app/frame_description.h"

#include <filesystem>
#include <string>
#include <nlohmann/json.hpp>

#include "scene/camera_path.h"

namespace clr {
namespace {

// JSON's number form: the shortest text that reads back as the same double, as in a scene file.
std::string number_text(double value) { return nlohmann::json(value).dump(); }

std::string vector_text(const Vec3& v) {
    return "[" + number_text(v.x) + ", " + number_text(v.y) + ", " + number_text(v.z) + "]";
}

}  // namespace

ImageText describe_frame(const Scene& scene, int frame, const std::optional<PixelRect>& crop) {
    const CameraKey camera = camera_at_frame(scene, frame);
    ImageText text = {
        {"Software", std::string("clrender ") + CLRENDER_VERSION},
        {"Scene", std::filesystem::path(scene.path).filename().string()},
        {"Size", std::to_string(scene.width) + "x" + std::to_string(scene.height)},
        {"Samples per pixel", std::to_string(scene.sampling.samples_per_pixel)},
        {"Seed", std::to_string(scene.sampling.seed)},
        {"Frame", std::to_string(frame)},
        {"Eye", vector_text(camera.eye)},
        {"Lookat", vector_text(camera.lookat)},
        {"Up", vector_text(scene.up)},
        {"Field of view", number_text(scene.fov_degrees)},
    };
    if (crop) text.insert(text.begin() + 3, {"Crop", format_pixel_rect(*crop)});
    return text;
}

}  // namespace clr
