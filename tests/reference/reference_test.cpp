// Closed-form checks of the double-precision reference (docs/scene-format.md, Conventions). Expected values come from
// geometry worked out by hand for each scene, not from the reference's own formulas.
#include "reference/reference.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <random>

#include "support/scene_builder.h"

namespace clr::reference {
namespace {

using testing::make_billboard;
using testing::make_image;
using testing::make_scene;
using testing::make_sphere;

constexpr double kPi = 3.14159265358979323846;
constexpr double kTight = 1e-12;  // double-precision agreement for simple closed forms

double radians(double degrees) { return degrees * kPi / 180; }

double angle_between(const Vec3& a, const Vec3& b) {
    const double cosine = dot(normalize(a), normalize(b));
    return std::acos(std::max(-1.0, std::min(1.0, cosine)));
}

void expect_vec_near(const Vec3& actual, const Vec3& expected, double tolerance) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}

Ray ray_towards(const Vec3& origin, const Vec3& target) { return {origin, normalize(target - origin)}; }

const Color kRed{1, 0, 0};
const Color kGreen{0, 1, 0};
const Color kBlue{0, 0, 1};
const Color kSky{0.2, 0.4, 0.6};
const Color kBlack{0, 0, 0};

// A flat-shaded scene with a recognisable background and no objects yet. The reference takes
// the image size from the camera, so the scene's own is left at 0.
Scene empty_scene() {
    Scene scene = make_scene(Vec3(0, 0, 0), Vec3(0, 0, -1), Vec3(0, 1, 0), 60, 0, 0);
    scene.background = kSky;
    return scene;
}

// An axis-aligned billboard in the plane z = `z`, facing +z (its image reads correctly from
// z > `z`): x from x0 to x1 left to right, y from y1 (top) down to y0.
Billboard facing_plus_z(double x0, double x1, double y0, double y1, double z, const Color& ambient,
                        bool mirror = false) {
    return make_billboard(Vec3(x0, y1, z), Vec3(x0, y0, z), Vec3(x1, y1, z), ambient, nullptr, mirror);
}

using Rgba = std::array<std::uint8_t, 4>;

Rgba pixel(const Image& image, int col, int row) {
    return {image.at(col, row, 0), image.at(col, row, 1), image.at(col, row, 2), image.at(col, row, 3)};
}

// ---------------------------------------------------------------------------------------
// Camera

TEST(ReferenceCamera, BasisIsOrthonormalAndRightHanded) {
    struct Setup {
        Vec3 eye, lookat, up;
    };
    const Setup setups[] = {
        {{0, 0, 0}, {0, 0, -1}, {0, 1, 0}},
        {{1, 2, 3}, {-4, 0.5, 7}, {0.3, 2, -0.1}},  // up neither unit nor orthogonal to the view
        {{-5, 5, 5}, {0, 0, 0}, {0, 0, 10}},
        {{0, 10, 0}, {0, 0, 0}, {0, 0, -1}},  // looking straight down
    };
    for (const Setup& s : setups) {
        const CameraFrame camera = make_camera(s.eye, s.lookat, s.up, 60, 40, 30);
        EXPECT_NEAR(length(camera.u), 1, kTight);
        EXPECT_NEAR(length(camera.v), 1, kTight);
        EXPECT_NEAR(length(camera.w), 1, kTight);
        EXPECT_NEAR(dot(camera.u, camera.v), 0, kTight);
        EXPECT_NEAR(dot(camera.u, camera.w), 0, kTight);
        EXPECT_NEAR(dot(camera.v, camera.w), 0, kTight);
        expect_vec_near(cross(camera.u, camera.v), camera.w, kTight);     // right-handed
        EXPECT_NEAR(angle_between(camera.w, s.eye - s.lookat), 0, 1e-7);  // w points at the viewer
        EXPECT_NEAR(dot(camera.u, s.up), 0, kTight);                      // no roll: right is level
        EXPECT_GT(dot(camera.v, s.up), 0);                                // screen up leans towards `up`
    }
}

TEST(ReferenceCamera, LookingDownMinusZHasXRightAndYUp) {
    const CameraFrame camera = make_camera({0, 0, 0}, {0, 0, -7}, {0, 3, 0}, 90, 10, 10);
    expect_vec_near(camera.u, {1, 0, 0}, kTight);
    expect_vec_near(camera.v, {0, 1, 0}, kTight);
    expect_vec_near(camera.w, {0, 0, 1}, kTight);
}

TEST(ReferenceCamera, ScreenRightIsForwardCrossUp) {
    // Facing +x with +z up in a right-handed world, one's right hand points to -y.
    const CameraFrame camera = make_camera({0, 0, 0}, {5, 0, 0}, {0, 0, 1}, 90, 10, 10);
    expect_vec_near(camera.u, {0, -1, 0}, kTight);
    expect_vec_near(camera.v, {0, 0, 1}, kTight);
}

TEST(ReferenceCamera, ObjectsRightOfAndAboveTheAxisLandRightAndUp) {
    // Camera at the origin facing +x with z up: the viewer's right is -y, up is +z.
    Scene scene = empty_scene();
    scene.background = kBlack;
    scene.spheres = {make_sphere({10, -3, 0}, 1, kRed), make_sphere({10, 0, 3}, 1, kGreen)};
    const int width = 41, height = 31;
    const Image image = render(scene, make_camera({0, 0, 0}, {1, 0, 0}, {0, 0, 1}, 60, width, height));
    int red = 0, green = 0;
    for (int row = 0; row < height; ++row) {
        for (int col = 0; col < width; ++col) {
            const Rgba p = pixel(image, col, row);
            if (p[0] == 255) {
                ++red;
                EXPECT_GT(col, width / 2) << "row " << row;
                EXPECT_EQ(row, std::clamp(row, 10, 20)) << "right of the axis, but not far off its height";
            }
            if (p[1] == 255) {
                ++green;
                EXPECT_LT(row, height / 2) << "col " << col;
            }
        }
    }
    EXPECT_GT(red, 10);
    EXPECT_GT(green, 10);
}

TEST(ReferenceCamera, PrimaryRaysStartAtTheEyeWithUnitDirection) {
    const CameraFrame camera = make_camera({1, -2, 3}, {4, 4, -1}, {0, 1, 0}, 75, 17, 9);
    for (int row = 0; row < 9; row += 4) {
        for (int col = 0; col < 17; col += 8) {
            const Ray ray = primary_ray(camera, col, row);
            expect_vec_near(ray.origin, {1, -2, 3}, 0);
            EXPECT_NEAR(length(ray.direction), 1, kTight);
        }
    }
}

TEST(ReferenceCamera, SquareFov90CornerRaysAreNear45Degrees) {
    // The frustum's edges lie at 45 degrees from the axis; corner pixel centres sit half a
    // pixel inside, so for N pixels their tangents are 1 - 1/N along both screen axes.
    const int n = 1000;
    const CameraFrame camera = make_camera({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 90, n, n);
    const double inset_tangent = 1 - 1.0 / n;
    const struct {
        int col, row;
        double sx, sy;  // expected signs of x and y
    } corners[] = {{0, 0, -1, 1}, {n - 1, 0, 1, 1}, {0, n - 1, -1, -1}, {n - 1, n - 1, 1, -1}};
    for (const auto& corner : corners) {
        const Vec3 d = primary_ray(camera, corner.col, corner.row).direction;
        EXPECT_NEAR(d.x / -d.z, corner.sx * inset_tangent, kTight);
        EXPECT_NEAR(d.y / -d.z, corner.sy * inset_tangent, kTight);
        // Horizontal and vertical angles just under 45 degrees; off-axis angle near atan(sqrt 2).
        EXPECT_NEAR(std::atan(std::abs(d.x / d.z)), radians(45), radians(0.05));
        EXPECT_LT(std::atan(std::abs(d.x / d.z)), radians(45));
        EXPECT_NEAR(angle_between(d, {0, 0, -1}), std::atan(std::sqrt(2.0)), radians(0.05));
    }
}

// The angle between the rays through the first and last pixel centres of the middle row
// and column. With an odd pixel count, the middle row and column lie on the view axis.
struct Spans {
    double across, down;
};
Spans angular_spans(int width, int height, double fov) {
    const CameraFrame camera = make_camera({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, fov, width, height);
    const int mid_col = width / 2, mid_row = height / 2;
    return {
        angle_between(primary_ray(camera, 0, mid_row).direction, primary_ray(camera, width - 1, mid_row).direction),
        angle_between(primary_ray(camera, mid_col, 0).direction, primary_ray(camera, mid_col, height - 1).direction)};
}

TEST(ReferenceCamera, WideImageSpansTheFovAcross) {
    // 301 x 101 at 60 degrees: the plane at distance 1 is 2 tan 30 wide, each pixel
    // 2 tan 30 / 301 across and (square pixels) as tall; outer pixel centres are half a pixel in.
    const double t = std::tan(radians(30));
    const Spans spans = angular_spans(301, 101, 60);
    EXPECT_NEAR(spans.across, 2 * std::atan(t * 300 / 301), kTight);
    EXPECT_NEAR(spans.down, 2 * std::atan(t * 100 / 301), kTight);
}

TEST(ReferenceCamera, TallImageSpansTheFovDown) {
    const double t = std::tan(radians(30));
    const Spans spans = angular_spans(101, 301, 60);
    EXPECT_NEAR(spans.down, 2 * std::atan(t * 300 / 301), kTight);
    EXPECT_NEAR(spans.across, 2 * std::atan(t * 100 / 301), kTight);
}

TEST(ReferenceCamera, PixelsAreSquare) {
    // Neighbouring centres near the axis are the same angle apart across and down.
    const std::array<int, 2> sizes[] = {{301, 101}, {101, 301}};
    for (const auto& size : sizes) {
        const CameraFrame camera = make_camera({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 50, size[0], size[1]);
        const Vec3 centre = primary_ray(camera, size[0] / 2, size[1] / 2).direction;
        const double across = angle_between(centre, primary_ray(camera, size[0] / 2 + 1, size[1] / 2).direction);
        const double down = angle_between(centre, primary_ray(camera, size[0] / 2, size[1] / 2 + 1).direction);
        EXPECT_NEAR(across, down, 1e-12);
    }
}

TEST(ReferenceCamera, TiltedUpVectorsKeepTheirScreenMeaning) {
    // An up vector leaning towards the viewer: only its part across the view counts.
    const CameraFrame leaning = make_camera({0, 0, 0}, {0, 0, -1}, {0, 1, 1}, 60, 10, 10);
    expect_vec_near(leaning.v, {0, 1, 0}, kTight);
    expect_vec_near(leaning.u, {1, 0, 0}, kTight);

    // An up vector rolled 45 degrees clockwise (seen by the viewer) rolls the screen with it.
    const double h = std::sqrt(0.5);
    const CameraFrame rolled = make_camera({0, 0, 0}, {0, 0, -1}, {1, 1, 0}, 60, 10, 10);
    expect_vec_near(rolled.v, {h, h, 0}, kTight);
    expect_vec_near(rolled.u, {h, -h, 0}, kTight);
}

// ---------------------------------------------------------------------------------------
// Spheres

TEST(ReferenceSphere, HeadOnCentrePixelHitsAtDistanceMinusRadius) {
    Scene scene = empty_scene();
    const Vec3 eye{1, 2, 3};
    const Vec3 center = eye + Vec3(3, 4, 12);  // 13 away
    scene.spheres = {make_sphere(center, 2, kRed)};
    const CameraFrame camera = make_camera(eye, center, {0, 1, 0}, 40, 5, 5);
    const Hit hit = intersect(scene, primary_ray(camera, 2, 2));
    EXPECT_EQ(hit.kind, HitKind::Sphere);
    EXPECT_EQ(hit.index, 0);
    EXPECT_NEAR(hit.t, 11, kTight);
}

TEST(ReferenceSphere, GrazingRaysHitOrMissAsTheGeometrySays) {
    // A ray along -z whose line passes at distance `offset` from the centre of a unit sphere
    // 10 away: it hits iff offset <= 1, at t = 10 - sqrt(1 - offset^2).
    const Ray ray{{0, 0, 0}, {0, 0, -1}};
    for (const double offset : {0.0, 0.5, 0.999, 1 - 1e-9}) {
        Scene scene = empty_scene();
        scene.spheres = {make_sphere({offset, 0, -10}, 1, kRed)};
        const Hit hit = intersect(scene, ray);
        ASSERT_EQ(hit.kind, HitKind::Sphere) << offset;
        EXPECT_NEAR(hit.t, 10 - std::sqrt(1 - offset * offset), 1e-9) << offset;
    }
    for (const double offset : {1 + 1e-9, 1.001, 3.0}) {
        Scene scene = empty_scene();
        scene.spheres = {make_sphere({offset, 0, -10}, 1, kRed)};
        EXPECT_EQ(intersect(scene, ray).kind, HitKind::None) << offset;
    }
}

TEST(ReferenceSphere, SmallDistantSphereIsHitAccurately) {
    // 1e6 away and 1e-3 in radius: (B/2)^2 and C are both ~1e12 and nearly equal, so a
    // naive discriminant loses every digit of the 1e-6 it should be.
    Scene scene = empty_scene();
    const Vec3 direction = normalize(Vec3(1, 2, -2));
    scene.spheres = {make_sphere(direction * 1e6, 1e-3, kRed)};
    const Hit hit = intersect(scene, {{0, 0, 0}, direction});
    ASSERT_EQ(hit.kind, HitKind::Sphere);
    EXPECT_NEAR(hit.t, 1e6 - 1e-3, 1e-7);
}

TEST(ReferenceSphere, EyeAtTheCentreHitsTheFarSideAtTheRadius) {
    Scene scene = empty_scene();
    const Vec3 center{2, -1, 4};
    scene.spheres = {make_sphere(center, 3, kRed)};
    for (const Vec3& d : {Vec3(1, 0, 0), Vec3(0, -1, 0), Vec3(1, 2, 3), Vec3(-3, 1, -1)}) {
        const Hit hit = intersect(scene, {center, normalize(d)});
        ASSERT_EQ(hit.kind, HitKind::Sphere);
        EXPECT_NEAR(hit.t, 3, kTight);
    }
}

TEST(ReferenceSphere, EyeInsideOffCentreTakesTheFarRoot) {
    Scene scene = empty_scene();
    scene.spheres = {make_sphere({0, 0, 0}, 2, kRed)};
    EXPECT_NEAR(intersect(scene, {{0.5, 0, 0}, {1, 0, 0}}).t, 1.5, kTight);
    EXPECT_NEAR(intersect(scene, {{0.5, 0, 0}, {-1, 0, 0}}).t, 2.5, kTight);
}

TEST(ReferenceSphere, SpheresBehindTheOriginAreIgnored) {
    Scene scene = empty_scene();
    scene.spheres = {make_sphere({0, 0, 5}, 1, kRed)};
    EXPECT_EQ(intersect(scene, {{0, 0, 0}, {0, 0, -1}}).kind, HitKind::None);
}

TEST(ReferenceSphere, NearestOfSeveralWinsWhateverTheOrder) {
    Scene scene = empty_scene();
    scene.spheres = {make_sphere({0, 0, -20}, 1, kRed), make_sphere({0, 0, -10}, 1, kGreen),
                     make_sphere({0, 0, -30}, 1, kBlue)};
    const Hit hit = intersect(scene, {{0, 0, 0}, {0, 0, -1}});
    EXPECT_EQ(hit.index, 1);
    EXPECT_NEAR(hit.t, 9, kTight);
    EXPECT_EQ(trace(scene, {{0, 0, 0}, {0, 0, -1}}), kGreen);
}

TEST(ReferenceSphere, TMaxAndTheSurfaceBeingLeftAreRespected) {
    Scene scene = empty_scene();
    scene.spheres = {make_sphere({0, 0, -10}, 1, kRed), make_sphere({0, 0, -20}, 1, kGreen)};
    const Ray ray{{0, 0, 0}, {0, 0, -1}};
    EXPECT_EQ(intersect(scene, ray, 9).kind, HitKind::None);  // t must be strictly below t_max
    EXPECT_EQ(intersect(scene, ray, 9.5).index, 0);
    const Hit skipping = intersect(scene, ray, kInfinity, {HitKind::Sphere, 0});
    EXPECT_EQ(skipping.index, 1);
    EXPECT_NEAR(skipping.t, 19, kTight);
}

TEST(ReferenceSphere, RandomHitsLieOnTheSurfaceAndNothingIsNearer) {
    std::mt19937 rng(433);
    std::uniform_real_distribution<double> coord(-5, 5);
    Scene scene = empty_scene();
    for (int i = 0; i < 6; ++i)
        scene.spheres.push_back(make_sphere({coord(rng), coord(rng), coord(rng)}, 0.5 + i * 0.2, kRed));
    int hits = 0;
    for (int i = 0; i < 2000; ++i) {
        const Ray ray = ray_towards({coord(rng), coord(rng), 12}, {coord(rng), coord(rng), coord(rng)});
        const Hit hit = intersect(scene, ray);
        if (hit.kind == HitKind::None) continue;
        ++hits;
        const Sphere& s = scene.spheres[hit.index];
        EXPECT_NEAR(length(ray.origin + ray.direction * hit.t - s.center), s.radius, 1e-9);
        // Marching the ray in small steps before the hit never enters any sphere.
        for (double t = 0; t < hit.t - 1e-6; t += 0.05) {
            for (const Sphere& other : scene.spheres) {
                EXPECT_GE(length(ray.origin + ray.direction * t - other.center), other.radius - 1e-9);
            }
        }
    }
    EXPECT_GT(hits, 200);
}

// ---------------------------------------------------------------------------------------
// Billboards

// An image whose every texel has its own colour, so that a wrong texel shows.
Rgba numbered_texel(int col, int row) {
    return {static_cast<std::uint8_t>(10 + 30 * col), static_cast<std::uint8_t>(20 + 40 * row), 200, 255};
}

// A camera at the origin looking down -z at distance D sees, at fov 90, a plane region
// D x half-extents; a billboard exactly that size maps pixel centres to texel centres.
struct FramedBillboard {
    Scene scene;
    int width = 8, height = 6;
};
FramedBillboard frame_filling_billboard() {
    FramedBillboard framed;
    const double distance = 4;
    const double half_w = distance * std::tan(radians(45));  // the wider dimension spans the fov
    const double half_h = half_w * framed.height / framed.width;
    Billboard b = facing_plus_z(-half_w, half_w, -half_h, half_h, -distance, kBlack);
    b.image = make_image(framed.width, framed.height, numbered_texel);
    framed.scene = empty_scene();
    framed.scene.billboards = {b};
    return framed;
}

TEST(ReferenceBillboard, FillingTheFrameShowsEachTexelAtItsPixel) {
    const FramedBillboard framed = frame_filling_billboard();
    const CameraFrame camera = make_camera({0, 0, 0}, {0, 0, -4}, {0, 1, 0}, 90, framed.width, framed.height);
    const Image image = render(framed.scene, camera);
    for (int row = 0; row < framed.height; ++row) {
        for (int col = 0; col < framed.width; ++col) {
            EXPECT_EQ(pixel(image, col, row), numbered_texel(col, row)) << col << "," << row;
        }
    }
}

TEST(ReferenceBillboard, SeenFromBehindTheImageIsMirrored) {
    // Same billboard, the camera now 4 behind it looking towards +z: its right is -x.
    const FramedBillboard framed = frame_filling_billboard();
    const CameraFrame camera = make_camera({0, 0, -8}, {0, 0, -4}, {0, 1, 0}, 90, framed.width, framed.height);
    const Image image = render(framed.scene, camera);
    for (int row = 0; row < framed.height; ++row) {
        for (int col = 0; col < framed.width; ++col) {
            EXPECT_EQ(pixel(image, col, row), numbered_texel(framed.width - 1 - col, row)) << col << "," << row;
        }
    }
}

TEST(ReferenceBillboard, ParallelogramCoordinatesAreRecovered) {
    // A sheared, tilted parallelogram: edges not perpendicular, not unit, not axis-aligned.
    const Vec3 ul{-1, 1, -5};
    const Vec3 edge_a{2, 0, 0.5};
    const Vec3 edge_b{0.8, -2, 0};
    Scene scene = empty_scene();
    scene.billboards = {make_billboard(ul, ul + edge_b, ul + edge_a, kRed)};
    const Vec3 origin{0.3, 0.2, 3};
    const std::array<double, 2> inside[] = {{0.5, 0.5}, {0.1, 0.9}, {0.95, 0.02}, {0, 0.3}, {1, 1}};
    for (const auto& ab : inside) {
        const Vec3 p = ul + edge_a * ab[0] + edge_b * ab[1];
        const Hit hit = intersect(scene, ray_towards(origin, p));
        ASSERT_EQ(hit.kind, HitKind::Billboard) << ab[0] << "," << ab[1];
        EXPECT_NEAR(hit.a, ab[0], 1e-12);
        EXPECT_NEAR(hit.b, ab[1], 1e-12);
        EXPECT_NEAR(hit.t, length(p - origin), 1e-12);
    }
    // Outside the parallelogram, including (-0.2, 0.9): inside the bounding rectangle a
    // projection onto unit edges would use, but left of the sheared left edge.
    const std::array<double, 2> outside[] = {{-0.2, 0.9}, {1.02, 0.3}, {0.5, 1.1}, {0.5, -0.01}};
    for (const auto& ab : outside) {
        const Vec3 p = ul + edge_a * ab[0] + edge_b * ab[1];
        EXPECT_EQ(intersect(scene, ray_towards(origin, p)).kind, HitKind::None) << ab[0] << "," << ab[1];
    }
}

TEST(ReferenceBillboard, RaysParallelToThePlaneOrAwayFromItMiss) {
    Scene scene = empty_scene();
    scene.billboards = {facing_plus_z(-1, 1, -1, 1, -5, kRed)};
    EXPECT_EQ(intersect(scene, {{0, 0, -5}, {1, 0, 0}}).kind, HitKind::None);  // in the plane
    EXPECT_EQ(intersect(scene, {{0, 0, -4}, {0, 1, 0}}).kind, HitKind::None);  // parallel, off it
    EXPECT_EQ(intersect(scene, {{0, 0, 0}, {0, 0, 1}}).kind, HitKind::None);   // plane behind
}

TEST(ReferenceBillboard, TheFarEdgesClampToTheLastTexel) {
    Billboard b = facing_plus_z(0, 4, -4, 0, -5, kBlack);  // UL (0,0), UR (4,0), LL (0,-4)
    b.image = make_image(3, 2, numbered_texel);
    Scene scene = empty_scene();
    scene.billboards = {b};
    // The lower right corner is exactly a = b = 1: column floor(3) clamps to 2, row to 1.
    const Color lower_right = trace(scene, {{4, -4, 0}, {0, 0, -1}});
    const Rgba expected = numbered_texel(2, 1);
    EXPECT_EQ(lower_right, Color(expected[0], expected[1], expected[2]) / 255.0);
    EXPECT_EQ(trace(scene, {{0, 0, 0}, {0, 0, -1}}), Color(10, 20, 200) / 255.0);  // a = b = 0
}

TEST(ReferenceBillboard, TransparentTexelsLetTheSphereBehindShow) {
    // Three texels across: alpha 0, alpha 254 (still transparent: below 255), opaque red.
    Billboard b = facing_plus_z(-1, 1, -1, 1, -5, kBlack);
    b.image = make_image(3, 1, [](int col, int) {
        const std::uint8_t alpha = col == 0 ? 0 : (col == 1 ? 254 : 255);
        return Rgba{255, 0, 0, alpha};
    });
    Scene scene = empty_scene();
    scene.billboards = {b};
    scene.spheres = {make_sphere({0, 0, -10}, 3, kBlue)};
    const Vec3 eye{0, 0, 0};
    const double texel_centres_x[] = {-2.0 / 3, 0, 2.0 / 3};
    EXPECT_EQ(intersect(scene, ray_towards(eye, {texel_centres_x[0], 0, -5})).kind, HitKind::Sphere);
    EXPECT_EQ(trace(scene, ray_towards(eye, {texel_centres_x[0], 0, -5})), kBlue);
    EXPECT_EQ(trace(scene, ray_towards(eye, {texel_centres_x[1], 0, -5})), kBlue);
    const Hit opaque = intersect(scene, ray_towards(eye, {texel_centres_x[2], 0, -5}));
    EXPECT_EQ(opaque.kind, HitKind::Billboard);
    EXPECT_NEAR(opaque.a, 5.0 / 6, kTight);
    EXPECT_EQ(trace(scene, ray_towards(eye, {texel_centres_x[2], 0, -5})), kRed);
}

TEST(ReferenceBillboard, FlatBillboardShowsItsAmbientAndHidesWhatIsBehind) {
    Scene scene = empty_scene();
    scene.spheres = {make_sphere({0, 0, -10}, 1, kBlue)};
    scene.billboards = {facing_plus_z(-1, 1, -1, 1, -5, kGreen)};
    EXPECT_EQ(trace(scene, {{0, 0, 0}, {0, 0, -1}}), kGreen);
    EXPECT_EQ(trace(scene, {{0, 0, -20}, {0, 0, 1}}), kBlue);  // from the other side, the sphere is nearer
}

// ---------------------------------------------------------------------------------------
// Lighting

// A unit sphere at the origin seen from +z; the centre pixel of a 5x5 frame hits its top
// point P = (0,0,1), where the outward normal is +z. The sun sits 50 from P at `angle` from
// the normal, in the xz plane.
struct LitSetup {
    Scene scene;
    Ray centre_ray;
};
const Color kAmbient{0.8, 0.6, 0.4};
LitSetup lit_sphere(double sun_angle_degrees) {
    LitSetup setup;
    setup.scene = empty_scene();
    setup.scene.spheres = {make_sphere({0, 0, 0}, 1, kAmbient)};
    setup.scene.has_sun = true;
    const double angle = radians(sun_angle_degrees);
    setup.scene.sun_location = Vec3(0, 0, 1) + Vec3(std::sin(angle), 0, std::cos(angle)) * 50;
    setup.centre_ray = primary_ray(make_camera({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 30, 5, 5), 2, 2);
    return setup;
}

TEST(ReferenceLighting, LitSphereIsAmbientTimesTheCosine) {
    for (const double angle : {0.0, 30.0, 60.0, 89.0}) {
        const LitSetup setup = lit_sphere(angle);
        expect_vec_near(trace(setup.scene, setup.centre_ray), kAmbient * std::cos(radians(angle)), 1e-12);
    }
}

TEST(ReferenceLighting, SunBelowTheHorizonGivesBlack) {
    for (const double angle : {90.5, 120.0, 180.0}) {
        const LitSetup setup = lit_sphere(angle);
        EXPECT_EQ(trace(setup.scene, setup.centre_ray), kBlack) << angle;
    }
}

TEST(ReferenceLighting, FlatModeIgnoresTheSun) {
    LitSetup setup = lit_sphere(60);
    setup.scene.only_ambient = true;
    EXPECT_EQ(trace(setup.scene, setup.centre_ray), kAmbient);
    setup.scene.only_ambient = false;
    setup.scene.has_sun = false;
    EXPECT_EQ(trace(setup.scene, setup.centre_ray), kAmbient);
}

TEST(ReferenceLighting, SphereBetweenPointAndSunCastsAShadow) {
    const Vec3 p{0, 0, 1};
    const Vec3 l = normalize(Vec3(1, 0, 1));  // sun at 45 degrees, 50 away
    LitSetup setup = lit_sphere(45);
    setup.scene.spheres.push_back(make_sphere(p + l * 10, 1, kRed));  // on the way to the sun
    EXPECT_EQ(trace(setup.scene, setup.centre_ray), kBlack);

    setup.scene.spheres.back().center = p + l * 60;  // beyond the sun: no shadow
    expect_vec_near(trace(setup.scene, setup.centre_ray), kAmbient * std::sqrt(0.5), 1e-12);

    setup.scene.spheres.back().center = p + l * 10 + Vec3(0, 1.5, 0);  // beside the way
    expect_vec_near(trace(setup.scene, setup.centre_ray), kAmbient * std::sqrt(0.5), 1e-12);
}

TEST(ReferenceLighting, BillboardShadowsComeOnlyFromOpaqueTexels) {
    // The sun at 45 degrees from P = (0,0,1): the shadow ray crosses the plane z = 3 at x = 2,
    // away from the camera's ray down the z axis. A billboard there has a transparent left
    // texel and an opaque right one.
    const std::uint8_t clear = 0, opaque = 255;
    const auto half_clear = make_image(2, 1, [&](int col, int) { return Rgba{9, 9, 9, col == 0 ? clear : opaque}; });
    for (const bool through_opaque : {false, true}) {
        LitSetup setup = lit_sphere(45);
        // x = 2 is at a = 0.75 (opaque) for x in [0.5, 2.5], at a = 0.25 for x in [1.5, 3.5].
        const double x0 = through_opaque ? 0.5 : 1.5;
        Billboard b = facing_plus_z(x0, x0 + 2, -1, 1, 3, kBlack);
        b.image = half_clear;
        setup.scene.billboards = {b};
        const Color expected = through_opaque ? kBlack : kAmbient * std::sqrt(0.5);
        expect_vec_near(trace(setup.scene, setup.centre_ray), expected, 1e-12);
    }
}

TEST(ReferenceLighting, BillboardsAreUnlit) {
    // The sun behind the billboard and at a grazing angle: its colour is shown as it is.
    Scene scene = empty_scene();
    scene.has_sun = true;
    scene.sun_location = Vec3(100, 0, -50);
    Billboard flat = facing_plus_z(-1, 1, -1, 1, -5, kGreen);
    Billboard textured = facing_plus_z(2, 4, -1, 1, -5, kBlack);
    textured.image = make_image(1, 1, [](int, int) { return Rgba{51, 102, 153, 255}; });
    scene.billboards = {flat, textured};
    EXPECT_EQ(trace(scene, {{0, 0, 0}, {0, 0, -1}}), kGreen);
    EXPECT_EQ(trace(scene, {{3, 0, 0}, {0, 0, -1}}), Color(0.2, 0.4, 0.6));
}

// ---------------------------------------------------------------------------------------
// Mirrors

TEST(ReferenceMirror, MirrorBillboardShowsTheSphereBehindTheCamera) {
    Scene scene = empty_scene();
    scene.spheres = {make_sphere({0, 0, 5}, 1, kRed)};
    Billboard mirror = facing_plus_z(-2, 2, -2, 2, -5, kBlack, true);
    // A mirror ignores its image, transparent texels included.
    mirror.image = make_image(1, 1, [](int, int) { return Rgba{0, 255, 0, 0}; });
    scene.billboards = {mirror};
    EXPECT_EQ(trace(scene, {{0, 0, 0}, {0, 0, -1}}), kRed);
    // A ray reflected away from the sphere: leaves (0.5,0,-5) in direction (0.1,0,1)/|.|,
    // passing x = 1.5 at z = 5, outside the unit sphere.
    EXPECT_EQ(trace(scene, ray_towards({0, 0, 0}, {0.5, 0, -5})), kSky);
}

TEST(ReferenceMirror, TheBackOfAMirrorIsBlack) {
    Scene scene = empty_scene();
    scene.spheres = {make_sphere({0, 0, 5}, 1, kRed)};
    scene.billboards = {facing_plus_z(-2, 2, -2, 2, -5, kBlack, true)};
    EXPECT_EQ(trace(scene, {{0, 0, -10}, {0, 0, 1}}), kBlack);  // from behind
    // The same square with its image read from the other side: the front faces -z, so the
    // camera at the origin sees the back.
    scene.billboards = {make_billboard({2, 2, -5}, {2, -2, -5}, {-2, 2, -5}, kBlack, nullptr, true)};
    EXPECT_EQ(trace(scene, {{0, 0, 0}, {0, 0, -1}}), kBlack);
}

TEST(ReferenceMirror, MirrorSphereReflectsStraightBackAndIsBlackInside) {
    Scene scene = empty_scene();
    scene.spheres = {make_sphere({0, 0, -5}, 1, kBlack, true), make_sphere({0, 0, 5}, 1, kRed)};
    EXPECT_EQ(trace(scene, {{0, 0, 0}, {0, 0, -1}}), kRed);
    EXPECT_EQ(trace(scene, {{0, 0, -5}, {0, 1, 0}}), kBlack);  // inside: its back side
}

// Two mirrors face each other across z = 0: M1 at z = -5 (x in [-1, 4]) and M2 at z = +5
// (x in [-1, 6]). Next to M1, at x in [4, 6], is a green picture. A ray from the origin with
// slope 0.1 in x meets z = -5 / +5 at x = 0.5 (M1), 1.5 (M2), 2.5 (M1), 3.5 (M2) and then
// 4.5: the green picture, after exactly four reflections.
Scene facing_mirrors(int max_depth) {
    Scene scene = empty_scene();
    scene.max_depth = max_depth;
    const Billboard m1 = facing_plus_z(-1, 4, -2, 2, -5, kBlack, true);
    const Billboard m2 = make_billboard({6, 2, 5}, {6, -2, 5}, {-1, 2, 5}, kBlack, nullptr, true);  // faces -z
    const Billboard picture = facing_plus_z(4, 6, -2, 2, -5, kGreen);
    scene.billboards = {m1, m2, picture};
    return scene;
}

TEST(ReferenceMirror, FacingMirrorsAllowMaxDepthReflections) {
    const Ray ray = ray_towards({0, 0, 0}, {0.5, 0, -5});
    EXPECT_EQ(trace(facing_mirrors(4), ray), kGreen);
    EXPECT_EQ(trace(facing_mirrors(10), ray), kGreen);
    EXPECT_EQ(trace(facing_mirrors(3), ray), kSky);  // would need a fourth reflection
    EXPECT_EQ(trace(facing_mirrors(0), ray), kSky);  // no reflection at all
    // Straight down the axis the ray bounces forever: always the background.
    EXPECT_EQ(trace(facing_mirrors(7), {{0, 0, 0}, {0, 0, -1}}), kSky);
}

// ---------------------------------------------------------------------------------------
// Decision margin

TEST(ReferenceMargin, SmallAtASilhouetteLargeAtTheCentre) {
    Scene scene = empty_scene();
    scene.spheres = {make_sphere({0, 0, -10}, 2, kRed)};
    const auto margin_at = [&](double x) { return decision_margin(scene, {{x, 0, 0}, {0, 0, -1}}); };
    EXPECT_NEAR(margin_at(0), 1, kTight);  // |0 - r| / r
    EXPECT_NEAR(margin_at(1), 0.5, kTight);
    EXPECT_LT(margin_at(2), 1e-12);  // the silhouette itself
    EXPECT_NEAR(margin_at(2 + 2e-6), 1e-6, 1e-12);
    EXPECT_NEAR(margin_at(2 - 2e-6), 1e-6, 1e-12);
    EXPECT_GT(margin_at(2.5), 0.2);
}

TEST(ReferenceMargin, InfiniteWithNothingNear) {
    Scene scene = empty_scene();
    EXPECT_EQ(decision_margin(scene, {{0, 0, 0}, {0, 0, -1}}), kInfinity);
    scene.spheres = {make_sphere({0, 0, 10}, 2, kRed)};  // behind the origin
    scene.billboards = {facing_plus_z(-1, 1, -1, 1, 5, kRed)};
    EXPECT_EQ(decision_margin(scene, {{0, 0, 0}, {0, 0, -1}}), kInfinity);
}

TEST(ReferenceMargin, BillboardEdgesAndTexelEdges) {
    Scene scene = empty_scene();
    scene.billboards = {facing_plus_z(-1, 1, -1, 1, -5, kRed)};  // 2 x 2: x = -1 + 2a
    const auto margin_at = [&](double x, double y) {
        return decision_margin(scene, ray_towards({0, 0, 0}, {x, y, -5}));
    };
    EXPECT_NEAR(margin_at(0, 0), 0.5, 1e-12);
    EXPECT_NEAR(margin_at(-1 + 2e-6, 0), 1e-6, 1e-10);              // just inside the left edge
    EXPECT_NEAR(margin_at(-1 - 2e-6, 0), 1e-6, 1e-10);              // just outside it
    EXPECT_NEAR(margin_at(1.2, 1.2), std::hypot(0.1, 0.1), 1e-10);  // off a corner

    scene.billboards[0].image = make_image(4, 4, numbered_texel);  // texel lines at a = k/4
    EXPECT_LT(margin_at(0, 0), 1e-12);                             // a = 0.5: between two texels
    EXPECT_NEAR(margin_at(-0.25, -0.25), 0.125, 1e-12);            // a texel centre
    EXPECT_NEAR(margin_at(-0.5 + 2e-7, -0.25), 1e-7, 1e-10);
}

TEST(ReferenceMargin, NearlyEqualDepths) {
    Scene scene = empty_scene();
    scene.billboards = {facing_plus_z(-1, 1, -1, 1, -5, kRed), facing_plus_z(-1, 1, -1, 1, -5.00001, kGreen)};
    EXPECT_NEAR(decision_margin(scene, {{0, 0, 0}, {0, 0, -1}}), 0.00001 / 5, 1e-12);
}

TEST(ReferenceMargin, CountsTheShadowRayOfALitPixel) {
    // The shadow ray from P = (0,0,1) runs up the z axis, grazing an occluder of radius 1
    // centred 1 away from it.
    LitSetup setup = lit_sphere(0);
    setup.scene.spheres.push_back(make_sphere({1, 0, 11}, 1, kRed));
    EXPECT_LT(decision_margin(setup.scene, setup.centre_ray), 1e-12);
    setup.scene.only_ambient = true;  // no shadow ray, no shadow edge
    EXPECT_GT(decision_margin(setup.scene, setup.centre_ray), 0.5);
}

TEST(ReferenceMargin, CountsReflectedRays) {
    // The mirror sends the ray back up the z axis, grazing a sphere centred 1 off it.
    Scene scene = empty_scene();
    scene.billboards = {facing_plus_z(-2, 2, -2, 2, -5, kBlack, true)};
    scene.spheres = {make_sphere({1, 0, 5}, 1, kRed)};
    EXPECT_LT(decision_margin(scene, {{0, 0, 0}, {0, 0, -1}}), 1e-12);
    scene.billboards[0].is_mirror = false;
    EXPECT_NEAR(decision_margin(scene, {{0, 0, 0}, {0, 0, -1}}), 0.5, 1e-12);
}

// ---------------------------------------------------------------------------------------
// Bytes and frames

TEST(ReferenceToByte, ClampsAndRoundsHalfUp) {
    EXPECT_EQ(to_byte(0), 0);
    EXPECT_EQ(to_byte(1), 255);
    EXPECT_EQ(to_byte(-1), 0);
    EXPECT_EQ(to_byte(2), 255);
    EXPECT_EQ(to_byte(kInfinity), 255);
    EXPECT_EQ(to_byte(-kInfinity), 0);
    EXPECT_EQ(to_byte(std::nan("")), 0);
    EXPECT_EQ(to_byte((0.5 - 1e-9) / 255), 0);
    EXPECT_EQ(to_byte(0.5 / 255), 1);  // exactly half: rounds up
    EXPECT_EQ(to_byte((0.5 + 1e-9) / 255), 1);
    EXPECT_EQ(to_byte((254.5 - 1e-9) / 255), 254);
    EXPECT_EQ(to_byte(254.5 / 255), 255);
}

TEST(ReferenceToByte, TexelBytesSurviveTheRoundTrip) {
    for (int byte = 0; byte <= 255; ++byte) EXPECT_EQ(to_byte(byte / 255.0), byte);
}

TEST(ReferenceRender, SizeAlphaAndRowOrder) {
    Scene scene = empty_scene();
    scene.spheres = {make_sphere({0, 3, -10}, 1, kRed)};  // above the view axis
    const int width = 9, height = 15;
    const CameraFrame camera = make_camera({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 60, width, height);
    const Image image = render(scene, camera);
    ASSERT_EQ(image.width, width);
    ASSERT_EQ(image.height, height);
    ASSERT_EQ(image.rgba.size(), static_cast<std::size_t>(width * height * 4));
    int red_rows_top = 0, red_rows_bottom = 0;
    for (int row = 0; row < height; ++row) {
        for (int col = 0; col < width; ++col) {
            const Rgba p = pixel(image, col, row);
            EXPECT_EQ(p[3], 255);
            const Color expected = trace(scene, primary_ray(camera, col, row));
            EXPECT_EQ(p[0], to_byte(expected.x));
            EXPECT_EQ(p[1], to_byte(expected.y));
            EXPECT_EQ(p[2], to_byte(expected.z));
            if (p == Rgba{255, 0, 0, 255}) (row < height / 2 ? red_rows_top : red_rows_bottom)++;
        }
    }
    EXPECT_GT(red_rows_top, 0);
    EXPECT_EQ(red_rows_bottom, 0);
}

}  // namespace
}  // namespace clr::reference
