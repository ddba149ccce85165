// Checks of the reference's impostors (docs/scene-format.md, Impostors) against geometry
// worked out by hand or against properties any correct placement has, not against the
// reference's own formulas.
#include "reference/impostors.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "reference/geometry.h"
#include "support/scene_builder.h"

namespace clr::reference {
namespace {

using testing::make_billboard;
using testing::make_image;
using testing::make_scene;

constexpr double kTight = 1e-12;  // double-precision agreement for simple closed forms
constexpr double kSqrtHalf = 0.70710678118654752440;

void expect_vec_near(const Vec3& actual, const Vec3& expected, double tolerance) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}

using Rgba = std::array<std::uint8_t, 4>;

const Rgba kRedTexel{255, 0, 0, 255};
const Rgba kGreenTexel{0, 255, 0, 255};
const Rgba kBlueTexel{0, 0, 255, 255};
const Rgba kWhiteTexel{255, 255, 255, 255};
const Rgba kHoleTexel{0, 0, 0, 0};
const Rgba kSkyPixel{51, 102, 153, 255};     // kSky as bytes
const Rgba kYellowPixel{255, 255, 0, 255};  // kYellow as bytes
const Color kSky{0.2, 0.4, 0.6};
const Color kYellow{1, 1, 0};
const Color kOrange{1, 0.5, 0};

// A 2 x 1 image: `left` in column 0, `right` in column 1.
std::shared_ptr<Image> two_texels(const Rgba& left, const Rgba& right) {
    return make_image(2, 1, [&](int col, int) { return col == 0 ? left : right; });
}

// A 1 x 1 image, to tell views apart by identity.
std::shared_ptr<Image> one_texel(const Rgba& color) {
    return make_image(1, 1, [&](int, int) { return color; });
}

ImpostorView view(const Vec3& direction, std::shared_ptr<const Image> image = nullptr) {
    return {normalize(direction), image ? std::move(image) : one_texel(kWhiteTexel)};
}

Impostor make_impostor(const Vec3& center, double width, double height, Facing facing,
                       std::vector<ImpostorView> views = {}, const Color& ambient = kOrange) {
    Impostor impostor;
    impostor.center = center;
    impostor.width = width;
    impostor.height = height;
    impostor.facing = facing;
    impostor.views = std::move(views);
    impostor.ambient = ambient;
    return impostor;
}

CameraFrame camera_at(const Vec3& eye, const Vec3& lookat, const Vec3& up = {0, 1, 0}) {
    return make_camera(eye, lookat, up, 60, 40, 30);
}

// The four views of the documentation's "pine": from +z, +x, -z and -x.
std::vector<ImpostorView> pine_views() {
    return {view({0, 0, 1}), view({1, 0, 0}), view({0, 0, -1}), view({-1, 0, 0})};
}

struct Placement {
    Vec3 eye, lookat, up, center;
};

// Eyes all around, tilted and non-unit up vectors, impostors off the view axis.
const Placement kPlacements[] = {
    {{0, 0, 10}, {0, 0, 0}, {0, 1, 0}, {0, 0, 0}},
    {{7, 3, -2}, {0, 0, 0}, {0, 1, 0}, {1, -1, 2}},
    {{-4, 9, 5}, {1, 1, 1}, {0, 3, 0}, {2, 0, -3}},
    {{3, 2, 1}, {-5, 0, 0}, {0.3, 2, -0.1}, {-6, 1, 4}},
    {{0, -8, 1}, {0, 0, 0}, {0, 0, 5}, {1, 2, 3}},
    {{100, 40, -250}, {0, 0, 0}, {1, 1, 0}, {-3, 7, 11}},
};

// The properties every placed rectangle has: centre, edge lengths, right angles.
void expect_rectangle(const Billboard& billboard, const Impostor& impostor) {
    const Vec3 top = billboard.upper_right - billboard.upper_left;
    const Vec3 left = billboard.upper_left - billboard.lower_left;
    expect_vec_near((billboard.upper_right + billboard.lower_left) / 2.0, impostor.center, 1e-9);
    EXPECT_NEAR(length(top), impostor.width, 1e-9);
    EXPECT_NEAR(length(left), impostor.height, 1e-9);
    EXPECT_NEAR(dot(top, left), 0, 1e-9);
}

// ---------------------------------------------------------------------------------------
// Upright placement

TEST(ReferenceImpostorUpright, FacesTheEyeWithItsVerticalEdgesAlongUp) {
    for (const Placement& p : kPlacements) {
        SCOPED_TRACE(&p - kPlacements);
        const Impostor impostor = make_impostor(p.center, 3, 5, Facing::Upright);
        const Billboard billboard = place_impostor(impostor, camera_at(p.eye, p.lookat, p.up), p.up);
        const Vec3 a = normalize(p.up);
        const Vec3 to_eye = p.eye - p.center;
        const Vec3 n = detail::billboard_front_normal(billboard);
        const Vec3 top = billboard.upper_right - billboard.upper_left;
        const Vec3 left = billboard.upper_left - billboard.lower_left;

        expect_rectangle(billboard, impostor);
        expect_vec_near(left, a * impostor.height, 1e-9);  // UL - LL is up, of length height
        EXPECT_NEAR(dot(top, a), 0, 1e-9);
        EXPECT_NEAR(dot(top, n), 0, 1e-9);
        // n is perpendicular to up, lies in the plane of up and D, and points to the eye's side:
        // that is the unit horizontal part of D and nothing else.
        EXPECT_NEAR(dot(n, a), 0, 1e-12);
        EXPECT_NEAR(dot(n, normalize(cross(a, to_eye))), 0, 1e-12);
        EXPECT_GT(dot(n, to_eye), 0);
    }
}

TEST(ReferenceImpostorUpright, HandWorkedEyeOnPlusZ) {
    const Impostor impostor = make_impostor({0, 0, 0}, 2, 4, Facing::Upright);
    const Billboard billboard = place_impostor(impostor, camera_at({0, 0, 5}, {0, 0, 0}), {0, 1, 0});
    expect_vec_near(billboard.upper_left, {-1, 2, 0}, kTight);
    expect_vec_near(billboard.upper_right, {1, 2, 0}, kTight);
    expect_vec_near(billboard.lower_left, {-1, -2, 0}, kTight);
}

TEST(ReferenceImpostorUpright, HandWorkedEyeAboveOnPlusXIgnoresTheHeight) {
    // D = (3, 7, 0): its horizontal part is +x, so the picture stands in the plane x = 2 with
    // its right (the camera's right, -z) along A x n = (0,1,0) x (1,0,0) = (0,0,-1).
    const Impostor impostor = make_impostor({2, 1, 0}, 2, 4, Facing::Upright);
    const Billboard billboard = place_impostor(impostor, camera_at({5, 8, 0}, {2, 1, 0}), {0, 2, 0});
    expect_vec_near(billboard.upper_left, {2, 3, 1}, kTight);
    expect_vec_near(billboard.upper_right, {2, 3, -1}, kTight);
    expect_vec_near(billboard.lower_left, {2, -1, 1}, kTight);
}

TEST(ReferenceImpostorUpright, EyeStraightAboveFallsBackToTheCameraBackward) {
    // Looking down from (0,10,0) towards (0,0,-1): w = unit(0,10,1), whose horizontal part
    // is +z, so the picture faces +z as if seen from the front. The same holds from below,
    // and with a horizontal offset of 1e-12, within the 1e-9 |D| that counts as none.
    const Impostor impostor = make_impostor({0, 0, 0}, 2, 4, Facing::Upright);
    for (const Vec3& eye : {Vec3(0, 10, 0), Vec3(1e-12, 10, 0), Vec3(0, -10, -1e-12)}) {
        SCOPED_TRACE(eye.y);
        const CameraFrame camera = camera_at(eye, {0, 0, -1});
        const Vec3 w_horizontal = normalize(Vec3(camera.w.x, 0, camera.w.z));
        const Billboard billboard = place_impostor(impostor, camera, {0, 1, 0});
        expect_vec_near(detail::billboard_front_normal(billboard), w_horizontal, kTight);
        expect_rectangle(billboard, impostor);
        expect_vec_near(billboard.upper_left - billboard.lower_left, {0, 4, 0}, kTight);
    }
    const Billboard above = place_impostor(impostor, camera_at({0, 10, 0}, {0, 0, -1}), {0, 1, 0});
    expect_vec_near(above.upper_left, {-1, 2, 0}, kTight);
    expect_vec_near(above.upper_right, {1, 2, 0}, kTight);
    expect_vec_near(above.lower_left, {-1, -2, 0}, kTight);
}

TEST(ReferenceImpostorUpright, SlightlyOffTheVerticalStillTurnsToTheEye) {
    // A horizontal offset well above 1e-9 |D| is a real direction, not the fallback.
    const Impostor impostor = make_impostor({0, 0, 0}, 2, 4, Facing::Upright);
    const Billboard billboard = place_impostor(impostor, camera_at({1e-6, 10, 0}, {0, 0, -1}), {0, 1, 0});
    expect_vec_near(detail::billboard_front_normal(billboard), {1, 0, 0}, kTight);
}

TEST(ReferenceImpostorUpright, EyeAtTheCentreFallsBackToTheCameraBackward) {
    const Impostor impostor = make_impostor({1, 2, 3}, 2, 4, Facing::Upright);
    const Billboard billboard = place_impostor(impostor, camera_at({1, 2, 3}, {4, 2, 7}), {0, 1, 0});
    expect_vec_near(detail::billboard_front_normal(billboard), {-0.6, 0, -0.8}, kTight);
    expect_rectangle(billboard, impostor);
}

// ---------------------------------------------------------------------------------------
// Free placement

TEST(ReferenceImpostorFree, FacesTheEyeWithItsTopTowardsUp) {
    for (const Placement& p : kPlacements) {
        SCOPED_TRACE(&p - kPlacements);
        const Impostor impostor = make_impostor(p.center, 3, 5, Facing::Free);
        const Billboard billboard = place_impostor(impostor, camera_at(p.eye, p.lookat, p.up), p.up);
        const Vec3 a = normalize(p.up);
        const Vec3 n = detail::billboard_front_normal(billboard);
        const Vec3 left = billboard.upper_left - billboard.lower_left;

        expect_rectangle(billboard, impostor);
        expect_vec_near(n, normalize(p.eye - p.center), 1e-12);
        EXPECT_NEAR(dot(left, n), 0, 1e-9);
        // The top edge leans towards up as far as facing the eye allows: UL - LL lies in the
        // plane of up and n, on up's side.
        EXPECT_NEAR(dot(normalize(left), normalize(cross(a, n))), 0, 1e-12);
        EXPECT_GT(dot(left, a), 0);
    }
}

TEST(ReferenceImpostorFree, HandWorkedEyeOnPlusZ) {
    const Impostor impostor = make_impostor({0, 0, 0}, 2, 4, Facing::Free);
    const Billboard billboard = place_impostor(impostor, camera_at({0, 0, 5}, {0, 0, 0}), {0, 1, 0});
    expect_vec_near(billboard.upper_left, {-1, 2, 0}, kTight);
    expect_vec_near(billboard.upper_right, {1, 2, 0}, kTight);
    expect_vec_near(billboard.lower_left, {-1, -2, 0}, kTight);
}

TEST(ReferenceImpostorFree, HandWorkedEyeAt45DegreesTiltsBack) {
    // n = (0,1,1)/sqrt2, r = +x, s = n x r = (0,1,-1)/sqrt2; a height of 2 sqrt2 makes the half
    // height along s exactly (0,1,-1).
    const Impostor impostor = make_impostor({0, 0, 0}, 2, 4 * kSqrtHalf, Facing::Free);
    const Billboard billboard = place_impostor(impostor, camera_at({0, 5, 5}, {0, 0, 0}), {0, 1, 0});
    expect_vec_near(billboard.upper_left, {-1, 1, -1}, kTight);
    expect_vec_near(billboard.upper_right, {1, 1, -1}, kTight);
    expect_vec_near(billboard.lower_left, {-1, -1, 1}, kTight);
}

TEST(ReferenceImpostorFree, EyeStraightAboveTakesTheCameraRight) {
    // From (0,10,0) looking towards (0,0,-1) the camera's right is +x and its screen up leans
    // to -z, so the picture lies flat, facing up, with its top row towards -z.
    const Impostor impostor = make_impostor({0, 0, 0}, 2, 4, Facing::Free);
    const Billboard billboard = place_impostor(impostor, camera_at({0, 10, 0}, {0, 0, -1}), {0, 1, 0});
    expect_vec_near(billboard.upper_left, {-1, 0, -2}, kTight);
    expect_vec_near(billboard.upper_right, {1, 0, -2}, kTight);
    expect_vec_near(billboard.lower_left, {-1, 0, 2}, kTight);
}

TEST(ReferenceImpostorFree, EyeAtTheCentreFacesTheCameraBackward) {
    const Impostor impostor = make_impostor({1, 2, 3}, 2, 4, Facing::Free);
    const CameraFrame camera = camera_at({1, 2, 3}, {4, 2, 7});
    const Billboard billboard = place_impostor(impostor, camera, {0, 1, 0});
    expect_vec_near(detail::billboard_front_normal(billboard), {-0.6, 0, -0.8}, kTight);
    expect_vec_near(billboard.upper_right - billboard.upper_left, camera.u * 2.0, kTight);
    expect_rectangle(billboard, impostor);
}

// ---------------------------------------------------------------------------------------
// What the billboard shows

TEST(ReferenceImpostor, WithoutViewsShowsItsFlatColour) {
    const Impostor impostor = make_impostor({0, 0, 0}, 1, 1, Facing::Free, {}, kOrange);
    const Billboard billboard = place_impostor(impostor, camera_at({0, 0, 5}, {0, 0, 0}), {0, 1, 0});
    EXPECT_EQ(billboard.image, nullptr);
    EXPECT_TRUE(billboard.has_ambient);
    EXPECT_EQ(billboard.ambient, kOrange);
    EXPECT_FALSE(billboard.is_mirror);
}

TEST(ReferenceImpostor, ShowsTheChosenViewsImageAndIsNeverAMirror) {
    const Impostor impostor = make_impostor({0, 0, 0}, 1, 1, Facing::Upright, pine_views());
    const Billboard billboard = place_impostor(impostor, camera_at({-9, 0, 1}, {0, 0, 0}), {0, 1, 0});
    EXPECT_EQ(billboard.image, impostor.views[3].image);  // from -x
    EXPECT_FALSE(billboard.is_mirror);
}

// ---------------------------------------------------------------------------------------
// Which view shows

TEST(ReferenceImpostorView, NoViewsIsMinusOne) {
    const Impostor impostor = make_impostor({0, 0, 0}, 1, 1, Facing::Upright);
    EXPECT_EQ(chosen_view(impostor, camera_at({0, 0, 5}, {0, 0, 0})), -1);
}

TEST(ReferenceImpostorView, SingleViewShowsFromEveryDirection) {
    const Impostor impostor = make_impostor({0, 0, 0}, 1, 1, Facing::Upright, {view({0, 0, 1})});
    for (const Vec3& eye : {Vec3(0, 0, 5), Vec3(0, 0, -5), Vec3(3, 4, 0), Vec3(0, 0, 0)}) {
        EXPECT_EQ(chosen_view(impostor, camera_at(eye, {0, 1, -9})), 0);
    }
}

TEST(ReferenceImpostorView, EachQuarterAroundShowsItsView) {
    const Impostor impostor = make_impostor({1, 0, -2}, 1, 1, Facing::Upright, pine_views());
    EXPECT_EQ(chosen_view(impostor, camera_at({1.5, 3, 8}, {0, 0, 0})), 0);   // mostly +z
    EXPECT_EQ(chosen_view(impostor, camera_at({20, -3, 1}, {0, 0, 0})), 1);   // mostly +x
    EXPECT_EQ(chosen_view(impostor, camera_at({-2, 0, -30}, {0, 0, 0})), 2);  // mostly -z
    EXPECT_EQ(chosen_view(impostor, camera_at({-7, 50, -1}, {0, 0, 0})), 3);  // mostly -x, from high up
}

TEST(ReferenceImpostorView, SwitchesExactlyWhereTheScoresCross) {
    // The eye slides along z = 10 from x = 0 to x = 20 past the centre at the origin. View
    // +z scores 10/|D|, view +x scores x/|D|: +z shows up to x = 10, where the scores are
    // exactly equal (the first wins), and +x from there on.
    const Impostor impostor = make_impostor({0, 0, 0}, 1, 1, Facing::Upright, pine_views());
    for (int step = 0; step <= 40; ++step) {
        const double x = step * 0.5;
        SCOPED_TRACE(x);
        EXPECT_EQ(chosen_view(impostor, camera_at({x, 0, 10}, {x, 0, 0})), x <= 10 ? 0 : 1);
    }
    // Just either side of the crossing.
    EXPECT_EQ(chosen_view(impostor, camera_at({10 - 1e-9, 0, 10}, {0, 0, 0})), 0);
    EXPECT_EQ(chosen_view(impostor, camera_at({10 + 1e-9, 0, 10}, {0, 0, 0})), 1);
}

TEST(ReferenceImpostorView, ExactTieGoesToTheFirstInTheList) {
    const auto plus_x = one_texel(kRedTexel);
    const auto minus_x = one_texel(kBlueTexel);
    const CameraFrame camera = camera_at({0, 0, 7}, {0, 0, 0});
    Impostor impostor =
        make_impostor({0, 0, 0}, 1, 1, Facing::Upright, {view({1, 0, 0}, plus_x), view({-1, 0, 0}, minus_x)});
    EXPECT_EQ(chosen_view(impostor, camera), 0);
    EXPECT_EQ(place_impostor(impostor, camera, {0, 1, 0}).image, plus_x);

    std::swap(impostor.views[0], impostor.views[1]);
    EXPECT_EQ(chosen_view(impostor, camera), 0);
    EXPECT_EQ(place_impostor(impostor, camera, {0, 1, 0}).image, minus_x);
}

TEST(ReferenceImpostorView, TieAtTheSwitchGoesToWhicheverComesFirst) {
    // At x = z the views +z and +x score the same; listing +x first makes it the one shown.
    const Impostor impostor =
        make_impostor({0, 0, 0}, 1, 1, Facing::Upright, {view({1, 0, 0}), view({0, 0, 1})});
    EXPECT_EQ(chosen_view(impostor, camera_at({10, 0, 10}, {0, 0, 0})), 0);
    EXPECT_EQ(chosen_view(impostor, camera_at({9.5, 0, 10}, {0, 0, 0})), 1);
}

TEST(ReferenceImpostorView, EyeAtTheCentreUsesTheCameraBackward) {
    const Impostor impostor =
        make_impostor({1, 2, 3}, 1, 1, Facing::Upright, {view({0, 0, 1}), view({0, 0, -1})});
    EXPECT_EQ(chosen_view(impostor, camera_at({1, 2, 3}, {1, 2, 2})), 0);  // w = +z
    EXPECT_EQ(chosen_view(impostor, camera_at({1, 2, 3}, {1, 2, 4})), 1);  // w = -z
}

// ---------------------------------------------------------------------------------------
// The placed scene

TEST(ReferenceImpostorScene, PlacedImpostorsFollowTheBillboardsInOrder) {
    Scene scene = make_scene({0, 0, 10}, {0, 0, 0}, {0, 2, 0}, 60, 40, 30);
    scene.spheres.push_back(testing::make_sphere({0, 0, -5}, 1, kYellow));
    scene.billboards.push_back(make_billboard({-1, 1, -3}, {-1, -1, -3}, {1, 1, -3}, kSky));
    scene.billboards.push_back(make_billboard({-2, 2, -4}, {-2, -2, -4}, {2, 2, -4}, kYellow));
    scene.impostors.push_back(make_impostor({3, 0, 0}, 1, 2, Facing::Upright, {}, kOrange));
    scene.impostors.push_back(make_impostor({-3, 1, 0}, 2, 1, Facing::Free, pine_views()));
    const CameraFrame camera = camera_at({0, 0, 10}, {0, 0, 0});

    const Scene placed = with_impostors_placed(scene, camera);
    EXPECT_TRUE(placed.impostors.empty());
    ASSERT_EQ(placed.spheres.size(), 1u);
    ASSERT_EQ(placed.billboards.size(), 4u);
    EXPECT_EQ(placed.billboards[0].upper_left, scene.billboards[0].upper_left);
    EXPECT_EQ(placed.billboards[1].upper_left, scene.billboards[1].upper_left);
    // Centres (UR + LL) / 2 tell the impostors apart.
    expect_vec_near((placed.billboards[2].upper_right + placed.billboards[2].lower_left) / 2.0, {3, 0, 0}, kTight);
    expect_vec_near((placed.billboards[3].upper_right + placed.billboards[3].lower_left) / 2.0, {-3, 1, 0}, kTight);
    EXPECT_EQ(placed.billboards[2].image, nullptr);
    EXPECT_EQ(placed.billboards[3].image, scene.impostors[1].views[0].image);
    EXPECT_FALSE(placed.billboards[2].is_mirror);
    EXPECT_FALSE(placed.billboards[3].is_mirror);
}

// ---------------------------------------------------------------------------------------
// Rendering

Rgba pixel(const Image& image, int col, int row) {
    return {image.at(col, row, 0), image.at(col, row, 1), image.at(col, row, 2), image.at(col, row, 3)};
}

// 40 x 30 pixels with a 60-degree field across: at distance 10 a pixel is 10 tan(30) / 20
// = 0.289 units wide. Column 15's centre lies 1.30 units left of the axis, column 25's 1.59
// right, column 5's 4.19 left; row 15's centre 0.14 below and row 2's 3.61 above.
constexpr int kWidth = 40;
constexpr int kHeight = 30;

Scene render_scene() {
    Scene scene = make_scene({0, 0, 10}, {0, 0, 0}, {0, 1, 0}, 60, kWidth, kHeight);
    scene.background = kSky;
    return scene;
}

Image render_from(const Scene& scene, const Vec3& eye) {
    return render(scene, make_camera(eye, {0, 0, 0}, scene.up, scene.fov_degrees, kWidth, kHeight));
}

TEST(ReferenceImpostorRender, ShowsTheViewForTheEyeFacingIt) {
    // A 4 x 2 upright impostor at the origin: from +z its picture is red | green, from +x
    // blue | white. Seen from +x a fixed billboard in the plane z = 0 would be edge-on; the
    // impostor turns, so both show their left texel left of the centre and the right one right.
    Scene scene = render_scene();
    scene.impostors.push_back(make_impostor({0, 0, 0}, 4, 2, Facing::Upright,
                                            {view({0, 0, 1}, two_texels(kRedTexel, kGreenTexel)),
                                             view({1, 0, 0}, two_texels(kBlueTexel, kWhiteTexel))}));

    const Image front = render_from(scene, {0, 0, 10});
    EXPECT_EQ(pixel(front, 15, 15), kRedTexel);
    EXPECT_EQ(pixel(front, 25, 15), kGreenTexel);
    EXPECT_EQ(pixel(front, 5, 15), kSkyPixel);  // beside it
    EXPECT_EQ(pixel(front, 20, 2), kSkyPixel);  // above it

    const Image side = render_from(scene, {10, 0, 0});
    EXPECT_EQ(pixel(side, 15, 15), kBlueTexel);
    EXPECT_EQ(pixel(side, 25, 15), kWhiteTexel);
    EXPECT_EQ(pixel(side, 5, 15), kSkyPixel);
    EXPECT_EQ(pixel(side, 20, 2), kSkyPixel);
}

TEST(ReferenceImpostorRender, WithoutViewsShowsTheFlatColourUnlit) {
    Scene scene = render_scene();
    scene.has_sun = true;
    scene.sun_location = Vec3(0, 0, -100);  // behind it: a picture is not lit, so no matter
    scene.impostors.push_back(make_impostor({0, 0, 0}, 4, 2, Facing::Free, {}, kYellow));
    const Image image = render_from(scene, {0, 0, 10});
    EXPECT_EQ(pixel(image, 15, 15), kYellowPixel);
    EXPECT_EQ(pixel(image, 25, 15), kYellowPixel);
    EXPECT_EQ(pixel(image, 5, 15), kSkyPixel);
}

TEST(ReferenceImpostorRender, TransparentTexelsShowWhatIsBehindWhateverTheOrder) {
    // Front: 4 x 2 at z = 2, its left texel a hole, its right one blue. Back: 8 x 4 yellow at
    // z = 0. At distance 8 column 15 sees x = -1.04 (the hole), column 25 x = +1.27 (blue);
    // column 8 passes the front's edge (x = -2.66 at distance 8) and meets the back at -3.32.
    const Impostor front = make_impostor({0, 0, 2}, 4, 2, Facing::Upright,
                                         {view({0, 0, 1}, two_texels(kHoleTexel, kBlueTexel))});
    const Impostor back = make_impostor({0, 0, 0}, 8, 4, Facing::Upright, {}, kYellow);
    for (bool front_first : {true, false}) {
        SCOPED_TRACE(front_first ? "front listed first" : "back listed first");
        Scene scene = render_scene();
        scene.impostors = front_first ? std::vector<Impostor>{front, back} : std::vector<Impostor>{back, front};
        const Image image = render_from(scene, {0, 0, 10});
        EXPECT_EQ(pixel(image, 15, 15), kYellowPixel);
        EXPECT_EQ(pixel(image, 25, 15), kBlueTexel);
        EXPECT_EQ(pixel(image, 8, 15), kYellowPixel);
        EXPECT_EQ(pixel(image, 2, 15), kSkyPixel);
    }
}

}  // namespace
}  // namespace clr::reference
