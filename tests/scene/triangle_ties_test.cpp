// compute_triangle_ties() (host/scene/triangle_ties.h): for each triangle, the lowest other
// triangle sharing each of its edges and corners, against neighbours worked out by hand.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>

#include "render/feature_set.h"
#include "scene/scene_loader.h"
#include "scene/triangle_ties.h"
#include "support/scene_builder.h"

namespace clr {
namespace {

using Ties = std::array<std::int32_t, 6>;

// The four faces of a square pyramid around apex (0, 0, 1), each (apex, b_i, b_i+1), the base
// corners counter-clockwise: face i shares its edge apex-b_i+1 with face i+1 and apex-b_i with
// face i-1.
testing::TestMesh pyramid(const Vec3& shift = {}) {
    const Vec3 apex{0, 0, 1};
    const std::array<Vec3, 4> base = {Vec3{1, 1, 0}, Vec3{-1, 1, 0}, Vec3{-1, -1, 0}, Vec3{1, -1, 0}};
    testing::TestMesh mesh;
    for (int i = 0; i < 4; ++i) mesh.triangles.push_back({apex + shift, base[i] + shift, base[(i + 1) % 4] + shift});
    return mesh;
}

Scene empty() { return testing::make_scene({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 60, 16, 12); }

TEST(TriangleTies, APyramidsFacesKnowTheirNeighboursAcrossEachEdgeAndAroundEachCorner) {
    Scene scene = empty();
    testing::add_mesh(scene, pyramid(), {1, 1, 1});
    compute_triangle_ties(scene);
    ASSERT_EQ(scene.triangle_ties.size(), 4u);
    // Face i: corners (apex, b_i, b_i+1). Edge opposite corner 0 (b_i-b_i+1, the open base): none.
    // Opposite corner 1 (b_i+1-apex): face i+1. Opposite corner 2 (apex-b_i): face i-1. Around the
    // apex: the lowest other face; around b_i: face i-1; around b_i+1: face i+1.
    const std::array<Ties, 4> expected = {
        Ties{0, 1, 3, 1, 3, 1},
        Ties{1, 2, 0, 0, 0, 2},
        Ties{2, 3, 1, 0, 1, 3},
        Ties{3, 0, 2, 0, 2, 0},
    };
    for (int t = 0; t < 4; ++t) EXPECT_EQ(scene.triangle_ties[t], expected[t]) << "face " << t;
}

TEST(TriangleTies, OnlyExactlyEqualPositionsAreShared) {
    Scene scene = empty();
    testing::TestMesh mesh;
    // Two triangles sharing the edge (0,0,0)-(1,0,0), the second spelling 0 as -0; a third whose
    // corner misses (1,0,0) by one ulp shares only the corner (0,0,0).
    mesh.triangles.push_back({Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}});
    mesh.triangles.push_back({Vec3{1, -0.0, 0}, Vec3{-0.0, 0, -0.0}, Vec3{0, -1, 0}});
    mesh.triangles.push_back({Vec3{0, 0, 0}, Vec3{std::nextafter(1.0, 2.0), 0, 0}, Vec3{0, 0, 1}});
    testing::add_mesh(scene, mesh, {1, 1, 1});
    compute_triangle_ties(scene);
    EXPECT_EQ(scene.triangle_ties[0], (Ties{0, 0, 1, 1, 1, 0}));
    EXPECT_EQ(scene.triangle_ties[1], (Ties{1, 1, 0, 0, 0, 1}));
    EXPECT_EQ(scene.triangle_ties[2], (Ties{2, 2, 2, 0, 2, 2}));
}

TEST(TriangleTies, PlacementsShareNothingAndAPlacedCopyIsShiftedOrFoundAgain) {
    Scene scene = empty();
    testing::add_mesh(scene, pyramid(), {1, 1, 1});
    testing::add_mesh(scene, pyramid(), {1, 1, 1});   // the same place: still its own placement
    testing::add_mesh(scene, pyramid({5, 0, 0}), {1, 1, 1});
    // A mesh of the same file and triangle count whose faces come in another order: the first's
    // neighbours, shifted, would be wrong, so they are found again.
    testing::TestMesh reordered = pyramid({-5, 0, 0});
    std::swap(reordered.triangles[0], reordered.triangles[2]);
    testing::add_mesh(scene, reordered, {1, 1, 1});
    for (Mesh& mesh : scene.meshes) mesh.path = "pyramid.obj";
    compute_triangle_ties(scene);
    for (int placement = 1; placement < 3; ++placement)
        for (int t = 0; t < 4; ++t) {
            Ties shifted = scene.triangle_ties[t];
            for (auto& other : shifted) other += 4 * placement;
            EXPECT_EQ(scene.triangle_ties[4 * placement + t], shifted) << "placement " << placement << ", face " << t;
        }
    // Reordered: faces 12..15 are the pyramid's faces 2, 1, 0, 3.
    EXPECT_EQ(scene.triangle_ties[12], (Ties{12, 15, 13, 13, 13, 15}));
    EXPECT_EQ(scene.triangle_ties[14], (Ties{14, 13, 15, 12, 15, 13}));
}

// A vertex or an edge that every triangle shares, as a file made to be slow would have: each
// triangle's neighbours are still found (by sorting, not by scanning every triangle there for
// each; that took about 10^11 steps for these).
TEST(TriangleTies, AFanAndABookOfTwoHundredThousandTrianglesAreTiedCorrectly) {
    constexpr int kCount = 200000;
    const auto rim = [](int i) {
        const double angle = 6.0 * i / kCount;  // less than a turn: an open fan
        return Vec3{std::cos(angle), std::sin(angle), 0};
    };
    Scene scene = empty();
    testing::TestMesh fan, book;
    for (int i = 0; i < kCount; ++i) fan.triangles.push_back({Vec3{0, 0, 0}, rim(i), rim(i + 1)});
    for (int i = 0; i < kCount; ++i) book.triangles.push_back({Vec3{0, 0, 0}, Vec3{0, 0, 1}, rim(i)});
    testing::add_mesh(scene, fan, {1, 1, 1});
    testing::add_mesh(scene, book, {1, 1, 1});
    compute_triangle_ties(scene);
    for (int i : {0, 1, kCount / 2, kCount - 1}) {
        // Fan triangle i: (hub, r_i, r_i+1); its neighbours are i - 1 and i + 1, every one shares the hub.
        const int before = i > 0 ? i - 1 : i, after = i + 1 < kCount ? i + 1 : i;
        EXPECT_EQ(scene.triangle_ties[i], (Ties{i, after, before, i == 0 ? 1 : 0, before, after})) << "fan " << i;
        // Book page i: (A, B, r_i), every page on the edge AB; r_i is its own.
        const int page = kCount + i, lowest = kCount + (i == 0 ? 1 : 0);
        EXPECT_EQ(scene.triangle_ties[page], (Ties{page, page, lowest, lowest, lowest, page})) << "book " << i;
    }
}

// Where every triangle at a vertex has the same corner normal there, both sides of it shade
// alike and nothing is settled; corner normals that differ (a crease given by `vn`) are settled
// as faceted triangles are. The kernels leave the rule out when nothing is.
TEST(TriangleTies, ASmoothSurfaceIsNotSettledAndACreaseIs) {
    const Vec3 a{0, 0, 0}, b{1, 0, 0}, up{0, 0, 1}, tilted = normalize(Vec3{0, 1, 1});
    // Two triangles on the edge a-b, the second with `far_normal` at every corner, lit by the sun.
    const auto roof = [&](const Vec3& far_normal) {
        testing::TestMesh mesh;
        mesh.triangles = {{a, b, Vec3{0, 1, 0}}, {b, a, Vec3{0, -1, 1}}};
        mesh.normals = {{up, up, up}, {far_normal, far_normal, far_normal}};
        Scene scene = empty();
        scene.has_sun = true;
        testing::add_mesh(scene, mesh, {1, 1, 1});
        compute_triangle_ties(scene);
        return scene;
    };
    const Scene smooth = roof(up);
    EXPECT_EQ(smooth.triangle_ties[0], (Ties{0, 0, 0, 0, 0, 0}));
    EXPECT_EQ(smooth.triangle_ties[1], (Ties{1, 1, 1, 1, 1, 1}));
    EXPECT_FALSE(smooth.has_triangle_ties);
    EXPECT_FALSE(FeatureSet::of(smooth).triangle_ties);

    Scene crease = roof(tilted);
    EXPECT_EQ(crease.triangle_ties[0], (Ties{0, 0, 1, 1, 1, 0}));
    EXPECT_EQ(crease.triangle_ties[1], (Ties{1, 1, 0, 0, 0, 1}));
    EXPECT_TRUE(crease.has_triangle_ties);
    EXPECT_TRUE(FeatureSet::of(crease).triangle_ties);
    crease.has_sun = false;  // unlit, one colour: nothing to settle either
    EXPECT_FALSE(FeatureSet::of(crease).triangle_ties);
}

TEST(TriangleTies, TheTriangleSurfacesOfAScenesShareEdgesAsOneMesh) {
    // The fall 2019 format's `triangle` surfaces, each its own mesh, and an OBJ-less scene.
    const std::string text = R"({"eye": [0, 0, 5], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60,
        "width": 16, "height": 12, "lights": [{"position": [1, 2, 3], "color": [1, 1, 1]}],
        "surfaces": [
          {"type": "triangle", "vertices": [[0, 0, 1], [1, 1, 0], [-1, 1, 0]], "ambient": [1, 0, 0]},
          {"type": "sphere", "center": [3, 0, 0], "radius": 1, "ambient": [1, 1, 1]},
          {"type": "triangle", "vertices": [[-1, 1, 0], [0, 0, 1], [-1, -1, 0]], "ambient": [0, 1, 0]},
          {"type": "triangle", "vertices": [[5, 5, 5], [6, 5, 5], [5, 6, 5]], "ambient": [1, 1, 1]}]})";
    const Scene scene = parse_scene(text, "surfaces.json");
    ASSERT_EQ(scene.triangles.size(), 3u);
    EXPECT_EQ(scene.triangle_ties[0], (Ties{0, 1, 0, 1, 0, 1}));
    EXPECT_EQ(scene.triangle_ties[1], (Ties{1, 1, 0, 0, 0, 1}));
    EXPECT_EQ(scene.triangle_ties[2], (Ties{2, 2, 2, 2, 2, 2}));
}

}  // namespace
}  // namespace clr
