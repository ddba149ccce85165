// The benchmark's generated scenes: the advertised object counts, the same scene on every
// generation, object ids that survive the trip through a rendered colour, and a busy picture.
#include <gtest/gtest.h>

#include <array>
#include <set>

#include "bench/bench_scenes.h"
#include "reference/impostors.h"
#include "reference/reference.h"
#include "support/render_helpers.h"

namespace clr::bench {
namespace {

bool same_billboard(const Billboard& a, const Billboard& b) {
    return a.upper_left == b.upper_left && a.lower_left == b.lower_left && a.upper_right == b.upper_right &&
           a.ambient == b.ambient && (a.image == nullptr) == (b.image == nullptr) &&
           (!a.image || a.image->rgba == b.image->rgba);
}

// The object id seen through the centre of each pixel of a small frame, by the reference
// (impostors placed for that camera first: they count as billboards after the others).
std::vector<std::uint32_t> reference_ids(const Scene& unplaced, int width, int height) {
    const CameraKey& key = unplaced.camera_path.front();
    reference::CameraFrame camera = reference::make_camera(key.eye, key.lookat, unplaced.up, unplaced.fov_degrees, width, height);
    const Scene scene = reference::with_impostors_placed(unplaced, camera);
    std::vector<std::uint32_t> ids;
    int sphere_count = static_cast<int>(scene.spheres.size());
    for (int row = 0; row < height; ++row)
        for (int col = 0; col < width; ++col) {
            reference::Hit hit = reference::intersect(scene, reference::primary_ray(camera, col, row));
            ids.push_back(hit.kind == reference::HitKind::Sphere      ? sphere_id(hit.index)
                          : hit.kind == reference::HitKind::Billboard ? billboard_id(sphere_count, hit.index)
                                                                      : kBackgroundId);
        }
    return ids;
}

double covered_fraction(const std::vector<std::uint32_t>& ids) {
    std::size_t covered = 0;
    for (std::uint32_t id : ids) covered += id != kBackgroundId;
    return static_cast<double>(covered) / ids.size();
}

TEST(BenchScenes, AdvertisedCounts) {
    const std::vector<std::pair<std::string, std::array<int, 3>>> advertised = {
        {"course", {3, 2, 0}},         {"16+16", {16, 16, 0}},         {"256+256", {256, 256, 0}},
        {"4096+4096", {4096, 4096, 0}}, {"100k spheres", {100000, 0, 0}}, {"10k impostors", {0, 0, 10000}},
        {"70k triangles", {1, 0, 0}},   {"70k triangles flat", {1, 0, 0}}, {"1M triangles", {1, 0, 0}},
        {"course + mesh", {3, 2, 0}},   {"100x100k triangles", {0, 0, 0}},
    };
    ASSERT_EQ(bench_scene_specs().size(), advertised.size());
    for (std::size_t i = 0; i < advertised.size(); ++i) {
        const BenchSceneSpec& spec = bench_scene_specs()[i];
        EXPECT_EQ(spec.name, advertised[i].first);
        if (spec.instances > 0) continue;  // 10M triangles: InstancedBallsAsDescribed, smaller
        Scene scene = make_bench_scene(spec, 192, 108);
        EXPECT_EQ(static_cast<int>(scene.spheres.size()), advertised[i].second[0]) << spec.name;
        EXPECT_EQ(static_cast<int>(scene.billboards.size()), advertised[i].second[1]) << spec.name;
        EXPECT_EQ(static_cast<int>(scene.impostors.size()), advertised[i].second[2]) << spec.name;
        for (const Impostor& impostor : scene.impostors) {
            ASSERT_EQ(impostor.views.size(), 3u) << spec.name;
            for (const ImpostorView& view : impostor.views) EXPECT_TRUE(view.image && view.image->has_transparency());
        }
        bool terrain = spec.name.find("triangles") != std::string::npos;
        bool with_mesh = terrain || spec.name == "course + mesh";
        bool lit = with_mesh && spec.name.find("flat") == std::string::npos;
        EXPECT_EQ(scene.lit(), lit) << spec.name << ": flat shading but for the lit mesh scenes";
        EXPECT_EQ(spec.lit(), lit) << spec.name;
        EXPECT_EQ(spec.terrain(), terrain) << spec.name;
        EXPECT_EQ(scene.meshes.size(), with_mesh ? 1u : 0u) << spec.name;
        for (const Billboard& billboard : scene.billboards) {
            EXPECT_FALSE(billboard.is_mirror);
            ASSERT_TRUE(billboard.image) << spec.name << ": billboards are textured";
            EXPECT_TRUE(billboard.image->has_transparency()) << spec.name << ": with alpha holes";
        }
        for (const Sphere& sphere : scene.spheres) EXPECT_FALSE(sphere.is_mirror);
    }
    EXPECT_THROW(find_bench_scene("no such scene"), std::invalid_argument);
}

TEST(BenchScenes, DeterministicFromFixedSeeds) {
    for (const BenchSceneSpec& spec : bench_scene_specs()) {
        if (spec.instances > 0) continue;  // no random numbers; 10M triangles
        Scene first = make_bench_scene(spec, 1920, 1080);
        Scene second = make_bench_scene(spec, 1920, 1080);
        ASSERT_EQ(first.spheres.size(), second.spheres.size());
        for (std::size_t i = 0; i < first.spheres.size(); ++i) {
            EXPECT_EQ(first.spheres[i].center, second.spheres[i].center) << spec.name << " sphere " << i;
            EXPECT_EQ(first.spheres[i].radius, second.spheres[i].radius) << spec.name << " sphere " << i;
            EXPECT_EQ(first.spheres[i].ambient, second.spheres[i].ambient) << spec.name << " sphere " << i;
        }
        ASSERT_EQ(first.impostors.size(), second.impostors.size());
        for (std::size_t k = 0; k < first.impostors.size(); ++k) {
            EXPECT_EQ(first.impostors[k].center, second.impostors[k].center) << spec.name << " impostor " << k;
            EXPECT_EQ(first.impostors[k].width, second.impostors[k].width) << spec.name << " impostor " << k;
        }
        ASSERT_EQ(first.billboards.size(), second.billboards.size());
        for (std::size_t j = 0; j < first.billboards.size(); ++j)
            EXPECT_TRUE(same_billboard(first.billboards[j], second.billboards[j])) << spec.name << " billboard " << j;
    }
    // A pinned value: the generator must not drift with the standard library or a refactoring.
    Scene field = make_bench_scene(find_bench_scene("16+16"), 1920, 1080);
    EXPECT_NEAR(field.spheres[0].center.x, 4.1857183230813577, 1e-9);
    EXPECT_NEAR(field.spheres[0].center.y, -2.9919200278935265, 1e-9);
    EXPECT_NEAR(field.spheres[0].center.z, -23.123776266171689, 1e-9);
    EXPECT_NEAR(field.spheres[0].radius, 4.31201634237389, 1e-9);
}

// "100x100k triangles": 100 placements of one ball of about 100k triangles, in a grid, each
// one tree shape's placement (the same path and count), lit by the sun. Built here with balls of
// about 400 triangles: the layout is the same at any size.
TEST(BenchScenes, InstancedBallsAsDescribed) {
    BenchSceneSpec spec = find_bench_scene("100x100k triangles");
    EXPECT_EQ(spec.instances, 100);
    EXPECT_EQ(spec.instance_triangles, 100000);
    EXPECT_EQ(spec.triangles(), 10000000);
    EXPECT_TRUE(spec.lit());
    spec.instance_triangles = 400;
    const Scene scene = make_bench_scene(spec, 192, 108);
    ASSERT_EQ(scene.meshes.size(), 100u);
    EXPECT_TRUE(scene.lit());
    EXPECT_TRUE(scene.spheres.empty() && scene.billboards.empty());
    std::set<std::pair<double, double>> places;
    for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
        const Mesh& mesh = scene.meshes[m];
        EXPECT_EQ(mesh.path, scene.meshes[0].path) << m;
        EXPECT_EQ(mesh.triangle_count, scene.meshes[0].triangle_count) << m;
        EXPECT_NEAR(static_cast<double>(mesh.triangle_count), 400, 40) << m;
        EXPECT_EQ(mesh.ambient, id_color(mesh_id(0, 0, static_cast<int>(m)))) << m;
        // Each is the first one moved: its corners differ from the first's by one shift.
        const Vec3 shift = scene.triangles[mesh.first_triangle].corners[0] - scene.triangles[0].corners[0];
        for (std::size_t t = 0; t < mesh.triangle_count; ++t)
            for (int c = 0; c < 3; ++c) {
                const Vec3 moved = scene.triangles[t].corners[c] + shift;
                const Vec3& own = scene.triangles[mesh.first_triangle + t].corners[c];
                ASSERT_NEAR(moved.x, own.x, 1e-12);
                ASSERT_NEAR(moved.y, own.y, 1e-12);
                ASSERT_NEAR(moved.z, own.z, 1e-12);
            }
        places.insert({shift.x, shift.z});
    }
    EXPECT_EQ(places.size(), 100u) << "each ball in a place of its own";
}

// The terrain scenes: about the advertised number of triangles, one mesh with smooth normals
// inside the documented box, and the sphere floating above the hills, between them and the sun.
TEST(BenchScenes, TerrainScenesAsDescribed) {
    for (const auto& [name, advertised] : {std::pair<std::string, double>{"70k triangles", 70e3},
                                           {"70k triangles flat", 70e3}, {"1M triangles", 1e6}}) {
        Scene scene = make_bench_scene(find_bench_scene(name), 192, 108);
        ASSERT_EQ(scene.meshes.size(), 1u) << name;
        EXPECT_EQ(scene.meshes[0].triangle_count, scene.triangles.size()) << name;
        EXPECT_NEAR(static_cast<double>(scene.triangles.size()), advertised, 0.01 * advertised) << name;
        EXPECT_EQ(scene.meshes[0].ambient, id_color(mesh_id(1, 0, 0))) << name;
        ASSERT_EQ(scene.corner_normals.size(), scene.triangles.size()) << name << ": every corner has its normal";
        double lowest = 1e9, highest = -1e9, area = 0;
        for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
            const Triangle& triangle = scene.triangles[i];
            ASSERT_EQ(triangle.mesh, 0u);
            ASSERT_EQ(triangle.normals, static_cast<std::int32_t>(i));
            const auto& c = triangle.corners;
            Vec3 geometric = cross(c[1] - c[0], c[2] - c[0]);
            area += length(geometric) / 2;
            for (int k = 0; k < 3; ++k) {
                ASSERT_GE(c[k].x, -30.0) << name;
                ASSERT_LE(c[k].x, 30.0) << name;
                ASSERT_GE(c[k].z, -63.0) << name;
                ASSERT_LE(c[k].z, -3.0) << name;
                lowest = std::min(lowest, c[k].y), highest = std::max(highest, c[k].y);
                const Vec3& n = scene.corner_normals[i][k];
                ASSERT_NEAR(length(n), 1.0, 1e-12) << name;
                // A smooth surface: the corner normals lean the way the faces do.
                ASSERT_GT(dot(n, geometric), 0.9 * length(geometric)) << name << " triangle " << i;
            }
        }
        EXPECT_GE(lowest, -4.4) << name;
        EXPECT_LE(highest, -1.6) << name;
        EXPECT_GT(highest - lowest, 2.0) << name << ": hills, not a plane";
        EXPECT_GT(area, 60.0 * 60.0) << name << ": the whole 60 x 60 ground, hills being longer than flat";
        ASSERT_EQ(scene.spheres.size(), 1u);
        const Sphere& sphere = scene.spheres[0];
        EXPECT_GT(sphere.center.y - sphere.radius, highest) << name << ": above every hill";
        EXPECT_GT(scene.sun_location.y, sphere.center.y + sphere.radius) << name << ": the sun above the sphere";
    }
}

// "course + mesh": the course's objects as in "course", and a closed smooth ball of about
// 25,000 triangles whose corner normals point out of its centre, lit by the sun.
TEST(BenchScenes, CourseWithMeshAsDescribed) {
    Scene course = make_bench_scene(find_bench_scene("course"), 192, 108);
    Scene scene = make_bench_scene(find_bench_scene("course + mesh"), 192, 108);
    ASSERT_EQ(scene.spheres.size(), course.spheres.size());
    for (std::size_t i = 0; i < scene.spheres.size(); ++i) EXPECT_EQ(scene.spheres[i].center, course.spheres[i].center);
    ASSERT_EQ(scene.billboards.size(), course.billboards.size());
    for (std::size_t j = 0; j < scene.billboards.size(); ++j)
        EXPECT_TRUE(same_billboard(scene.billboards[j], course.billboards[j]));
    EXPECT_TRUE(scene.lit());
    ASSERT_EQ(scene.meshes.size(), 1u);
    EXPECT_EQ(scene.meshes[0].ambient, id_color(mesh_id(3, 2, 0)));
    // 160 x 80 quads of two triangles, less the poles' collapsed ones: one per quad of the two
    // rows that touch a pole.
    EXPECT_EQ(scene.triangles.size(), 25600u - 2 * 160);
    ASSERT_EQ(scene.corner_normals.size(), scene.triangles.size());
    Vec3 lower{1e9, 1e9, 1e9}, upper{-1e9, -1e9, -1e9};
    for (std::size_t i = 0; i < scene.triangles.size(); ++i)
        for (int k = 0; k < 3; ++k) {
            const Vec3& p = scene.triangles[i].corners[k];
            lower = {std::min(lower.x, p.x), std::min(lower.y, p.y), std::min(lower.z, p.z)};
            upper = {std::max(upper.x, p.x), std::max(upper.y, p.y), std::max(upper.z, p.z)};
            ASSERT_NEAR(length(scene.corner_normals[i][k]), 1.0, 1e-12);
        }
    const Vec3 centre = (lower + upper) / 2;
    EXPECT_NEAR(upper.x - lower.x, 3.2, 1e-9) << "a ball of radius 1.6";
    EXPECT_NEAR(upper.y - lower.y, 3.2, 1e-9);
    for (std::size_t i = 0; i < scene.triangles.size(); ++i)
        for (int k = 0; k < 3; ++k) {
            Vec3 outwards = (scene.triangles[i].corners[k] - centre) / 1.6;
            ASSERT_NEAR(dot(outwards, scene.corner_normals[i][k]), 1.0, 1e-9) << "triangle " << i;
        }
}

TEST(BenchScenes, IdsRoundTripThroughDisplayBytes) {
    std::set<std::uint32_t> codes;
    for (std::uint32_t id = 0; id < 110000; ++id) {
        Color c = id_color(id);
        auto byte = [](double v) { return reference::to_byte(v); };
        ASSERT_EQ(id_of_bytes(byte(c.x), byte(c.y), byte(c.z)), id);
        codes.insert((byte(c.x) << 16) | (byte(c.y) << 8) | byte(c.z));
    }
    EXPECT_EQ(codes.size(), 110000u) << "every object has its own colour";
    EXPECT_EQ(id_color(kBackgroundId), (Color{0, 0, 0}));
}

TEST(BenchScenes, OpaqueTexelsShowTheBillboardsId) {
    Scene scene = make_bench_scene(find_bench_scene("16+16"), 192, 108);
    for (std::size_t j = 0; j < scene.billboards.size(); ++j) {
        const Image& image = *scene.billboards[j].image;
        std::uint32_t id = billboard_id(static_cast<int>(scene.spheres.size()), static_cast<int>(j));
        for (std::size_t t = 0; t < image.rgba.size(); t += 4)
            if (image.rgba[t + 3] == 255) {
                ASSERT_EQ(id_of_bytes(image.rgba[t], image.rgba[t + 1], image.rgba[t + 2]), id);
            }
    }
}

// Most pixels of a generated field see an object, and every scene shows a fair share.
TEST(BenchScenes, BusyPictures) {
    const std::vector<std::pair<std::string, double>> least_coverage = {
        {"course", 0.5}, {"16+16", 0.75}, {"256+256", 0.8}, {"4096+4096", 0.8}, {"100k spheres", 0.8},
        {"10k impostors", 0.8},
    };
    for (const auto& [name, least] : least_coverage) {
        bool huge = name == "100k spheres" || name == "10k impostors";  // the double reference is brute force too
        Scene scene = make_bench_scene(find_bench_scene(name), 1920, 1080);
        double covered = covered_fraction(reference_ids(scene, huge ? 32 : 96, huge ? 18 : 54));
        EXPECT_GE(covered, least) << name;
    }
}

// The kernels' image of a scene decodes to the reference's object ids, but on silhouettes.
TEST(BenchScenes, RenderedColoursDecodeToObjectIds) {
    for (const std::string name : {"course", "16+16", "10k impostors"}) {
        bool huge = name == "10k impostors";
        int width = huge ? 48 : 96, height = huge ? 27 : 54;
        Scene scene = make_bench_scene(find_bench_scene(name), width, height);
        std::vector<std::uint32_t> kernel = object_ids(testing::render_with_kernels(scene));
        std::vector<std::uint32_t> expected = reference_ids(scene, width, height);
        ASSERT_EQ(kernel.size(), expected.size());
        std::size_t differing = 0;
        for (std::size_t i = 0; i < kernel.size(); ++i) differing += kernel[i] != expected[i];
        EXPECT_LE(differing, kernel.size() / 100) << name;
    }
}

}  // namespace
}  // namespace clr::bench
