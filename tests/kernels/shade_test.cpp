// The shade kernel alone: it is given the reference's hits, so only shading is under test
// (textures, transparency, flat and sun-lit colours, shadow rays, mirror reflections).
#include <gtest/gtest.h>

#include <cmath>

#include "support/random_scene.h"
#include "support/stage_runner.h"

namespace clr {
namespace {

constexpr double kMarginAllowed = 1e-4;
constexpr double kColorTolerance = 2e-5;

ClrHit to_device_hit(const reference::Hit& hit) {
    ClrHit out{};
    out.t = std::isinf(hit.t) ? INFINITY : static_cast<float>(hit.t);
    out.kind = hit.kind == reference::HitKind::Sphere ? CLR_HIT_SPHERE
               : hit.kind == reference::HitKind::Billboard ? CLR_HIT_BILLBOARD
                                                           : CLR_HIT_NONE;
    out.index = hit.index;
    return out;
}

bool is_mirror(const Scene& scene, const reference::Hit& hit) {
    if (hit.kind == reference::HitKind::Sphere) return scene.spheres[hit.index].is_mirror;
    if (hit.kind == reference::HitKind::Billboard) return scene.billboards[hit.index].is_mirror;
    return false;
}

// Unit normal on the front side, from the scene's geometry.
Vec3 front_normal(const Scene& scene, const reference::Hit& hit, const Vec3& point) {
    if (hit.kind == reference::HitKind::Sphere) return normalize(point - scene.spheres[hit.index].center);
    const Billboard& b = scene.billboards[hit.index];
    return normalize(cross(b.lower_left - b.upper_left, b.upper_right - b.upper_left));
}

void check_shading(const Scene& scene, std::uint32_t seed, int reflections) {
    SCOPED_TRACE("seed " + std::to_string(seed) + ", reflections " + std::to_string(reflections));
    std::vector<reference::Ray> rays = testing::make_random_rays(scene, seed, 3000);
    std::vector<ClrRay> device_rays;
    std::vector<ClrHit> device_hits;
    std::vector<reference::Hit> hits;
    for (const auto& ray : rays) {
        hits.push_back(reference::intersect(scene, ray));
        device_rays.push_back(testing::to_device_ray(ray));
        device_hits.push_back(to_device_hit(hits.back()));
    }
    testing::StageRunner runner(scene);
    testing::ShadeOutput out = runner.shade(device_rays, device_hits, reflections);

    int shaded = 0, bounced = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const reference::Hit& hit = hits[i];
        const cl_float4& color = out.colors[i];
        // The reference's margin covers the whole path: this ray, its shadow ray and its
        // reflections. Float32 may legitimately decide otherwise this close to an edge.
        if (reference::decision_margin(scene, rays[i]) < kMarginAllowed) continue;
        Vec3 point = rays[i].origin + rays[i].direction * hit.t;
        if (is_mirror(scene, hit) && dot(rays[i].direction, front_normal(scene, hit, point)) < 0 &&
            reflections < scene.max_depth) {
            ++bounced;
            ASSERT_EQ(color.s[3], 0.0f) << "ray " << i << " should bounce";
            Vec3 n = front_normal(scene, hit, point);
            Vec3 reflected = rays[i].direction - n * (2 * dot(rays[i].direction, n));
            for (int k = 0; k < 3; ++k) {
                EXPECT_NEAR(out.next_rays[i].direction.s[k], reflected[k], 1e-4) << "ray " << i;
                EXPECT_NEAR(out.next_rays[i].origin.s[k], point[k], 1e-4 * std::max(1.0, std::fabs(point[k]))) << "ray " << i;
            }
            continue;
        }
        ++shaded;
        ASSERT_EQ(color.s[3], 1.0f) << "ray " << i << " should end";
        // Non-bouncing hits end the path: their colour is what the reference traces, except
        // for mirrors out of reflections (background) and mirror backs (black).
        Color expected = reference::trace(scene, rays[i]);
        if (is_mirror(scene, hit)) {
            bool front = dot(rays[i].direction, front_normal(scene, hit, point)) < 0;
            expected = front ? scene.background : Color{0, 0, 0};
        }
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(color.s[k], expected[k], kColorTolerance) << "ray " << i << " channel " << k;
    }
    EXPECT_GT(shaded, 500);
    if (reflections < scene.max_depth && (scene.spheres.size() + scene.billboards.size()) > 0) {
        bool has_mirror = false;
        for (const auto& s : scene.spheres) has_mirror |= s.is_mirror;
        for (const auto& b : scene.billboards) has_mirror |= b.is_mirror;
        if (has_mirror) {
            EXPECT_GT(bounced, 20);
        }
    }
}

TEST(Shade, FlatTexturedAndTransparentBillboards) {
    for (std::uint32_t seed : {21u, 22u, 23u}) {
        Scene scene = testing::make_random_scene(seed, 6, 12);
        scene.background = {0.25, 0.5, 0.75};
        check_shading(scene, seed, 0);
    }
}

TEST(Shade, SunLightAndShadows) {
    for (std::uint32_t seed : {31u, 32u, 33u}) {
        Scene scene = testing::make_random_scene(seed, 14, 8);
        scene.has_sun = true;
        scene.sun_location = {20, 25, 15};
        check_shading(scene, seed, 0);
    }
}

TEST(Shade, MirrorsReflectUntilMaxDepth) {
    for (std::uint32_t seed : {41u, 42u}) {
        Scene scene = testing::make_random_scene(seed, 8, 8);
        for (std::size_t i = 0; i < scene.spheres.size(); i += 2) scene.spheres[i].is_mirror = true;
        for (std::size_t i = 1; i < scene.billboards.size(); i += 2) scene.billboards[i].is_mirror = true;
        scene.max_depth = 2;
        scene.background = {0.9, 0.1, 0.3};
        check_shading(scene, seed, 0);  // reflections left: mirrors bounce
        check_shading(scene, seed, 2);  // none left: mirrors show the background
    }
}

}  // namespace
}  // namespace clr
