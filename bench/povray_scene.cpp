#include "bench/povray_scene.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>
#include <stdexcept>

#include "core/errors.h"
#include "render/frame_camera.h"
#include "render/impostor_placement.h"
#include "scene/camera_path.h"
#include "scene/image_loader.h"

namespace clr::bench {
namespace {

// POV-Ray's limit on max_trace_level.
constexpr int kPovrayMaxTraceLevel = 256;

// Enough digits that a double reads back as itself.
std::string number(double value) {
    if (value == 0) value = 0;  // -0 reads oddly in a scene file
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", value);
    return text;
}

std::string vector(const Vec3& v) { return "<" + number(v.x) + ", " + number(v.y) + ", " + number(v.z) + ">"; }

std::string rgb(const Color& c) { return "rgb " + vector(c); }

// A file name as a POV-Ray string literal: backslash and quote are its escapes; a control
// character has no place in one.
std::string povray_string(const Scene& scene, const std::string& path) {
    std::string quoted = "\"";
    for (char c : path) {
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
            throw SceneError(scene.path, "", "image '" + path + "' has a control character in its name, which POV-Ray cannot read");
        if (c == '\\' || c == '"') quoted += '\\';
        quoted += c;
    }
    return quoted + "\"";
}

// POV-Ray's keyword for an image file's format, which clrender tells from the file's content.
std::string povray_image_type(const Scene& scene, const std::string& path) {
    std::string format;
    for (const ImageFileInfo& file : scene.image_files)
        if (file.path == path) format = file.format;
    if (format.empty()) {
        std::optional<ImageHeader> header = read_image_header(read_image_file(path));
        if (header) format = header->format;
    }
    if (format == "PNG") return "png";
    if (format == "JPEG") return "jpeg";
    if (format == "PPM") return "ppm";
    throw SceneError(scene.path, "",
                     "image '" + path + "' (" + (format.empty() ? "unknown format" : format) +
                         ") cannot be given to POV-Ray: only image files can, not --placeholders' stand-ins");
}

// Unlit: the colour shows as it is (docs/scene-format.md, Conventions: Lighting and shadows,
// Flat), whatever the light. POV-Ray's emission adds the pigment's colour, unscaled.
const char* const kUnlitFinish = "finish { emission 1 }";
// Lit by the sun: pigment * (n . l) * shadow, no ambient term, no highlight, no fall-off.
const char* const kSunlitFinish = "finish { diffuse 1 }";
// An ideal mirror: all reflection, no colour of its own (Conventions: Mirrors).
const char* const kMirrorTexture = "texture { pigment { rgb 0 } finish { reflection { 1 } } }";

std::string sphere_text(const Scene& scene, const Sphere& sphere) {
    std::string texture = sphere.is_mirror ? kMirrorTexture
                                           : "texture { pigment { " + rgb(sphere.ambient) + " } " +
                                                 (scene.lit() ? kSunlitFinish : kUnlitFinish) + " }";
    return "sphere { " + vector(sphere.center) + ", " + number(sphere.radius) + "\n    " + texture + "\n}\n";
}

// The pigment of a billboard that is not a mirror: its image, nearest texel (no interpolate), not repeated
// (`once`), read as display values (`gamma 1.0`, as assumed_gamma is 1: no conversion).
// An image's alpha becomes POV-Ray's transmit, so transparent texels let rays through.
std::string billboard_pigment(const Scene& scene, const Billboard& billboard) {
    if (!billboard.image) return "pigment { " + rgb(billboard.ambient) + " }";
    const std::string path = billboard.image->path;
    const std::string absolute = std::filesystem::absolute(path).lexically_normal().string();
    return "pigment { image_map { " + povray_image_type(scene, path) + " " + povray_string(scene, absolute) +
           " gamma 1.0 once } }";
}

// A billboard is the unit square of POV-Ray's x-y plane, where image_map puts its image
// (lower-left texel at the origin, top row along y = 1), carried onto the parallelogram by
// one matrix: x -> UL->UR, y -> LL->UL, origin -> LL. The image's top-left texel then lands on
// UL, its top row along UL->UR and its left column along UL->LL (Conventions: Billboards).
std::string billboard_text(const Scene& scene, const Billboard& billboard) {
    const Vec3 across = billboard.upper_right - billboard.upper_left;
    const Vec3 upwards = billboard.upper_left - billboard.lower_left;
    const Vec3 normal = cross(across, upwards);
    const Vec3 unit_normal = normal / length(normal);
    const std::string texture = billboard.is_mirror ? kMirrorTexture
                                                    : "texture { " + billboard_pigment(scene, billboard) + " " +
                                                          kUnlitFinish + " }";
    auto row = [](const Vec3& v) { return number(v.x) + ", " + number(v.y) + ", " + number(v.z); };
    return "polygon { 5, <0, 0>, <1, 0>, <1, 1>, <0, 1>, <0, 0>\n    " + texture + "\n    matrix <" + row(across) +
           ",\n            " + row(upwards) + ",\n            " + row(unit_normal) + ",\n            " +
           row(billboard.lower_left) + ">\n}\n";
}

// A mesh as POV-Ray's mesh2: three vertices of its own per triangle (the scene's placed
// corners), and where any triangle has corner normals, a normal per corner (the geometric
// normal at each corner of a triangle without them), which POV-Ray blends by the hit's
// barycentric coordinates as clrender does. POV-Ray's triangles have no back either, and it
// turns a smooth triangle's normal to face the ray, as clrender turns a mesh's.
std::string mesh_text(const Scene& scene, const Mesh& mesh) {
    const std::size_t first = mesh.first_triangle, count = mesh.triangle_count;
    bool smooth = false;
    for (std::size_t i = first; i < first + count; ++i) smooth |= scene.triangles[i].normals >= 0;
    std::ostringstream text;
    text << "mesh2 {\n    vertex_vectors { " << 3 * count;
    for (std::size_t i = first; i < first + count; ++i)
        for (const Vec3& corner : scene.triangles[i].corners) text << ",\n        " << vector(corner);
    text << " }\n";
    if (smooth) {
        text << "    normal_vectors { " << 3 * count;
        for (std::size_t i = first; i < first + count; ++i) {
            const Triangle& triangle = scene.triangles[i];
            const auto& c = triangle.corners;
            const Vec3 geometric = cross(c[1] - c[0], c[2] - c[0]);
            for (int k = 0; k < 3; ++k)
                text << ",\n        "
                     << vector(triangle.normals >= 0 ? scene.corner_normals[triangle.normals][k] : geometric);
        }
        text << " }\n";
    }
    text << "    face_indices { " << count;
    for (std::size_t t = 0; t < count; ++t) text << ", <" << 3 * t << ", " << 3 * t + 1 << ", " << 3 * t + 2 << ">";
    text << " }\n";
    // Without normal_indices, POV-Ray takes face_indices for the normals too.
    const std::string texture = mesh.is_mirror ? kMirrorTexture
                                               : "texture { pigment { " + rgb(mesh.ambient) + " } " +
                                                     (scene.lit() ? kSunlitFinish : kUnlitFinish) + " }";
    text << "    " << texture << "\n}\n";
    return text.str();
}

// `v` less its part along the unit vector `along`.
Vec3 without_part_along(const Vec3& v, const Vec3& along) { return v - along * (dot(v, along) / dot(along, along)); }

// The frame's camera as clrender computes it (render/frame_camera.h): POV-Ray's ray for the
// screen point (x, y) in [-0.5, 0.5]^2 is direction + x right + y up, so right and up are the
// image plane's full width and height. Given as vectors rather than look_at and angle, they
// need no conversion between handedness or angle conventions. clrender's vectors are rounded
// to float, so they are perpendicular only to about 1e-8, which POV-Ray warns about; they are
// made perpendicular again in double, a change far below the rays' float resolution.
std::string camera_text(const FrameCamera& camera) {
    const Vec3 right = without_part_along(camera.right, camera.forward);
    const Vec3 up = without_part_along(without_part_along(camera.up, camera.forward), right);
    return "camera { perspective\n    location " + vector(camera.eye_in_scene()) + "\n    direction " +
           vector(camera.forward) + "\n    right " + vector(right * 2) + "\n    up " + vector(up * 2) + "\n}\n";
}

std::string settings_text(const Scene& scene) {
    return "global_settings { assumed_gamma 1.0 max_trace_level " + std::to_string(povray_trace_levels(scene)) +
           " }\n"
           // No light but the sun's: no ambient term anywhere, no diffuse unless asked.
           "#default { finish { ambient 0 diffuse 0 emission 0 specular 0 phong 0 } }\n"
           "background { " +
           rgb(scene.background) + " }\n";
}

// What the converter does not write: the fall 2019 format's planes, point lights and
// Blinn-Phong materials, and near/far clipping. Written without them, such a scene rendered as
// another (its planes and lights gone, its surfaces flat) with nothing said, and the comparison
// measured two different pictures; it is refused instead.
void refuse_what_is_not_converted(const Scene& scene) {
    std::string missing;
    auto add = [&missing](bool present, const std::string& what) {
        if (present) missing += (missing.empty() ? "" : ", ") + what;
    };
    add(!scene.planes.empty(), "planes");
    add(scene.lit_by_lights(), "point lights (\"lights\")");
    add(scene.materials.size() > 1, "Blinn-Phong materials (diffuse, specular, mirror, phong_exponent)");
    add(scene.clips(), "near/far clipping");
    if (!missing.empty())
        throw SceneError(scene.path, "", "the scene has " + missing +
                                             ", which clrender_to_povray does not write (docs/benchmarks.md, "
                                             "Against POV-Ray)");
}

CameraKey key_of_frame(const Scene& scene, int frame) {
    try {
        return camera_at_frame(scene, frame);
    } catch (const std::out_of_range&) {
        throw UsageError("--frame " + std::to_string(frame) + " is outside the animation's " +
                         std::to_string(animation_frame_count(scene)) + " frames (0-based)");
    }
}

}  // namespace

int povray_trace_levels(const Scene& scene) {
    long long levels = static_cast<long long>(scene.max_depth) + 1;
    for (const Billboard& billboard : scene.billboards)
        if (billboard.image) ++levels;
    levels += static_cast<long long>(scene.impostors.size());
    return static_cast<int>(std::min<long long>(levels, kPovrayMaxTraceLevel));
}

std::string povray_scene_text(const Scene& scene, int frame) {
    refuse_what_is_not_converted(scene);
    const CameraKey key = key_of_frame(scene, frame);
    std::ostringstream text;
    text << "// " << scene.name << ", frame " << frame << ", " << scene.width << " x " << scene.height
         << ": written by clrender_to_povray (docs/benchmarks.md, Against POV-Ray)\n#version 3.7;\n";
    text << settings_text(scene) << camera_text(frame_camera(scene, key, frame));
    if (scene.lit()) text << "light_source { " << vector(scene.sun_location) << " color rgb 1 }\n";
    for (const Sphere& sphere : scene.spheres) text << sphere_text(scene, sphere);
    for (const Billboard& billboard : scene.billboards) text << billboard_text(scene, billboard);
    for (const Mesh& mesh : scene.meshes)
        if (mesh.triangle_count > 0) text << mesh_text(scene, mesh);
    std::vector<Billboard> placed;
    place_impostors(scene, PlacementCamera(key, scene.up), placed);
    for (const Billboard& billboard : placed) text << billboard_text(scene, billboard);
    return text.str();
}

}  // namespace clr::bench
