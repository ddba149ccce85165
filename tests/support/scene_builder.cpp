#include "support/scene_builder.h"

#include <cmath>
#include <string>

namespace clr::testing {

Scene make_scene(const Vec3& eye, const Vec3& lookat, const Vec3& up, double fov_degrees, int width, int height) {
    Scene scene;
    scene.path = "test-scene.json";
    scene.name = "test-scene";
    scene.camera_path = {{eye, lookat}};
    scene.up = up;
    scene.fov_degrees = fov_degrees;
    scene.width = width;
    scene.height = height;
    return scene;
}

Sphere make_sphere(const Vec3& center, double radius, const Color& ambient, bool mirror) {
    Sphere sphere;
    sphere.center = center;
    sphere.radius = radius;
    sphere.ambient = ambient;
    sphere.is_mirror = mirror;
    return sphere;
}

Billboard make_billboard(const Vec3& upper_left, const Vec3& lower_left, const Vec3& upper_right, const Color& ambient,
                         std::shared_ptr<const Image> image, bool mirror) {
    Billboard billboard;
    billboard.upper_left = upper_left;
    billboard.lower_left = lower_left;
    billboard.upper_right = upper_right;
    billboard.has_ambient = true;
    billboard.ambient = ambient;
    billboard.image = std::move(image);
    billboard.is_mirror = mirror;
    return billboard;
}

}  // namespace clr::testing

namespace clr::testing {

void add_mesh(Scene& scene, const TestMesh& mesh, const Color& ambient, bool mirror) {
    Mesh placed;
    placed.filename = "test-mesh-" + std::to_string(scene.meshes.size()) + ".obj";
    placed.ambient = ambient;
    placed.is_mirror = mirror;
    placed.first_triangle = scene.triangles.size();
    placed.triangle_count = mesh.triangles.size();
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
        Triangle triangle;
        triangle.corners = mesh.triangles[i];
        triangle.mesh = static_cast<std::uint32_t>(scene.meshes.size());
        if (!mesh.normals.empty()) {
            triangle.normals = static_cast<std::int32_t>(scene.corner_normals.size());
            scene.corner_normals.push_back(mesh.normals[i]);
        }
        scene.triangles.push_back(triangle);
    }
    scene.meshes.push_back(placed);
}

TestMesh sphere_mesh(const Vec3& center, double radius, int slices, int stacks, bool smooth) {
    const double pi = 3.14159265358979323846;
    const auto unit = [&](int stack, int slice) {
        const double theta = pi * stack / stacks, phi = 2 * pi * slice / slices;
        return Vec3{std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)};
    };
    TestMesh mesh;
    for (int i = 0; i < stacks; ++i)
        for (int j = 0; j < slices; ++j) {
            const Vec3 a = unit(i, j), b = unit(i, j + 1), c = unit(i + 1, j + 1), d = unit(i + 1, j);
            for (const auto& corners : {std::array<Vec3, 3>{a, b, c}, std::array<Vec3, 3>{a, c, d}}) {
                const std::array<Vec3, 3> placed = {center + corners[0] * radius, center + corners[1] * radius,
                                                    center + corners[2] * radius};
                const Vec3 area = cross(placed[1] - placed[0], placed[2] - placed[0]);
                if (!(dot(area, area) > 0)) continue;  // the poles' collapsed triangles
                mesh.triangles.push_back(placed);
                if (smooth) mesh.normals.push_back(corners);
            }
        }
    return mesh;
}

TestMesh grid_mesh(const Vec3& corner, const Vec3& edge_a, const Vec3& edge_b, int nx, int ny) {
    TestMesh mesh;
    const auto at = [&](int i, int j) { return corner + edge_a * (static_cast<double>(i) / nx) + edge_b * (static_cast<double>(j) / ny); };
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    return mesh;
}

}  // namespace clr::testing
