// The reference's trace observer (reference/trace_observer.h): it is told the numbers the
// reference decides with, and watching never changes what the reference computes.
#include "reference/trace_observer.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "reference/eye_relative.h"
#include "support/random_scene.h"
#include "support/scene_builder.h"

namespace clr::reference {
namespace {

using testing::make_billboard;
using testing::make_image;
using testing::make_scene;
using testing::make_sphere;

// Keeps what it is told, in order.
class Recorder : public TraceObserver {
public:
    struct SphereTest {
        int index;
        detail::SphereRoots roots;
        double t_max, t;
    };
    struct BillboardTest {
        int index;
        detail::PlaneHit plane;
        bool accepted;
    };
    std::vector<RayRole> rays;
    std::vector<SphereTest> spheres;
    std::vector<BillboardTest> billboards;
    std::vector<Hit> nearest;
    std::vector<ColourSource> colours;
    int samples = 0;

    void sample_started(int, int, double, double, const Vec3&, const Ray&) override { ++samples; }
    void ray_cast(RayRole role, int, const Ray&, double) override { rays.push_back(role); }
    void sphere_tested(int index, const detail::SphereRoots& roots, double t_max, double t) override {
        spheres.push_back({index, roots, t_max, t});
    }
    void billboard_tested(int index, const detail::PlaneHit& plane, double, bool accepted) override {
        billboards.push_back({index, plane, accepted});
    }
    void nearest_found(const Hit& hit) override { nearest.push_back(hit); }
    void colour_found(ColourSource source, const Color&) override { colours.push_back(source); }
};

TEST(TraceObserver, SphereTestCarriesTheLecturesCoefficients) {
    Scene scene = make_scene({0, 0, 6}, {0, 0, 0}, {0, 1, 0}, 60, 8, 8);
    scene.spheres.push_back(make_sphere({0.3, -0.2, 0.1}, 1.25, {1, 0, 0}));
    const Ray ray{{0, 0, 6}, normalize(Vec3{0.05, -0.03, -1})};
    Recorder recorder;
    trace(scene, ray, &recorder);
    ASSERT_EQ(recorder.spheres.size(), 1u);
    const auto& roots = recorder.spheres[0].roots;
    // A = d.d = 1, B = 2 d.(o - c), C = (o - c).(o - c) - R^2, discriminant B^2 - 4AC.
    const Vec3 oc = ray.origin - Vec3{0.3, -0.2, 0.1};
    const double b = 2 * dot(ray.direction, oc);
    const double c = dot(oc, oc) - 1.25 * 1.25;
    const double discriminant = b * b - 4 * c;
    EXPECT_NEAR(2 * roots.half_b, b, 1e-12);
    EXPECT_NEAR(roots.c, c, 1e-12);
    EXPECT_NEAR(4 * roots.quarter_discriminant, discriminant, 1e-9);
    EXPECT_NEAR(roots.t_near, (-b - std::sqrt(discriminant)) / 2, 1e-12);
    EXPECT_NEAR(roots.t_far, (-b + std::sqrt(discriminant)) / 2, 1e-12);
    EXPECT_EQ(recorder.spheres[0].t, roots.t_near);
    ASSERT_EQ(recorder.nearest.size(), 1u);
    EXPECT_EQ(recorder.nearest[0].kind, HitKind::Sphere);
    EXPECT_EQ(recorder.colours, std::vector<ColourSource>{ColourSource::SphereAmbient});
}

TEST(TraceObserver, HoleIsReportedRejectedAndTheSurfaceBehindAccepted) {
    Scene scene = make_scene({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 60, 8, 8);
    // Left texel opaque, right texel a hole.
    auto image = make_image(2, 1, [](int col, int) {
        return std::array<std::uint8_t, 4>{255, 0, 0, std::uint8_t(col == 0 ? 255 : 0)};
    });
    scene.billboards.push_back(make_billboard({-2, 2, 0}, {-2, -2, 0}, {2, 2, 0}, {0, 0, 0}, image));
    scene.billboards.push_back(make_billboard({-9, 9, -3}, {-9, -9, -3}, {9, 9, -3}, {0, 0, 1}));
    Recorder recorder;
    const Color colour = trace(scene, {{1, 0, 5}, {0, 0, -1}}, &recorder);
    EXPECT_EQ(colour, (Color{0, 0, 1}));
    ASSERT_EQ(recorder.billboards.size(), 2u);
    EXPECT_FALSE(recorder.billboards[0].accepted);
    EXPECT_NEAR(recorder.billboards[0].plane.t, 5, 1e-12);
    EXPECT_NEAR(recorder.billboards[0].plane.a, 0.75, 1e-12);  // (1 - -2) / 4
    EXPECT_NEAR(recorder.billboards[0].plane.b, 0.5, 1e-12);
    EXPECT_TRUE(recorder.billboards[1].accepted);
    EXPECT_NEAR(recorder.billboards[1].plane.t, 8, 1e-12);
}

TEST(TraceObserver, ShadowAndMirrorRaysAreAnnounced) {
    Scene scene = make_scene({0, 0, 6}, {0, 0, 0}, {0, 1, 0}, 60, 8, 8);
    scene.has_sun = true;
    scene.sun_location = {0, 8, 8};
    scene.spheres.push_back(make_sphere({0, 0, 0}, 1, {1, 0, 0}));
    scene.spheres.push_back(make_sphere({0, 4, 4.5}, 0.5, {0, 1, 0}));
    Recorder lit;
    EXPECT_EQ(trace(scene, {{0, 0, 6}, {0, 0, -1}}, &lit), (Color{0, 0, 0}));
    EXPECT_EQ(lit.rays, (std::vector<RayRole>{RayRole::Primary, RayRole::Shadow}));
    ASSERT_EQ(lit.nearest.size(), 2u);
    EXPECT_EQ(lit.nearest[1].kind, HitKind::Sphere);  // the blocker
    EXPECT_EQ(lit.nearest[1].index, 1);

    Scene mirror = make_scene({0, 0, 6}, {0, 0, 0}, {0, 1, 0}, 60, 8, 8);
    mirror.billboards.push_back(make_billboard({-3, 3, 0}, {-3, -3, 0}, {3, 3, 0}, {0, 0, 0}, nullptr, true));
    mirror.max_depth = 0;
    Recorder exhausted;
    trace(mirror, {{0, 0, 6}, {0, 0, -1}}, &exhausted);
    EXPECT_EQ(exhausted.colours, std::vector<ColourSource>{ColourSource::DepthExhausted});
    mirror.max_depth = 1;
    Recorder bounced;
    trace(mirror, {{0, 0, 6}, {0, 0, -1}}, &bounced);
    EXPECT_EQ(bounced.rays, (std::vector<RayRole>{RayRole::Primary, RayRole::Reflected}));
    EXPECT_EQ(bounced.colours, std::vector<ColourSource>{ColourSource::Background});
}

// Watching changes nothing: the same colours, bit for bit, on random scenes and rays, and
// pixel_colour() of the eye-relative scene gives render()'s bytes.
TEST(TraceObserver, WatchingChangesNoResult) {
    for (std::uint32_t seed = 1; seed <= 5; ++seed) {
        Scene scene = testing::make_random_scene(seed, 6, 6);
        scene.has_sun = seed % 2 == 0;
        scene.sun_location = {3, 20, 4};
        if (seed == 3 && !scene.spheres.empty()) scene.spheres[0].is_mirror = true;
        for (const Ray& ray : testing::make_random_rays(scene, seed, 200)) {
            Recorder recorder;
            const Color watched = trace(scene, ray, &recorder);
            const Color plain = trace(scene, ray);
            EXPECT_EQ(watched, plain) << "seed " << seed;
            EXPECT_EQ(intersect(scene, ray, kInfinity, {}, &recorder).t, intersect(scene, ray).t) << "seed " << seed;
        }
    }
    Scene scene = testing::make_random_scene(7, 5, 5);
    scene.sampling.samples_per_pixel = 3;
    scene.width = 12;
    scene.height = 9;
    scene.camera_path = {{{0, 2, 25}, {0, 0, 0}}};
    scene.up = {0, 1, 0};
    const CameraFrame camera = camera_of(scene, scene.camera_path[0]);
    const Image image = render(scene, camera, 4);
    const EyeRelative relative = relative_to_eye(scene, camera);  // what render() traces
    for (int row = 0; row < scene.height; ++row)
        for (int col = 0; col < scene.width; ++col) {
            Recorder recorder;
            const Color colour = pixel_colour(relative.scene, relative.camera, 4, col, row, &recorder);
            EXPECT_EQ(recorder.samples, 3);
            EXPECT_EQ(to_byte(colour.x), image.at(col, row, 0)) << col << "," << row;
            EXPECT_EQ(to_byte(colour.y), image.at(col, row, 1)) << col << "," << row;
            EXPECT_EQ(to_byte(colour.z), image.at(col, row, 2)) << col << "," << row;
        }
}

}  // namespace
}  // namespace clr::reference
