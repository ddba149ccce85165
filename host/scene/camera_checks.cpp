#include "scene/camera_checks.h"

#include <sstream>

#include "scene/camera_path.h"  // the frames' cameras exactly as they will be rendered

namespace clr {
namespace {

std::string format_vec3(const Vec3& v) {
    std::ostringstream text;
    text << "[" << v.x << ", " << v.y << ", " << v.z << "]";
    return text.str();
}

// Unit vector along `v`, of any finite length. Zero stays zero.
Vec3 direction(const Vec3& v) { return v == Vec3{} ? v : normalize(v); }

}  // namespace

std::optional<std::string> camera_problem(const CameraKey& camera, const Vec3& up, const std::string& where) {
    if (camera.eye == camera.lookat)
        return "eye and lookat are the same point " + format_vec3(camera.eye) + where + ", so the camera has no view direction";
    const Vec3 view = direction(camera.lookat - camera.eye);
    const double sine = length(cross(direction(up), view));
    if (!(sine >= kParallelSine)) {  // written so that NaN fails too
        return "up " + format_vec3(up) + " is parallel to the view direction " + format_vec3(view) + where +
               ", so the camera's roll is undefined";
    }
    return std::nullopt;
}

void check_frames_between_keys(const Scene& scene, const std::vector<std::string>& key_locations,
                               const Diagnostics& diagnostics) {
    const std::size_t keys = scene.camera_path.size();
    if (keys < 2) return;
    const long long frames = animation_frame_count(scene);
    for (long long frame = 1; frame + 1 < frames; ++frame) {
        // The same integer arithmetic as camera_path.cpp: frames on a key were checked there.
        const long long scaled = frame * static_cast<long long>(keys - 1);
        if (scaled % (frames - 1) == 0) continue;
        const CameraKey camera = camera_at_frame(scene, static_cast<int>(frame));
        const std::size_t segment = static_cast<std::size_t>(scaled / (frames - 1));
        const std::string from = std::to_string(segment), to = std::to_string(segment + 1);
        const std::optional<std::string> problem =
            camera_problem(camera, scene.up, " at frame " + std::to_string(frame) + ", between camera keys " + from + " and " + to);
        if (!problem) continue;
        const std::string remedy = camera.eye == camera.lookat
                                       ? "; move key " + from + " or " + to + " so that the eye's path and the look-at point's path do not meet"
                                       : "; change 'up', or move key " + from + " or " + to + " so that the view never turns parallel to up";
        diagnostics.fail(key_locations[segment], *problem + remedy);
    }
}

}  // namespace clr
