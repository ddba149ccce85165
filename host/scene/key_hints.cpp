#include "scene/key_hints.h"

#include <string>
#include <vector>

namespace clr {
namespace {

// Hints `mistakes` towards `right_key`: "did you mean 'right_key'?".
void did_you_mean(ObjectReader& object, const std::vector<std::string>& mistakes, const std::string& right_key) {
    object.hint(mistakes, right_key, "did you mean '" + right_key + "'?");
}

// Keys of any object that shows a colour or picture.
void hint_surface_keys(ObjectReader& object) {
    did_you_mean(object, {"color", "colour", "rgb", "diffuse"}, "ambient");
    did_you_mean(object, {"mirror", "is_mirror", "reflective"}, "IsMirror");
}

}  // namespace

void hint_scene_keys(ObjectReader& scene) {
    did_you_mean(scene, {"fov", "fovy", "field_of_view", "fieldOfView", "angle"}, "fov_angle");
    did_you_mean(scene, {"background", "backgroundColor", "background_color", "bgcolor", "bg"}, "DefaultColor");
    did_you_mean(scene, {"sun", "light", "LightLocation", "LightPosition", "sun_position"}, "SunLocation");
    did_you_mean(scene, {"camera", "position", "eyeLocation"}, "eye");
    did_you_mean(scene, {"target", "center", "look_at"}, "lookat");
    scene.hint({"resolution", "size"}, "width", "give 'width' and 'height' (or --size WxH on the command line)");
    // clrender's own settings live under "clrender", where the course's tools never see them.
    for (const char* key : {"spp", "fps", "seed", "frames", "duration", "frames_per_segment", "interpolation",
                            "impostors", "view_sets"}) {
        const std::string name = key;
        scene.hint({name}, "clrender/" + name,
                   "'" + name + "' belongs under \"clrender\": \"clrender\": {\"" + name + "\": ...}");
    }
}

void hint_extension_keys(ObjectReader& extensions) {
    did_you_mean(extensions, {"samples", "samples_per_pixel", "antialiasing"}, "spp");
    did_you_mean(extensions, {"frame_rate", "framerate", "frames_per_second"}, "fps");
    did_you_mean(extensions, {"frame_count", "total_frames"}, "frames");
    did_you_mean(extensions, {"length", "seconds", "time"}, "duration");
}

void hint_sphere_keys(ObjectReader& sphere) {
    hint_surface_keys(sphere);
    did_you_mean(sphere, {"position", "pos", "origin"}, "center");
    did_you_mean(sphere, {"r", "size", "radii"}, "radius");
}

void hint_billboard_keys(ObjectReader& billboard) {
    hint_surface_keys(billboard);
    did_you_mean(billboard, {"image", "file", "texture", "img", "picture", "src", "path"}, "filename");
}

void hint_mesh_keys(ObjectReader& mesh) {
    hint_surface_keys(mesh);
    did_you_mean(mesh, {"file", "path", "model", "mesh", "src", "obj"}, "filename");
    did_you_mean(mesh, {"pos", "origin", "offset", "translation", "translate", "center"}, "position");
    did_you_mean(mesh, {"size", "scaling", "scale_factor"}, "scale");
}

void hint_impostor_keys(ObjectReader& impostor) {
    did_you_mean(impostor, {"color", "colour", "rgb"}, "ambient");
    did_you_mean(impostor, {"image", "file", "texture", "img", "picture", "src", "path"}, "filename");
    did_you_mean(impostor, {"position", "pos", "origin"}, "center");
}

}  // namespace clr
