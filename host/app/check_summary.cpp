#include "app/check_summary.h"

#include <cstdio>
#include <map>
#include <sstream>
#include <vector>

#include "core/printable_text.h"
#include "render/compiled_scene.h"
#include "render/feature_set.h"
#include "scene/camera_path.h"
#include "shared/clr_types.h"

namespace clr {
namespace {

std::string count_of(std::size_t n, const std::string& one, const std::string& many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

std::string seconds_text(double seconds) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", seconds);
    return text;
}

std::string frames_line(const Scene& scene) {
    const int frames = animation_frame_count(scene);
    if (!scene.is_animated()) return "1 (a still)";
    const char* interpolation = scene.animation.interpolation == Interpolation::Linear ? "linear" : "catmull-rom";
    return std::to_string(frames) + " (" + seconds_text(frames / scene.animation.fps) + " s at " +
           seconds_text(scene.animation.fps) + " fps, " + std::to_string(scene.camera_path.size()) + " camera keys, " +
           interpolation + ")";
}

template <typename Object>
std::string objects_line(const std::vector<Object>& objects) {
    std::size_t mirrors = 0;
    for (const Object& object : objects) mirrors += object.is_mirror;
    return std::to_string(objects.size()) + (mirrors ? " (" + count_of(mirrors, "mirror", "mirrors") + ")" : "");
}

// "2 (1 mirror, 1 placeholder), 5120 triangles (2.2 MB on the device)": the device holds
// each triangle's struct, where the mesh gives them its three corner normals, and where the
// program settles hits on shared edges its neighbours there (triangle_device_bytes()).
std::string meshes_line(const Scene& scene) {
    std::size_t mirrors = 0, placeholders = 0;
    for (const Mesh& mesh : scene.meshes) {
        mirrors += mesh.is_mirror;
        placeholders += mesh.placeholder;
    }
    std::string notes;
    if (mirrors) notes += count_of(mirrors, "mirror", "mirrors");
    if (placeholders) notes += (notes.empty() ? "" : ", ") + count_of(placeholders, "placeholder", "placeholders");
    const double bytes = static_cast<double>(triangle_device_bytes(scene));
    char size[32];
    std::snprintf(size, sizeof size, "%.3g", bytes / 1e6);
    return std::to_string(scene.meshes.size()) + (notes.empty() ? "" : " (" + notes + ")") + ", " +
           count_of(scene.triangles.size(), "triangle", "triangles") +
           (scene.triangles.empty() ? "" : " (" + std::string(size) + " MB on the device)");
}

std::string images_line(const Scene& scene) {
    if (scene.image_files.empty()) return "none";
    long long pixels = 0;
    std::map<std::string, int> formats;
    for (const ImageFileInfo& file : scene.image_files) {
        pixels += file.width * file.height;
        ++formats[file.format];
    }
    std::string line = count_of(scene.image_files.size(), "file", "files") + ", " + std::to_string(pixels) +
                       " pixels in all (";
    const char* separator = "";
    for (const auto& [format, count] : formats) {
        line += separator + std::to_string(count) + " " + format;
        separator = ", ";
    }
    return line + ")";
}

// The images are decoded as for a render, so the transparency test (alpha) is known: it is
// compiled in when a shown image has a texel with alpha below 255.
std::string features_line(const Scene& scene, bool double_precision) {
    const FeatureSet features = FeatureSet::of(scene);
    const std::vector<std::pair<const char*, bool>> named = {
        {"spheres", features.spheres}, {"billboards", features.billboards}, {"triangles", features.triangles},
        {"planes", features.planes},   {"textures", features.textures},    {"lights", features.lights},
        {"alpha", features.alpha},     {"sun", features.sun},               {"mirrors", features.mirrors},
        {"clip", features.clip},       {"bvh", features.bvh},               {"double", double_precision},
    };
    std::string line;
    for (const auto& [name, on] : named) {
        if (on) line += (line.empty() ? "" : " ") + std::string(name);
    }
    return line.empty() ? "none (background only)" : line;
}

}  // namespace

std::string check_summary(const Scene& scene, bool double_precision) {
    std::ostringstream out;
    const int spp = scene.sampling.samples_per_pixel;
    out << "scene:      " << printable(scene.path) << "\n";
    out << "size:       " << scene.width << " x " << scene.height << ", " << count_of(spp, "sample", "samples")
        << " per pixel\n";
    out << "frames:     " << frames_line(scene) << "\n";
    out << "spheres:    " << objects_line(scene.spheres) << "\n";
    out << "billboards: " << objects_line(scene.billboards) << "\n";
    out << "impostors:  " << scene.impostors.size() << "\n";
    out << "meshes:     " << meshes_line(scene) << "\n";
    // The fall 2019 format's planes and point lights, listed where a scene has them.
    if (!scene.planes.empty()) out << "planes:     " << scene.planes.size() << "\n";
    if (!scene.lights.empty())
        out << "lights:     " << scene.lights.size() << (scene.lit_by_lights() ? "" : " (off: OnlyAmbient)") << "\n";
    out << "images:     " << printable(images_line(scene)) << "\n";
    out << "features:   " << features_line(scene, double_precision) << "\n";
    out << "warnings:   " << scene.warning_count
        << (scene.warnings.empty() ? "" : " (on standard error, above)") << "\n";
    return out.str();
}

}  // namespace clr
