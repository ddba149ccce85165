// Small scenes built in code for tests, with the camera and image size set explicitly.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "scene/scene.h"

namespace clr::testing {

// A scene with one camera key, no objects, black background, flat shading.
Scene make_scene(const Vec3& eye, const Vec3& lookat, const Vec3& up, double fov_degrees, int width, int height);

Sphere make_sphere(const Vec3& center, double radius, const Color& ambient, bool mirror = false);

// A billboard from its three corners; flat colour unless an image is given.
Billboard make_billboard(const Vec3& upper_left, const Vec3& lower_left, const Vec3& upper_right,
                         const Color& ambient, std::shared_ptr<const Image> image = nullptr, bool mirror = false);

// An RGBA image whose texel (col, row) has the colour pick(col, row) (alpha included).
template <typename Pick>
std::shared_ptr<Image> make_image(int width, int height, Pick pick) {
    auto image = std::make_shared<Image>();
    image->width = width;
    image->height = height;
    image->rgba.resize(static_cast<std::size_t>(width) * height * 4);
    for (int row = 0; row < height; ++row)
        for (int col = 0; col < width; ++col) {
            auto texel = pick(col, row);
            for (int c = 0; c < 4; ++c) image->rgba[(static_cast<std::size_t>(row) * width + col) * 4 + c] = texel[c];
        }
    return image;
}

}  // namespace clr::testing

namespace clr::testing {

// Triangles of a test mesh, corners in scene coordinates, and optional corner normals.
struct TestMesh {
    std::vector<std::array<Vec3, 3>> triangles;
    std::vector<std::array<Vec3, 3>> normals;  // empty, or one per triangle
};

// Appends `mesh` to `scene` as one `obj` mesh of colour `ambient`.
void add_mesh(Scene& scene, const TestMesh& mesh, const Color& ambient, bool mirror = false);

// A sphere of `slices` x `stacks` quads (two triangles each), with its exact normals at the
// corners when `smooth`.
TestMesh sphere_mesh(const Vec3& center, double radius, int slices, int stacks, bool smooth);

// The parallelogram corner + a * edge_a + b * edge_b, 0 <= a, b <= 1, as nx x ny cells of
// two triangles each, split along the cell's diagonal from (0, 0) to (1, 1).
TestMesh grid_mesh(const Vec3& corner, const Vec3& edge_a, const Vec3& edge_b, int nx, int ny);

}  // namespace clr::testing
