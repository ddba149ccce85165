// The numeric ranges of docs/scene-format.md ("Numeric ranges"): values just inside each limit
// load, values just outside are refused at their own location with the range in the message,
// and directions of any finite non-zero length load as the same direction.
#include <gtest/gtest.h>

#include <cfloat>
#include <string>
#include <vector>

#include "support/scene_json.h"

namespace clr {
namespace {

using namespace testing::scene_json;

const std::string kPositionRange = "every coordinate must be from -1e15 to 1e15";
const std::string kLengthRange = "lengths must be from 1e-15 to 1e16";

Json billboard_with(const Json& upper_left, const Json& lower_left, const Json& upper_right) {
    Json billboard = flat_billboard();
    billboard["UpperLeft"] = upper_left;
    billboard["LowerLeft"] = lower_left;
    billboard["UpperRight"] = upper_right;
    return billboard;
}

Json with_billboard(const Json& billboard) {
    Json json = minimal_scene();
    json["billboards"] = {billboard};
    return json;
}

Json with_sphere(const Json& center, const Json& radius) {
    Json json = minimal_scene();
    Json object = sphere(radius);
    object["center"] = center;
    json["spheres"] = {object};
    return json;
}

Json with_impostor(const Json& center, const Json& width, const Json& height) {
    Json json = minimal_scene();
    json["clrender"]["impostors"] = {{{"center", center}, {"width", width}, {"height", height}, {"ambient", {1, 0, 0}}}};
    return json;
}

TEST(ValueRanges, PositionsAtTheLimitLoad) {
    Json json = with_sphere({1e15, -1e15, 1e15}, 1);
    json["eye"] = {-1e15, 1e15, -1e15};
    json["lookat"] = {1e15, 1e15, 1e15};
    json["SunLocation"] = {-1e15, -1e15, -1e15};
    json["billboards"] = {billboard_with({-1e15, 1e15, 0}, {-1e15, -1e15, 0}, {1e15, 1e15, 0})};
    const Scene scene = parse(json);
    EXPECT_EQ(scene.spheres[0].center, Vec3(1e15, -1e15, 1e15));
    EXPECT_EQ(scene.sun_location, Vec3(-1e15, -1e15, -1e15));
    EXPECT_EQ(scene.billboards[0].upper_right, Vec3(1e15, 1e15, 0));
    // The longest edge two valid corners can make, 2 sqrt(3) 1e15, is inside the length range.
    EXPECT_NO_THROW(parse(with_billboard(billboard_with({-1e15, -1e15, -1e15}, {1e15, -1e15, 1e15}, {1e15, 1e15, 1e15}))));
    EXPECT_NO_THROW(parse(with_impostor({1e15, 1e15, -1e15}, 1, 1)));
}

TEST(ValueRanges, EachPositionJustOutsideIsRefusedAtItsCoordinate) {
    const double outside = 1.000001e15;
    Json eye = minimal_scene();
    eye["eye"] = {0, 0, outside};
    EXPECT_TRUE(FailsAt(eye, "/eye/2", "eye[2] is 1.000001e15, outside the range clrender renders exactly enough: " + kPositionRange));
    Json lookat = minimal_scene();
    lookat["lookat"] = {-outside, 0, 0};
    EXPECT_TRUE(FailsAt(lookat, "/lookat/0", "is -1.000001e15, outside the range"));
    Json path = minimal_scene();
    path.erase("eye");
    path["eyeLocations"] = {{0, 0, 5}, {0, outside, 5}};
    EXPECT_TRUE(FailsAt(path, "/eyeLocations/1/1", kPositionRange));
    Json lookats = minimal_scene();
    lookats.erase("eye");
    lookats.erase("lookat");
    lookats["eyeLocations"] = {{0, 0, 5}, {0, 1, 5}};
    lookats["lookatLocations"] = {{0, 0, 0}, {0, 0, -outside}};
    EXPECT_TRUE(FailsAt(lookats, "/lookatLocations/1/2", kPositionRange));
    Json sun = minimal_scene();
    sun["SunLocation"] = {0, 1e38, 0};
    EXPECT_TRUE(FailsAt(sun, "/SunLocation/1", "SunLocation[1] is 1e38, outside the range"));
    EXPECT_TRUE(FailsAt(with_sphere({0, 0, 1e300}, 1), "/spheres/0/center/2", "center[2] is 1e300"));
    EXPECT_TRUE(FailsAt(with_billboard(billboard_with({-1, 1, 0}, {-1, -1, 0}, {outside, 1, 0})), "/billboards/0/UpperRight/0",
                        kPositionRange));
    EXPECT_TRUE(FailsAt(with_impostor({0, -outside, 0}, 1, 1), "/clrender/impostors/0/center/1", kPositionRange));
}

TEST(ValueRanges, LengthsAtTheLimitsLoad) {
    EXPECT_EQ(parse(with_sphere({0, 0, 0}, 1e-15)).spheres[0].radius, 1e-15);
    EXPECT_EQ(parse(with_sphere({0, 0, 0}, 1e16)).spheres[0].radius, 1e16);
    const Scene impostor = parse(with_impostor({0, 0, 0}, 1e-15, 1e16));
    EXPECT_EQ(impostor.impostors[0].width, 1e-15);
    EXPECT_EQ(impostor.impostors[0].height, 1e16);
    // Edges of exactly 1e-15 (the corner sine is 1: a square).
    EXPECT_NO_THROW(parse(with_billboard(billboard_with({0, 0, 0}, {0, -1e-15, 0}, {1e-15, 0, 0}))));
}

TEST(ValueRanges, LengthsJustOutsideAreRefusedWithTheRange) {
    EXPECT_TRUE(FailsAt(with_sphere({0, 0, 0}, 9.99e-16), "/spheres/0/radius",
                        "radius 9.99e-16 is outside the range clrender renders exactly enough: " + kLengthRange));
    EXPECT_TRUE(FailsAt(with_sphere({0, 0, 0}, 1.001e16), "/spheres/0/radius", "radius 1.001e16 is outside the range"));
    EXPECT_TRUE(FailsAt(with_sphere({0, 0, 0}, 1e300), "/spheres/0/radius", "radius 1e300 is outside the range"));
    EXPECT_TRUE(FailsAt(with_sphere({0, 0, 0}, 1e-38), "/spheres/0/radius", "radius 1e-38 is outside the range"));
    EXPECT_TRUE(FailsAt(with_impostor({0, 0, 0}, 9.99e-16, 1), "/clrender/impostors/0/width", "width 9.99e-16 is outside"));
    EXPECT_TRUE(FailsAt(with_impostor({0, 0, 0}, 1, 1.001e16), "/clrender/impostors/0/height", kLengthRange));
    // Zero and negative keep their own message.
    EXPECT_TRUE(FailsAt(with_sphere({0, 0, 0}, 0), "/spheres/0/radius", "radius must be > 0 (got 0)"));
}

// A 1e-200 edge is far below the smallest length: the message says so, not "collinear".
TEST(ValueRanges, TinyBillboardEdgeIsReportedAsTooShort) {
    EXPECT_TRUE(FailsAt(with_billboard(billboard_with({0, 0, 0}, {0, -1, 0}, {1e-200, 0, 0})), "/billboards/0",
                        "billboard edge from UpperLeft to UpperRight is 1e-200 long, outside the range clrender renders "
                        "exactly enough: " + kLengthRange));
    EXPECT_TRUE(FailsAt(with_billboard(billboard_with({0, 0, 0}, {0, -9.99e-16, 0}, {1, 0, 0})), "/billboards/0",
                        "billboard edge from UpperLeft to LowerLeft is 9.99e-16 long"));
}

// Collinearity is the sine of the angle between unit edges: the same verdict at any scale.
TEST(ValueRanges, CollinearityDoesNotDependOnTheBillboardsSize) {
    for (double scale : {1e-15, 1.0, 1e14}) {
        const Json square = billboard_with({0, 0, 0}, {0, -scale, 0}, {scale, 0, 0});
        EXPECT_NO_THROW(parse(with_billboard(square))) << scale;
        const Json sliver = billboard_with({0, 0, 0}, {scale, scale * 1e-13, 0}, {scale, 0, 0});
        EXPECT_TRUE(FailsAt(with_billboard(sliver), "/billboards/0", "collinear")) << scale;
        const Json thin = billboard_with({0, 0, 0}, {scale, scale * 1e-11, 0}, {scale, 0, 0});
        EXPECT_NO_THROW(parse(with_billboard(thin))) << scale;
    }
}

TEST(ValueRanges, DirectionsOfAnyFiniteLengthLoad) {
    for (double scale : {1e-300, 1e300}) {
        Json json = minimal_scene();
        json["up"] = {0, scale, 0};
        EXPECT_EQ(parse(json).up, Vec3(0, scale, 0)) << scale;
        json["up"] = {0, 0, -scale};  // along the view: still refused, at any length
        EXPECT_TRUE(FailsAt(json, "/up", "is parallel to the view direction")) << scale;
    }
    Json huge_up = minimal_scene();
    huge_up["up"] = {1.5e308, 1.5e308, -1.5e308};
    EXPECT_NO_THROW(parse(huge_up));
    // The eye as close to the look-at point as two doubles can be.
    Json close = minimal_scene();
    close["eye"] = {0, 0, 1e-300};
    close["lookat"] = {0, 0, 0};
    EXPECT_NO_THROW(parse(close));
    Json views = minimal_scene();
    views["clrender"]["impostors"] = {{{"center", {0, 0, 0}}, {"width", 1}, {"height", 1},
                                        {"views", {{{"filename", "a.png"}, {"direction", {1e-300, 0, 0}}}}}}};
    LoadOptions placeholders;
    placeholders.placeholder_images = true;
    const Scene scene = parse(views, placeholders);
    EXPECT_EQ(scene.impostors[0].views[0].direction, Vec3(1, 0, 0));
}

}  // namespace
}  // namespace clr
