#include "scene/scene_digest.h"

#include <exception>

#include "core/sha256.h"
#include "scene/image_loader.h"

namespace clr {

std::string scene_digest(const std::string& scene_text, const std::vector<SceneOverride>& overrides, const Scene& scene) {
    try {
        Sha256 hash;
        hash.add_field(std::string("clrender scene digest 2")).add_field(scene_text);
        hash.add_number(overrides.size());
        for (const SceneOverride& override : overrides) hash.add_field(override.argument);
        for (const ImageFileInfo& file : scene.image_files) {  // each file once, in the scene's order
            hash.add_field(file.format);
            if (file.format == "placeholder") continue;  // a missing file: its checkerboard is fixed
            const std::vector<unsigned char> bytes = read_image_file(file.path);
            hash.add_field(bytes.data(), bytes.size());
        }
        // Meshes as placed, not their files: the triangles, corner normals, colours and
        // mirror flags are exactly what the pixels depend on, .mtl colours included. A scene
        // without meshes keeps the digest it had before meshes were drawn.
        if (!scene.meshes.empty()) {
            hash.add_number(scene.meshes.size());
            for (const Mesh& mesh : scene.meshes) {
                const double values[] = {mesh.ambient.x, mesh.ambient.y, mesh.ambient.z, mesh.is_mirror ? 1.0 : 0.0};
                hash.add_field(values, sizeof values);
            }
            hash.add_field(scene.triangles.data(), scene.triangles.size() * sizeof(Triangle));
            hash.add_field(scene.corner_normals.data(), scene.corner_normals.size() * sizeof(scene.corner_normals[0]));
        }
        return to_hex(hash.finish()).substr(0, 16);
    } catch (const std::exception&) {  // libcrypto refused, or the file went away since it was read
        return "";
    }
}

}  // namespace clr
