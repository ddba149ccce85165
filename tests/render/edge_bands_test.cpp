// Rays exactly through the edges of a mesh where no neighbour takes the ray whichever side it
// falls (docs/scene-format.md, Meshes, "Edges and the band"): an open edge, a silhouette through
// a vertex, an edge beside a triangle seen edge on. Each precision's own rounding had put such a
// ray on either side; with every edge volume within the band counting as zero, the kernels
// (float and double, screen tiles, packets through the BVH and one ray at a time) and the
// reference agree to the pixel.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "reference/eye_relative.h"
#include "render/renderer.h"
#include "scene/triangle_ties.h"
#include "support/render_helpers.h"
#include "support/scene_builder.h"

namespace clr {
namespace {

double norm1(const Vec3& v) { return std::fabs(v.x) + std::fabs(v.y) + std::fabs(v.z); }

// Whether the ray passes through the segment (p, q), to double's rounding: the lines meet
// (their volume is zero) at a point between p and q.
bool passes_through(const reference::Ray& ray, const Vec3& p, const Vec3& q) {
    const Vec3 a = p - ray.origin, b = q - ray.origin, e = q - p;
    if (std::fabs(dot(cross(a, b), ray.direction)) > 1e-12 * (norm1(a) + norm1(b)) * norm1(e)) return false;
    // Where along the edge the ray comes nearest: a + s e closest to the ray's line.
    const Vec3 across = cross(ray.direction, cross(e, ray.direction));
    const double s = -dot(a, across) / dot(e, across);
    return s >= -1e-9 && s <= 1 + 1e-9;
}

// The pixels whose primary rays pass exactly through an edge of one of the scene's triangles.
int pixels_on_edges(const Scene& scene) {
    const reference::EyeRelative relative =
        reference::relative_to_eye(scene, reference::camera_of(scene, scene.camera_path.front()));
    int pixels = 0;
    for (int row = 0; row < scene.height; ++row)
        for (int col = 0; col < scene.width; ++col) {
            const reference::Ray ray = reference::primary_ray(relative.camera, col, row);
            const bool on_edge = std::any_of(relative.scene.triangles.begin(), relative.scene.triangles.end(),
                                             [&](const Triangle& triangle) {
                                                 const auto& c = triangle.corners;
                                                 return passes_through(ray, c[0], c[1]) ||
                                                        passes_through(ray, c[1], c[2]) ||
                                                        passes_through(ray, c[2], c[0]);
                                             });
            pixels += on_edge;
        }
    return pixels;
}

Scene view(const Vec3& eye, const Vec3& lookat, double fov, int width, int height, bool sunlit) {
    Scene scene = testing::make_scene(eye, lookat, {0, 1, 0}, fov, width, height);
    scene.background = {0.1, 0.1, 0.2};
    scene.has_sun = sunlit;
    scene.only_ambient = !sunlit;
    scene.sun_location = {10, 20, 30};
    return scene;
}

void add(Scene& scene, const testing::TestMesh& mesh) {
    testing::add_mesh(scene, mesh, {0.9, 0.7, 0.3});
    compute_triangle_ties(scene);
}

void expect_every_path_matches_the_reference(const Scene& scene, const std::string& what) {
    ASSERT_GT(pixels_on_edges(scene), 0) << what << ": no pixel's ray passes through an edge";
    testing::expect_every_kernel_path_matches_reference(scene, what);
}

// A lone triangle's open diagonal through the centre of the view: with an even image size,
// each pixel centre on the image's diagonal.
TEST(EdgeBands, ALoneTrianglesOpenDiagonalMatchesTheReference) {
    for (const auto& [width, height] : {std::array<int, 2>{64, 48}, std::array<int, 2>{160, 120}}) {
        Scene scene = view({0, 0, 5}, {0, 0, 0}, 60, width, height, true);
        testing::TestMesh mesh;
        mesh.triangles = {{Vec3{-1, -1, 0}, Vec3{1, -1, 0}, Vec3{-1, 1, 0}}};
        add(scene, mesh);
        expect_every_path_matches_the_reference(scene, "lone triangle at " + std::to_string(width));
    }
}

// A square of two triangles with a corner at the view's centre, seen from above the plane of
// its lower edge: with an odd image size the middle column and row of pixel centres run along
// two of its open edges.
TEST(EdgeBands, AnOpenSquaresEdgesAlongAPixelColumnAndRowMatchTheReference) {
    for (const auto& [width, height] : {std::array<int, 2>{161, 121}, std::array<int, 2>{65, 49}}) {
        Scene scene = view({0, 2, 5}, {0, 0, 0}, 45, width, height, true);
        add(scene, testing::grid_mesh({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 1, 1));
        expect_every_path_matches_the_reference(scene, "open square at " + std::to_string(width));
    }
}

// A closed pyramid (its base two triangles) seen from the plane of its base: the middle column of
// pixel centres runs in the base's plane, which is edge on, and through the base edge of the
// side facing the eye.
TEST(EdgeBands, AnEdgeBesideATriangleSeenEdgeOnMatchesTheReference) {
    const Vec3 apex{0, 0, 1};
    const std::array<Vec3, 4> base = {Vec3{-1, -1, 0}, Vec3{1, -1, 0}, Vec3{1, 1, 0}, Vec3{-1, 1, 0}};
    testing::TestMesh pyramid;
    for (int i = 0; i < 4; ++i) pyramid.triangles.push_back({apex, base[i], base[(i + 1) % 4]});
    pyramid.triangles.push_back({base[0], base[3], base[2]});
    pyramid.triangles.push_back({base[0], base[2], base[1]});
    for (double fov : {30.0, 90.0}) {
        Scene scene = view({7, 0, 0}, {0, 0, 0}, fov, 161, 121, false);
        add(scene, pyramid);
        expect_every_path_matches_the_reference(scene, "pyramid from its base's plane, fov " + std::to_string(fov));
    }
}

// A closed octahedron seen from a corner's axis: its silhouette passes through four vertices
// and along edges whose two triangles face away from each other.
TEST(EdgeBands, AnOctahedronsSilhouetteThroughItsVerticesMatchesTheReference) {
    const std::array<Vec3, 6> corner = {Vec3{1, 0, 0}, Vec3{-1, 0, 0}, Vec3{0, 1, 0},
                                        Vec3{0, -1, 0}, Vec3{0, 0, 1}, Vec3{0, 0, -1}};
    testing::TestMesh octahedron;
    for (int x : {0, 1})
        for (int y : {2, 3})
            for (int z : {4, 5}) octahedron.triangles.push_back({corner[x], corner[y], corner[z]});
    Scene scene = view({0, 0, 5}, {0, 0, 0}, 90, 160, 120, false);
    add(scene, octahedron);
    expect_every_path_matches_the_reference(scene, "octahedron");
}

// A cube seen along its diagonal, the middle column of pixel rays through two of its edges and
// the middle pixel's through a vertex of three faces on its silhouette. (With a band four times
// as wide, and no box for the hits the band alone admits, 10 of its pixels differed.)
TEST(EdgeBands, ACubeSeenAlongItsDiagonalMatchesTheReference) {
    const auto along = [](int axis, double length) {
        return Vec3{axis == 0 ? length : 0, axis == 1 ? length : 0, axis == 2 ? length : 0};
    };
    testing::TestMesh cube;
    for (int axis = 0; axis < 3; ++axis)
        for (double side : {-1.0, 1.0}) {
            const Vec3 centre = along(axis, side), a = along((axis + 1) % 3, 2), b = along((axis + 2) % 3, 2);
            const testing::TestMesh face = testing::grid_mesh(centre - a * 0.5 - b * 0.5, a, b, 1, 1);
            cube.triangles.insert(cube.triangles.end(), face.triangles.begin(), face.triangles.end());
        }
    for (double fov : {30.0, 45.0}) {
        Scene scene = view({4, 4, 4}, {0, 0, 0}, fov, 161, 121, true);
        add(scene, cube);
        expect_every_path_matches_the_reference(scene, "cube along its diagonal, fov " + std::to_string(fov));
    }
}

// A square whose right edge lies 1e-5 short of a column of pixel rays (64 pixels across at 90
// degrees, from 5 away: column 38's rays meet its plane at x = 1.015625): within the band of that
// edge, but outside the box of its triangles' corners by four times the box's widening. Such a
// hit counts in no path, nor in the reference.
TEST(EdgeBands, AHitTheBandAloneAdmitsCountsOnlyWithinTheTrianglesBox) {
    Scene scene = view({0, 0, 5}, {0, 0, 0}, 90, 64, 48, false);
    add(scene, testing::grid_mesh({-1, -1, 0}, {2.015625 - 1e-5, 0, 0}, {0, 2, 0}, 1, 1));
    testing::expect_every_kernel_path_matches_reference(scene, "a square 1e-5 short of a column");
    // Column 38 is the background; column 37 the square.
    const Image image = testing::render_with_reference(scene);
    EXPECT_NE(image.at(38, 24, 0), image.at(37, 24, 0));
}

}  // namespace
}  // namespace clr
