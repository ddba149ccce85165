// The intersect kernel against the reference's nearest hits, for seeded random scenes and
// rays. Object ids may differ only where the reference says the ray passes within a
// relative 1e-4 of a decision boundary (a silhouette, an edge, a texel edge, a depth tie).
#include <gtest/gtest.h>

#include <cmath>

#include "reference/impostors.h"
#include "support/random_scene.h"
#include "support/stage_runner.h"

namespace clr {
namespace {

constexpr double kMarginAllowed = 1e-4;    // float32 kernels may differ this close to an edge
constexpr double kFloatEpsilon = 6e-8;      // float32 unit roundoff

int reference_kind(reference::HitKind kind) {
    switch (kind) {
        case reference::HitKind::Sphere: return CLR_HIT_SPHERE;
        case reference::HitKind::Billboard: return CLR_HIT_BILLBOARD;
        default: return CLR_HIT_NONE;
    }
}

// |cos| of the angle between the ray and the surface normal at the hit.
double grazing_cosine(const Scene& scene, const reference::Hit& hit, const reference::Ray& ray) {
    Vec3 point = ray.origin + ray.direction * hit.t;
    Vec3 normal;
    if (hit.kind == reference::HitKind::Sphere) {
        normal = normalize(point - scene.spheres[hit.index].center);
    } else {
        const Billboard& b = scene.billboards[hit.index];
        normal = normalize(cross(b.lower_left - b.upper_left, b.upper_right - b.upper_left));
    }
    return std::fabs(dot(normal, ray.direction));
}

// The error float32 can make in t, from the conditioning of each intersection: at a grazing
// angle (small cosine between ray and normal) a small error in the plane or sphere equation
// moves the hit far along the ray, by about roundoff / cosine; for a sphere the roundoff of
// its equation grows with (distance / radius). A generous factor of 50 over that estimate.
double distance_tolerance(const Scene& scene, const reference::Hit& hit, double cosine) {
    double scale = 1;
    if (hit.kind == reference::HitKind::Sphere) scale = std::max(1.0, hit.t / scene.spheres[hit.index].radius);
    return 50 * kFloatEpsilon * std::max(1.0, hit.t) * (1 + scale / std::max(cosine, 1e-6));
}

struct Agreement {
    int rays = 0, hits = 0, disagreements = 0;
};

// `device_scene` goes to the kernel; the reference sees `scene`, which is the same scene or,
// when the device scene has impostors, the reference's own placement of them.
Agreement compare_with_reference(const Scene& scene, std::uint32_t seed, int ray_count,
                                 const Scene* device_scene = nullptr) {
    std::vector<reference::Ray> rays = testing::make_random_rays(scene, seed, ray_count);
    std::vector<ClrRay> device_rays;
    for (const auto& ray : rays) device_rays.push_back(testing::to_device_ray(ray));
    testing::StageRunner runner(device_scene ? *device_scene : scene);
    std::vector<ClrHit> hits = runner.intersect(device_rays);

    Agreement agreement;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        reference::Hit expected = reference::intersect(scene, rays[i]);
        const ClrHit& hit = hits[i];
        ++agreement.rays;
        bool same_surface = hit.kind == reference_kind(expected.kind) && (hit.kind == CLR_HIT_NONE || hit.index == expected.index);
        if (!same_surface) {
            ++agreement.disagreements;
            double margin = reference::decision_margin(scene, rays[i]);
            EXPECT_LT(margin, kMarginAllowed) << "ray " << i << ": kernel hit kind " << hit.kind << " #" << hit.index
                                              << " at t=" << hit.t << ", reference kind "
                                              << reference_kind(expected.kind) << " #" << expected.index
                                              << " at t=" << expected.t;
            continue;
        }
        if (hit.kind == CLR_HIT_NONE) {
            EXPECT_TRUE(std::isinf(hit.t)) << "ray " << i;
            continue;
        }
        ++agreement.hits;
        double cosine = grazing_cosine(scene, expected, rays[i]);
        EXPECT_NEAR(hit.t, expected.t, distance_tolerance(scene, expected, cosine))
            << "ray " << i << " kind " << hit.kind << " #" << hit.index << " cos " << cosine;
    }
    return agreement;
}

class IntersectRandomTest : public ::testing::TestWithParam<std::uint32_t> {};

TEST_P(IntersectRandomTest, NearestHitMatchesReference) {
    std::uint32_t seed = GetParam();
    SCOPED_TRACE("seed " + std::to_string(seed));
    Scene scene = testing::make_random_scene(seed, 12, 12);
    Agreement agreement = compare_with_reference(scene, seed, 4000);
    // The rays are built so that most hit: a test where nothing hits would prove nothing.
    EXPECT_GT(agreement.hits, agreement.rays / 4);
    EXPECT_LT(agreement.disagreements, agreement.rays / 200);
}

INSTANTIATE_TEST_SUITE_P(Seeds, IntersectRandomTest, ::testing::Range(1u, 13u));

TEST(Intersect, SpheresOnlyAndBillboardsOnlyScenes) {
    for (std::uint32_t seed : {101u, 102u}) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        Agreement spheres = compare_with_reference(testing::make_random_scene(seed, 20, 0), seed, 2000);
        Agreement billboards = compare_with_reference(testing::make_random_scene(seed, 0, 20), seed, 2000);
        EXPECT_GT(spheres.hits, 200);
        EXPECT_GT(billboards.hits, 200);
    }
}

// Impostors reach the kernel as billboards placed for the scene's camera; the reference
// places them by itself. Their cut-out views must let rays through to what lies behind.
TEST(Intersect, ImpostorsPlacedForTheCameraMatchTheReference) {
    for (std::uint32_t seed : {201u, 202u, 203u}) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        Scene scene = testing::make_random_scene(seed, 4, 0);
        Scene with_holes = testing::make_random_scene(seed + 50, 0, 12);  // billboards with cut-out images
        for (std::size_t i = 0; i < with_holes.billboards.size(); ++i) {
            const Billboard& shape = with_holes.billboards[i];
            Impostor impostor;
            impostor.center = (shape.upper_right + shape.lower_left) / 2.0;
            impostor.width = length(shape.upper_right - shape.upper_left);
            impostor.height = length(shape.lower_left - shape.upper_left);
            impostor.facing = i % 2 ? Facing::Free : Facing::Upright;
            impostor.ambient = shape.ambient;
            if (shape.image) impostor.views = {{{0, 0, 1}, shape.image}, {{1, 0, 0}, shape.image}};
            scene.impostors.push_back(impostor);
        }
        const CameraKey& key = scene.camera_path.front();
        Scene placed = reference::with_impostors_placed(
            scene, reference::make_camera(key.eye, key.lookat, scene.up, scene.fov_degrees, scene.width, scene.height));
        Agreement agreement = compare_with_reference(placed, seed, 3000, &scene);
        EXPECT_GT(agreement.hits, 300);
        EXPECT_LT(agreement.disagreements, agreement.rays / 200);
    }
}

TEST(Intersect, EmptySceneHitsNothing) {
    Scene scene = testing::make_random_scene(7, 0, 0);
    Agreement agreement = compare_with_reference(scene, 7, 100);
    EXPECT_EQ(agreement.hits, 0);
    EXPECT_EQ(agreement.disagreements, 0);
}

}  // namespace
}  // namespace clr
