// Rays exactly through shared mesh edges and vertices (docs/scene-format.md, Meshes, "Shared
// edges and vertices"): pixel centres placed on a faceted pyramid's ridges, a roof's ridge and
// a folded grid's creases, where which face a ray takes is a rounding decision. The kernels
// (float and double, screen tiles and one ray at a time) and the reference settle such a hit
// on the lowest-numbered triangle there, so they agree to the pixel.
#include <gtest/gtest.h>

#include <array>
#include <string>

#include "reference/eye_relative.h"
#include "reference/trace_observer.h"
#include "render/renderer.h"
#include "scene/scene_loader.h"
#include "scene/triangle_ties.h"
#include "support/image_compare.h"
#include "support/render_helpers.h"
#include "support/scene_builder.h"

namespace clr {
namespace {

// A view of the origin from `eye` (up y), against a dark blue, lit by the sun at `sun`.
Scene sunlit_view(const Vec3& eye, double fov, int width, int height, const Vec3& sun) {
    Scene scene = testing::make_scene(eye, {0, 0, 0}, {0, 1, 0}, fov, width, height);
    scene.background = {0.1, 0.1, 0.2};
    scene.has_sun = true;
    scene.sun_location = sun;
    return scene;
}

// Apex (0, 0, 1) over the square base +-1, seen along its axis from (0, 0, distance): with an
// even image size the pixel centres on the image's diagonals look exactly along its four ridges.
Scene pyramid_scene(double distance, double fov, int width, int height, bool mirror = false) {
    Scene scene = sunlit_view({0, 0, distance}, fov, width, height, {10, 20, 30});
    const Vec3 apex{0, 0, 1};
    const std::array<Vec3, 4> base = {Vec3{1, 1, 0}, Vec3{-1, 1, 0}, Vec3{-1, -1, 0}, Vec3{1, -1, 0}};
    testing::TestMesh mesh;
    for (int i = 0; i < 4; ++i) mesh.triangles.push_back({apex, base[i], base[(i + 1) % 4]});
    testing::add_mesh(scene, mesh, {0.9, 0.7, 0.3}, mirror);
    if (mirror) {  // something to reflect: a floor of two triangles far behind and a sphere
        scene.spheres.push_back(testing::make_sphere({0, 3, 2}, 1, {0.9, 0.2, 0.2}));
        testing::add_mesh(scene, testing::grid_mesh({-20, -20, -3}, {40, 0, 0}, {0, 40, 0}, 1, 1), {0.3, 0.8, 0.3});
    }
    compute_triangle_ties(scene);
    return scene;
}

// A roof whose ridge (y = 2.75 at z = 16) lies on a row of pixel centres of a 64 x 64 image.
Scene roof_scene() {
    Scene scene = sunlit_view({0, 0, 32}, 90, 64, 64, {-5, 8, 12});
    const Vec3 a{-16, 2.75, 16}, b{16, 2.75, 16}, c{-16, 14.75, 0}, d{16, 14.75, 0}, e{-16, -9.25, 0}, f{16, -9.25, 0};
    testing::TestMesh mesh;
    mesh.triangles = {{a, b, d}, {a, d, c}, {b, a, e}, {b, e, f}};
    testing::add_mesh(scene, mesh, {0.8, 0.8, 0.8});
    compute_triangle_ties(scene);
    return scene;
}

// An 8 x 8 grid on whole coordinates with heights 0 and 0.5 in a checkerboard, each square
// split along its x = y diagonal: creases and vertices under pixel rays of a 160 x 120 view.
Scene folded_scene() {
    Scene scene = sunlit_view({0, 0, 10}, 60, 160, 120, {10, 20, 30});
    const auto at = [](int i, int j) { return Vec3{double(i), double(j), (i + j) % 2 ? 0.5 : 0.0}; };
    testing::TestMesh mesh;
    for (int i = -4; i < 4; ++i)
        for (int j = -4; j < 4; ++j) {
            mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    testing::add_mesh(scene, mesh, {0.4, 0.8, 0.4});
    compute_triangle_ties(scene);
    return scene;
}

// The pyramid as the fall 2019 format's four `triangle` surfaces under a point light, each its
// own mesh: they share their edges as one. Unlit (no light), two colours meet on each ridge.
Scene surface_pyramid(bool lit) {
    const std::string light = lit ? R"("lights": [{"position": [10, 20, 30], "color": [0.8, 0.8, 0.8]}],)" : "";
    const std::string text = R"({"eye": [0, 0, 5], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60,
        "width": 160, "height": 120, "DefaultColor": [0.1, 0.1, 0.2], )" + light + R"(
        "surfaces": [
          {"type": "triangle", "vertices": [[0, 0, 1], [1, 1, 0], [-1, 1, 0]], "ambient": [0.9, 0.1, 0.1], "diffuse": [0.8, 0.6, 0.2]},
          {"type": "triangle", "vertices": [[0, 0, 1], [-1, 1, 0], [-1, -1, 0]], "ambient": [0.1, 0.9, 0.1], "diffuse": [0.2, 0.6, 0.8]},
          {"type": "triangle", "vertices": [[0, 0, 1], [-1, -1, 0], [1, -1, 0]], "ambient": [0.1, 0.1, 0.9], "diffuse": [0.8, 0.6, 0.2]},
          {"type": "triangle", "vertices": [[0, 0, 1], [1, -1, 0], [1, 1, 0]], "ambient": [0.9, 0.9, 0.1], "diffuse": [0.6, 0.2, 0.8]}]})";
    return parse_scene(text, "pyramid.json");
}

// Counts the hits that the reference finds on an edge or corner shared with another triangle.
class OnSharedEdges : public reference::TraceObserver {
public:
    void hit_settled(const reference::Hit& hit, const reference::TieSettled& tie) override {
        if (tie.other >= 0 && tie.other != hit.index) ++count;
    }
    int count = 0;
};

// The pixels some of whose rays (primary or secondary) hit a shared edge or corner: the rule
// decides those pixels, which rounding decided before.
int pixels_settled(const Scene& scene) {
    const reference::EyeRelative relative =
        reference::relative_to_eye(scene, reference::camera_of(scene, scene.camera_path.front()));
    int pixels = 0;
    for (int row = 0; row < scene.height; ++row)
        for (int col = 0; col < scene.width; ++col) {
            OnSharedEdges on_edges;
            reference::pixel_colour(relative.scene, relative.camera, 0, col, row, &on_edges);
            pixels += on_edges.count > 0;
        }
    return pixels;
}

TEST(SharedEdges, ASunlitPyramidSeenAlongItsAxisMatchesTheReferenceOnItsRidges) {
    for (double distance : {3.0, 5.0, 10.0}) {
        const Scene scene = pyramid_scene(distance, 60, 160, 120);
        const std::string what = "pyramid from " + std::to_string(distance);
        EXPECT_GT(pixels_settled(scene), 0) << what << ": no pixel on a ridge";
        testing::expect_every_kernel_path_matches_reference(scene, what);
    }
}

TEST(SharedEdges, ARoofsRidgeOnAPixelRowMatchesTheReference) {
    const Scene scene = roof_scene();
    EXPECT_GT(pixels_settled(scene), 0);
    testing::expect_every_kernel_path_matches_reference(scene, "roof");
}

TEST(SharedEdges, AFoldedGridsCreasesAndVerticesMatchTheReference) {
    const Scene scene = folded_scene();
    EXPECT_GT(pixels_settled(scene), 0);
    testing::expect_every_kernel_path_matches_reference(scene, "folded grid");
}

TEST(SharedEdges, AMirrorPyramidReflectsTheSameSideOfEachRidge) {
    const Scene scene = pyramid_scene(5, 60, 160, 120, true);
    EXPECT_GT(pixels_settled(scene), 0);
    testing::expect_every_kernel_path_matches_reference(scene, "mirror pyramid");
}

TEST(SharedEdges, TriangleSurfacesUnderALightOrUnlitMatchTheReference) {
    for (bool lit : {true, false}) {
        const Scene scene = surface_pyramid(lit);
        const std::string what = lit ? "triangle surfaces, a point light" : "triangle surfaces of four colours, unlit";
        EXPECT_GT(pixels_settled(scene), 0) << what;
        testing::expect_every_kernel_path_matches_reference(scene, what);
    }
}

}  // namespace
}  // namespace clr
