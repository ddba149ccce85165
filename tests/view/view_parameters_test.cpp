// A viewer request's camera parameters: their form (view_parameters.h) and their values,
// checked by the scene loader as -D and --size would be (view_camera.h).
#include <gtest/gtest.h>

#include <cmath>

#include "scene/camera_path.h"
#include "scene/scene_loader.h"
#include "view/camera_keys.h"
#include "view/view_camera.h"
#include "view/view_parameters.h"

namespace clr {
namespace {

const char* kPathScene = R"({
  "eyeLocations": [[0, 0, 10], [10, 0, 0]], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 50,
  "width": 64, "height": 48, "clrender": {"spp": 2, "frames_per_segment": 4},
  "spheres": [{"center": [0, 0, 0], "radius": 1, "ambient": [1, 0, 0]}]
})";

Scene path_scene() { return parse_scene(kPathScene, "path.json"); }

// The parameter a query's error names, or "" when it is accepted.
std::string refused_parameter(const std::string& name, const std::string& value) {
    try {
        resolve_view_camera(path_scene(), parse_view_query({{name, value}}));
        return "";
    } catch (const ParameterError& error) {
        EXPECT_FALSE(std::string(error.what()).empty());
        return error.parameter();
    }
}

TEST(ViewParameters, MissingValuesAreTheScenes) {
    const Scene scene = path_scene();
    const ViewCamera view = resolve_view_camera(scene, parse_view_query({}));
    EXPECT_EQ(view.key.eye, (Vec3{0, 0, 10}));
    EXPECT_EQ(view.key.lookat, (Vec3{0, 0, 0}));
    EXPECT_EQ(view.up, (Vec3{0, 1, 0}));
    EXPECT_EQ(view.fov_degrees, 50);
    EXPECT_EQ(view.width, 64);
    EXPECT_EQ(view.height, 48);
    EXPECT_EQ(view.sampling.samples_per_pixel, 2);
    EXPECT_EQ(view.frame, 0);
}

TEST(ViewParameters, GivenValuesReplaceTheScenes) {
    const ViewCamera view = resolve_view_camera(
        path_scene(), parse_view_query({{"eye", "1,2.5,-3e1"}, {"lookat", "0,0,1"}, {"up", "0,0,1e-3"}, {"fov", "30.5"},
                                        {"size", "20x10"}, {"spp", "4"}, {"token", "ignored"}, {"t", "17"}}));
    EXPECT_EQ(view.key.eye, (Vec3{1, 2.5, -30}));
    EXPECT_EQ(view.key.lookat, (Vec3{0, 0, 1}));
    EXPECT_EQ(view.up, (Vec3{0, 0, 1e-3}));
    EXPECT_EQ(view.fov_degrees, 30.5);
    EXPECT_EQ(view.width, 20);
    EXPECT_EQ(view.height, 10);
    EXPECT_EQ(view.sampling.samples_per_pixel, 4);
}

TEST(ViewParameters, FrameTakesTheCameraOfThePathAndItsSeed) {
    const Scene scene = path_scene();
    const ViewCamera view = resolve_view_camera(scene, parse_view_query({{"frame", "3"}}));
    EXPECT_EQ(view.frame, 3);
    EXPECT_EQ(view.key.eye, camera_at_frame(scene, 3).eye);
    EXPECT_NE(view.key.eye, scene.camera_path[0].eye);
    const ViewCamera moved = resolve_view_camera(scene, parse_view_query({{"frame", "3"}, {"eye", "0,5,5"}}));
    EXPECT_EQ(moved.key.eye, (Vec3{0, 5, 5}));
    EXPECT_EQ(moved.key.lookat, camera_at_frame(scene, 3).lookat);
    EXPECT_EQ(moved.frame, 3);
}

TEST(ViewParameters, BadValuesNameTheirParameter) {
    const std::vector<std::tuple<std::string, std::string, std::string>> cases = {
        {"eye", "nan,0,0", "eye"},         {"eye", "1e400,0,0", "eye"},       {"eye", "1,2", "eye"},
        {"eye", "1,2,3,4", "eye"},         {"eye", "inf,0,0", "eye"},         {"eye", "0x10,0,0", "eye"},
        {"eye", " 1,2,3", "eye"},          {"eye", "", "eye"},                {"eye", "2e15,0,0", "eye"},
        {"eye", "0,0,0", "eye"},  // the look-at point: no view direction
        {"lookat", "a,b,c", "lookat"},     {"up", "0,0,0", "up"},             {"up", "0,0,1", "up"},  // parallel to the view
        {"up", "0,0,-5", "up"},            {"fov", "0", "fov"},               {"fov", "180", "fov"},
        {"fov", "-10", "fov"},             {"fov", "nan", "fov"},             {"fov", "1e-9", "fov"},  // too narrow
        {"size", "100000x100000", "size"}, {"size", "-5x10", "size"},         {"size", "0x10", "size"},
        {"size", "16385x1", "size"},       {"size", "9000x9000", "size"},     {"size", "10", "size"},
        {"spp", "1000000000", "spp"},      {"spp", "0", "spp"},               {"spp", "4097", "spp"},
        {"spp", "-1", "spp"},              {"spp", "2.5", "spp"},             {"spp", "99999999999999999999", "spp"},
        {"frame", "13", "frame"},          {"frame", "-1", "frame"},          {"frame", "x", "frame"},
    };
    for (const auto& [name, value, parameter] : cases) EXPECT_EQ(refused_parameter(name, value), parameter) << name << "=" << value;
}

TEST(ViewParameters, AFaultOfTwoValuesNamesTheOneTheQueryGave) {
    // The scene's eye is [0, 0, 10], its look-at point the origin, its up [0, 1, 0].
    EXPECT_EQ(refused_parameter("lookat", "0,0,10"), "lookat");   // onto the eye: it was named eye
    EXPECT_EQ(refused_parameter("lookat", "0,-5,10"), "lookat");  // the view parallel to up: named up
    EXPECT_EQ(refused_parameter("eye", "0,7,0"), "eye");          // the same: named up
    // A size the scene's narrow fov cannot resolve is the size's fault (named fov).
    const Scene narrow = parse_scene(R"({"eye": [0, 0, 10], "lookat": [0, 0, 0], "up": [0, 1, 0],
        "fov_angle": 0.01, "width": 64, "height": 48})", "narrow.json");
    try {
        resolve_view_camera(narrow, parse_view_query({{"size", "16384x1"}}));
        ADD_FAILURE() << "a fov of 0.01 degrees across 16384 pixels was taken";
    } catch (const ParameterError& error) {
        EXPECT_EQ(error.parameter(), "size") << error.what();
    }
    // Given both, the value at fault is named, as before.
    try {
        resolve_view_camera(path_scene(), parse_view_query({{"eye", "1,1,1"}, {"lookat", "1,1,1"}}));
        ADD_FAILURE() << "eye and lookat the same point were taken";
    } catch (const ParameterError& error) {
        EXPECT_EQ(error.parameter(), "eye") << error.what();
    }
}

TEST(ViewParameters, LimitsAreTheCommandLines) {
    // The largest values a render accepts are accepted; one beyond is refused.
    EXPECT_EQ(refused_parameter("spp", "4096"), "");
    EXPECT_EQ(refused_parameter("size", "16384x1"), "");
    EXPECT_EQ(refused_parameter("size", "8192x8192"), "");
    EXPECT_EQ(refused_parameter("eye", "1e15,0,0"), "");
    EXPECT_EQ(refused_parameter("frame", "4"), "");  // the last of (2 keys - 1) x 4 + 1 frames
    EXPECT_EQ(refused_parameter("frame", "5"), "frame");
    EXPECT_EQ(refused_parameter("fov", "179.9"), "");
}

TEST(ViewParameters, ARepeatedParameterIsRefused) {
    EXPECT_THROW(parse_view_query({{"eye", "0,0,1"}, {"eye", "0,0,2"}}), ParameterError);
}

// The parameter that query_parameters() refuses in `target`, or "" when it takes the query.
std::string refused_in_query(const std::string& target, const std::vector<std::string>& known) {
    try {
        (void)query_parameters(target, known);
        return "";
    } catch (const ParameterError& error) {
        return error.parameter();
    }
}

// The query is read as sent: cpp-httplib's parse merged a pair given twice alike, kept what
// followed a value's last '=', decoded %uXXXX, and a route never heard of a name it ignored.
TEST(ViewParameters, AQueryIsReadAsSent) {
    const std::vector<std::string> frame = {"eye", "size", "spp"};
    EXPECT_EQ(refused_in_query("/f?spp=4&spp=4", frame), "spp");
    EXPECT_EQ(refused_in_query("/f?spp=4&sp%70=4", frame), "spp") << "a name however encoded";
    EXPECT_EQ(refused_in_query("/f?eye=9,9,9=0,1,2", frame), "eye");
    EXPECT_EQ(refused_in_query("/f?size=2x2=3", frame), "size");
    EXPECT_EQ(refused_in_query("/f?sise=4x4", frame), "sise");
    EXPECT_THROW(query_parameters("/f?=4", frame), ParameterError) << "a value without a name";
    EXPECT_EQ(refused_in_query("/f?x", {}), "x");
    EXPECT_EQ(refused_in_query("/f?token=T&token=T&spp=1", frame), "") << "the guard's to refuse";

    const QueryParameters read =
        query_parameters("/f?eye=0%2C1.5%2C14&&size=%u0034x4&token=T&spp=1+2&", {"eye", "size", "spp"});
    EXPECT_EQ(read, (QueryParameters{{"eye", "0,1.5,14"}, {"size", "%u0034x4"}, {"spp", "1 2"}}));
    EXPECT_EQ(query_parameters("/f?eye=%3D%zz%4", {"eye"}), (QueryParameters{{"eye", "=%zz%4"}}));
    EXPECT_EQ(query_parameters("/f?eye", {"eye"}), (QueryParameters{{"eye", ""}}));
    EXPECT_TRUE(query_parameters("/f", {}).empty());
    EXPECT_TRUE(query_parameters("/f?", {}).empty());
}

TEST(ViewParameters, PixelNeedsBothCoordinates) {
    EXPECT_EQ(parse_pixel_query({{"x", "3"}, {"y", "7"}}).y, 7);
    EXPECT_THROW(parse_pixel_query({{"x", "3"}}), ParameterError);
    EXPECT_THROW(parse_pixel_query({{"x", "-3"}, {"y", "1"}}), ParameterError);
    EXPECT_THROW(parse_pixel_query({{"x", "3.5"}, {"y", "1"}}), ParameterError);
}

TEST(ViewParameters, PlainNumbersOnly) {
    EXPECT_EQ(parse_plain_number("-1.5e2"), -150);
    EXPECT_EQ(parse_plain_number(".5"), 0.5);
    EXPECT_EQ(parse_plain_number("1e-400"), 0);  // underflow reads as zero, as strtod reads JSON
    for (const char* text : {"1e400", "-1e400", "inf", "nan", "0x1p3", "1,5", "", "+", "1e", " 1", "1 "})
        EXPECT_FALSE(parse_plain_number(text)) << text;
}

// What an export's body that cannot be read says: not JSON, a number no double holds (the
// whole number not echoed back), or JSON of another shape, each named as the body's fault.
TEST(ViewCameraKeys, EachWayABodyFailsSaysWhich) {
    const std::string huge(400, '9');
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"not json", "the body is not JSON (byte "},
        {R"({"keys": [{"eye": [0, 0, )" + huge + R"(], "lookat": [0, 0, 0]}]})", "a number too large for a double"},
        {R"({"keys": [{"eye": [0, 0, 1e400], "lookat": [0, 0, 0]}]})", "a number too large for a double"},
        {"[1, 2, 3]", "the body must be a JSON object"},
    };
    for (const auto& [body, expected] : cases) {
        try {
            parse_camera_keys(body);
            ADD_FAILURE() << body.substr(0, 60) << ": accepted";
        } catch (const ParameterError& error) {
            const std::string message = error.what();
            EXPECT_EQ(error.parameter(), "body") << message;
            EXPECT_NE(message.find(expected), std::string::npos) << message;
            EXPECT_EQ(message.find(huge.substr(0, 40)), std::string::npos) << "the number echoed: " << message;
        }
    }
}

// A body of more JSON values than the most keys take is refused as the body's fault, before it
// is built (it was built whole, 24 times its bytes, and then refused for its count of keys);
// the most keys, each with a member more than the page sends, are still read.
TEST(ViewCameraKeys, ABodyOfMoreValuesThanTheMostKeysTakeIsRefusedAsSuch) {
    std::string many = R"({"keys": [)";
    for (std::size_t i = 0; i < kMostBodyValues; ++i) many += "[],";
    many.back() = ']';
    many += "}";
    try {
        parse_camera_keys(many);
        ADD_FAILURE() << "accepted";
    } catch (const ParameterError& error) {
        EXPECT_EQ(error.parameter(), "body") << error.what();
        EXPECT_NE(std::string(error.what()).find("more than " + std::to_string(kMostBodyValues) + " JSON values"),
                  std::string::npos)
            << error.what();
    }
    std::string most = R"({"keys": [)";
    for (std::size_t i = 0; i < kMostCameraKeys; ++i)
        most += R"({"eye": [1, 2, 3], "lookat": [0, 0, 0], "fov": 40},)";
    most.back() = ']';
    most += R"(, "name": "n", "up": [0, 1, 0], "fov": 40})";
    EXPECT_EQ(parse_camera_keys(most).keys.size(), kMostCameraKeys);
}

}  // namespace
}  // namespace clr
