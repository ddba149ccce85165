// /frame.png against the batch render with the same camera as -D values, byte for byte:
// spheres, billboards with transparent holes, the sun's shadows, mirrors, several samples per
// pixel, and a frame of a camera path; /frame.rgba carries the same pixels raw; /explain is
// --explain-pixel's text; /camera.json is the camera of a path frame as a batch render places it.
#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <vector>

#include "scene/camera_path.h"
#include "scene/image_loader.h"
#include "scene/scene_loader.h"
#include "support/command.h"
#include "support/temp_folder.h"
#include "view/viewer_process.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using testing::read_bytes;
using testing::run_clrender;
using testing::TempFolder;
using testing::ViewerProcess;

const std::string kDemo = std::string(CLRENDER_SOURCE_DIR) + "/scenes/demo/";

// The viewer's PNG for `query`, decoded; fails the test on another status.
Image viewer_frame(const ViewerProcess& viewer, const std::string& query) {
    const httplib::Result result = viewer.client()->Get(viewer.with_token("/frame.png?" + query));
    EXPECT_TRUE(result) << query;
    if (!result) return {};
    EXPECT_EQ(result->status, 200) << query << ": " << result->body;
    EXPECT_EQ(result->get_header_value("Content-Type"), "image/png");
    const std::vector<unsigned char> bytes(result->body.begin(), result->body.end());
    return *load_image_from_bytes(bytes, "frame.png");
}

// The batch render of `arguments` (written to out.png in `folder`), decoded.
Image batch_frame(const TempFolder& folder, const std::string& arguments) {
    const auto render = run_clrender(arguments + " -q -o '" + folder.file("out.png") + "'", folder.path());
    EXPECT_EQ(render.exit_code, 0) << render.output;
    Image image = *load_image(folder.file("out.png"));
    fs::remove(folder.file("out.png"));
    return image;
}

void expect_same_pixels(const Image& viewer, const Image& batch, const std::string& what) {
    ASSERT_EQ(viewer.width, batch.width) << what;
    ASSERT_EQ(viewer.height, batch.height) << what;
    std::size_t differing = 0;
    for (std::size_t i = 0; i < viewer.rgba.size(); ++i) differing += viewer.rgba[i] != batch.rgba[i];
    EXPECT_EQ(differing, 0u) << what;
}

TEST(ViewFrames, PngEqualsTheBatchRenderWithTheSameCamera) {
    TempFolder folder;
    // demo.json: spheres and billboards with images, one of them with transparent holes.
    ViewerProcess viewer("'" + kDemo + "demo.json'", folder.path());
    ASSERT_TRUE(viewer.started()) << viewer.output();
    // Its own camera, another camera with every parameter, and several samples per pixel.
    expect_same_pixels(viewer_frame(viewer, "size=96x54"), batch_frame(folder, "'" + kDemo + "demo.json' --size 96x54"),
                       "the scene's camera");
    const std::string query = "eye=3,2.5,9&lookat=1,1.5,-4&up=0.1,1,0&fov=48.5&size=120x70&spp=4";
    const Image moved = viewer_frame(viewer, query);
    expect_same_pixels(moved,
                       batch_frame(folder, "'" + kDemo + "demo.json' -D 'eye=[3,2.5,9]' -D 'lookat=[1,1.5,-4]' "
                                           "-D 'up=[0.1,1,0]' -D fov_angle=48.5 --size 120x70 --spp 4"),
                       query);
    // The comparison can fail: a different camera gives a different image.
    const Image other = viewer_frame(viewer, "eye=3,2.5,9.5&lookat=1,1.5,-4&up=0.1,1,0&fov=48.5&size=120x70&spp=4");
    EXPECT_NE(moved.rgba, other.rgba);
    EXPECT_EQ(viewer.stop(SIGTERM), 143);
}

TEST(ViewFrames, PngEqualsTheBatchRenderOfAPathFrameWithSunAndMirrors) {
    TempFolder folder;
    // showcase.json: a Catmull-Rom path of 96 frames, the sun's shadows, a mirror sphere and a
    // mirror billboard.
    ViewerProcess viewer("'" + kDemo + "showcase.json' --size 96x54 --spp 2", folder.path());
    ASSERT_TRUE(viewer.started()) << viewer.output();
    for (int frame : {0, 37, 95}) {
        expect_same_pixels(viewer_frame(viewer, "frame=" + std::to_string(frame)),
                           batch_frame(folder, "'" + kDemo + "showcase.json' --size 96x54 --spp 2 --frames " +
                                                   std::to_string(frame)),
                           "frame " + std::to_string(frame));
    }
    // A camera of its own on the path scene: the path replaced by that one camera.
    expect_same_pixels(viewer_frame(viewer, "eye=4,3,8&lookat=0,1,-3"),
                       batch_frame(folder, "'" + kDemo + "showcase.json' --size 96x54 --spp 2 "
                                           "-D 'eyeLocations=[[4,3,8]]' -D 'lookatLocations=[[0,1,-3]]'"),
                       "own camera");
    EXPECT_EQ(viewer.stop(SIGTERM), 143);
}

// A key recorded at a path frame is this camera: it must be the batch render's, to the last bit,
// between the keys of a Catmull-Rom path too (which straight lines would miss).
TEST(ViewFrames, CameraJsonIsThePathFramesCameraAsTheBatchRenderPlacesIt) {
    TempFolder folder;
    ViewerProcess viewer("'" + kDemo + "showcase.json' --size 96x54", folder.path());
    ASSERT_TRUE(viewer.started()) << viewer.output();
    LoadOptions header_only;
    header_only.decode_images = false;
    const Scene scene = load_scene(kDemo + "showcase.json", header_only);
    for (int frame : {0, 37, 95}) {
        const httplib::Result result = viewer.client()->Get(viewer.with_token("/camera.json?frame=" + std::to_string(frame)));
        ASSERT_TRUE(result);
        ASSERT_EQ(result->status, 200) << result->body;
        EXPECT_EQ(result->get_header_value("Content-Type"), "application/json");
        const nlohmann::json camera = nlohmann::json::parse(result->body);
        const CameraKey placed = camera_at_frame(scene, frame);
        EXPECT_EQ(camera["frame"], frame);
        EXPECT_EQ(camera["eye"], nlohmann::json::array({placed.eye.x, placed.eye.y, placed.eye.z})) << frame;
        EXPECT_EQ(camera["lookat"], nlohmann::json::array({placed.lookat.x, placed.lookat.y, placed.lookat.z})) << frame;
        EXPECT_EQ(camera["up"], nlohmann::json::parse("[0, 1, 0]"));
        EXPECT_EQ(camera["fov"], 65);
    }
    // A frame the animation does not have is refused as /frame.png refuses it.
    const httplib::Result outside = viewer.client()->Get(viewer.with_token("/camera.json?frame=96"));
    ASSERT_TRUE(outside);
    EXPECT_EQ(outside->status, 400);
    EXPECT_NE(outside->body.find("\"parameter\":\"frame\""), std::string::npos) << outside->body;
    // Only frame= counts: other parameters, even ones /frame.png would refuse, are not read.
    const httplib::Result others = viewer.client()->Get(viewer.with_token("/camera.json?frame=5&eye=nan&size=0x0"));
    ASSERT_TRUE(others);
    EXPECT_EQ(others->status, 200) << others->body;
    EXPECT_EQ(nlohmann::json::parse(others->body)["frame"], 5) << others->body;
    EXPECT_EQ(viewer.stop(SIGTERM), 143);
}

TEST(ViewFrames, RgbaCarriesThePngsPixelsRaw) {
    TempFolder folder;
    ViewerProcess viewer("'" + kDemo + "demo.json' --size 64x40", folder.path());
    ASSERT_TRUE(viewer.started()) << viewer.output();
    const std::string query = "eye=-2,2,10&spp=3";
    const Image png = viewer_frame(viewer, query);
    const httplib::Result raw = viewer.client()->Get(viewer.with_token("/frame.rgba?" + query));
    ASSERT_TRUE(raw);
    ASSERT_EQ(raw->status, 200);
    EXPECT_EQ(raw->get_header_value("X-Width"), "64");
    EXPECT_EQ(raw->get_header_value("X-Height"), "40");
    ASSERT_EQ(raw->body.size(), 64u * 40 * 4);
    EXPECT_EQ(std::vector<std::uint8_t>(raw->body.begin(), raw->body.end()), png.rgba);
    EXPECT_EQ(viewer.stop(SIGINT), 130);
}

TEST(ViewFrames, ExplainIsTheCommandLinesExplanation) {
    TempFolder folder;
    ViewerProcess viewer("'" + kDemo + "demo.json' --size 80x45", folder.path());
    ASSERT_TRUE(viewer.started()) << viewer.output();
    const httplib::Result explained = viewer.client()->Get(viewer.with_token("/explain?x=50&y=20&eye=1,2,12&spp=2"));
    ASSERT_TRUE(explained);
    ASSERT_EQ(explained->status, 200) << explained->body;
    EXPECT_EQ(explained->get_header_value("Content-Type"), "text/plain; charset=utf-8");
    const auto cli = run_clrender("'" + kDemo + "demo.json' --size 80x45 -D 'eye=[1,2,12]' --spp 2 --explain-pixel 50,20 2>/dev/null",
                                  folder.path());
    ASSERT_EQ(cli.exit_code, 0) << cli.output;
    EXPECT_EQ(explained->body, cli.output);
    const httplib::Result outside = viewer.client()->Get(viewer.with_token("/explain?x=80&y=0"));
    ASSERT_TRUE(outside);
    EXPECT_EQ(outside->status, 400);
    EXPECT_NE(outside->body.find("\"parameter\":\"x\""), std::string::npos) << outside->body;
    EXPECT_EQ(viewer.stop(SIGTERM), 143);
}

TEST(ViewFrames, SceneJsonDescribesCameraSizeAndPath) {
    TempFolder folder;
    ViewerProcess viewer("'" + kDemo + "showcase.json' --size 96x54", folder.path());
    ASSERT_TRUE(viewer.started()) << viewer.output();
    const httplib::Result result = viewer.client()->Get(viewer.with_token("/scene.json"));
    ASSERT_TRUE(result);
    ASSERT_EQ(result->status, 200);
    const nlohmann::json scene = nlohmann::json::parse(result->body);
    EXPECT_EQ(scene["camera"]["eye"], nlohmann::json::parse("[-9, 2.5, 13]"));
    EXPECT_EQ(scene["camera"]["lookat"], nlohmann::json::parse("[0, 1, -6]"));
    EXPECT_EQ(scene["camera"]["up"], nlohmann::json::parse("[0, 1, 0]"));
    EXPECT_EQ(scene["camera"]["fov"], 65);
    EXPECT_EQ(scene["size"], nlohmann::json::parse("[96, 54]"));
    EXPECT_EQ(scene["spp"], 1);
    EXPECT_EQ(scene["frames"], 96);
    ASSERT_EQ(scene["path"].size(), 5u);
    EXPECT_EQ(scene["path"][4]["eye"], nlohmann::json::parse("[6, 2.5, 3]"));
    EXPECT_EQ(scene["name"], "showcase.json");
    EXPECT_EQ(viewer.stop(SIGTERM), 143);
}

}  // namespace
}  // namespace clr
