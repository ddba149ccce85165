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

ImageText describe_frame(const Scene& scene, int frame, const Options& options) {
    const CameraKey camera = camera_at_frame(scene, frame);
    ImageText text = {{"Software", std::string("clrender ") + CLRENDER_VERSION},
                      {"Scene", std::filesystem::path(scene.path).filename().string()}};
    if (!scene.digest.empty()) text.push_back({"Scene digest", scene.digest});
    text.push_back({"Size", std::to_string(scene.width) + "x" + std::to_string(scene.height)});
    if (options.crop) text.push_back({"Crop", format_pixel_rect(*options.crop)});
    text.push_back({"Samples per pixel", std::to_string(scene.sampling.samples_per_pixel)});
    text.push_back({"Seed", std::to_string(scene.sampling.seed)});
    if (options.reference)
        text.push_back({"Renderer", "host reference"});
    else if (options.double_precision)
        text.push_back({"Precision", "double"});
    text.push_back({"Frame", std::to_string(frame)});
    text.push_back({"Eye", vector_text(camera.eye)});
    text.push_back({"Lookat", vector_text(camera.lookat)});
    text.push_back({"Up", vector_text(scene.up)});
    text.push_back({"Field of view", number_text(scene.fov_degrees)});
    return text;
}

}  // namespace clr
