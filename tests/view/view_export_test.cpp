// POST /export and /render-video: the recorded keys as the course's camera path, a scene that
// clrender renders, written atomically into --output-dir and never over the scene or its
// images; and its video, rendered in the background through the normal render path.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <thread>

#include "support/command.h"
#include "support/temp_folder.h"
#include "view/viewer_process.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using testing::read_bytes;
using testing::run_clrender;
using testing::TempFolder;
using testing::ViewerProcess;

const std::string kDemo = std::string(CLRENDER_SOURCE_DIR) + "/scenes/demo/";
const std::string kTwoKeys =
    R"({"keys": [{"eye": [-3, 2, 12], "lookat": [0, 1, 0]}, {"eye": [3, 1.5, 10], "lookat": [1, 1, -2]}], "name": "tour"})";

httplib::Result post(const ViewerProcess& viewer, const std::string& path, const std::string& body) {
    const httplib::Headers origin = {{"Origin", "http://127.0.0.1:" + std::to_string(viewer.port())}};
    return viewer.client()->Post(viewer.with_token(path).c_str(), origin, body, "application/json");
}

TEST(ViewExport, WritesTheKeysAsACameraPathThatClrenderRenders) {
    TempFolder folder;
    fs::create_directories(folder.file("out"));
    ViewerProcess viewer("'" + kDemo + "demo.json' --size 48x27 -D MaxDepth=3 --output-dir out", folder.path());
    ASSERT_TRUE(viewer.started()) << viewer.output();
    const httplib::Result result = post(viewer, "/export", kTwoKeys);
    ASSERT_TRUE(result);
    ASSERT_EQ(result->status, 200) << result->body;
    const json answer = json::parse(result->body);
    EXPECT_EQ(answer["file"], "out/tour.json");
    const std::string written = read_bytes(folder.file("out/tour.json"));
    EXPECT_EQ(answer["scene"], written);
    const json scene = json::parse(written);
    EXPECT_EQ(scene["eyeLocations"], json::parse("[[-3, 2, 12], [3, 1.5, 10]]"));
    EXPECT_EQ(scene["lookatLocations"], json::parse("[[0, 1, 0], [1, 1, -2]]"));
    EXPECT_FALSE(scene.contains("eye"));
    EXPECT_FALSE(scene.contains("lookat"));
    EXPECT_EQ(scene["MaxDepth"], 3) << "the -D values are the scene the page showed";
    EXPECT_EQ(scene["width"], 48);
    // Image names are absolute, so the scene finds its images wherever it is saved.
    EXPECT_EQ(scene["billboards"][0]["filename"], fs::path(kDemo + "backdrop.png").lexically_normal().string());
    // The exported scene renders: frame 0 is the viewer's frame of the first key.
    const auto render = run_clrender("out/tour.json -q --frames 0 -o first.png", folder.path());
    ASSERT_EQ(render.exit_code, 0) << render.output;
    // The text the page shows (and offers as a download), saved in another folder, renders the same.
    fs::create_directories(folder.file("downloads"));
    folder.write("downloads/tour.json", answer["scene"].get<std::string>());
    const auto saved = run_clrender("downloads/tour.json -q --frames 0 -o saved.png", folder.path());
    ASSERT_EQ(saved.exit_code, 0) << saved.output;
    EXPECT_EQ(read_bytes(folder.file("saved.png")), read_bytes(folder.file("first.png")));
    const httplib::Result frame = viewer.client()->Get(viewer.with_token("/frame.png?eye=-3,2,12&lookat=0,1,0").c_str());
    ASSERT_TRUE(frame);
    EXPECT_EQ(frame->status, 200);
    EXPECT_EQ(viewer.stop(SIGTERM), 143);
}

TEST(ViewExport, RefusesBadKeysNamesAndOutputsOverInputs) {
    TempFolder folder;
    // The scene and its images in the output folder: an export must not replace them.
    for (const char* name : {"demo.json", "backdrop.png", "checker.png", "cutout.png", "sign.ppm"})
        fs::copy_file(kDemo + name, folder.file(name));
    ViewerProcess viewer("demo.json --size 32x18", folder.path());
    ASSERT_TRUE(viewer.started()) << viewer.output();
    const std::string scene_before = read_bytes(folder.file("demo.json"));
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"not json", "body"},
        {"{}", "keys"},
        {R"({"keys": []})", "keys"},
        {R"({"keys": [{"eye": [0, 1]}]})", "keys"},
        {R"({"keys": [{"eye": [0, 0, 1e400], "lookat": [0, 0, 0]}]})", "body"},
        {R"({"keys": [{"eye": [0, 1, 5], "lookat": [0, 1, 5]}]})", "keys"},  // no view direction
        {R"({"keys": [{"eye": [2e15, 1, 5], "lookat": [0, 1, 0]}]})", "keys"},
        {R"({"keys": [{"eye": [0, 1, 5], "lookat": [0, 1, 0]}], "name": "../escape"})", "name"},
        {R"({"keys": [{"eye": [0, 1, 5], "lookat": [0, 1, 0]}], "name": "/tmp/abs"})", "name"},
        {R"({"keys": [{"eye": [0, 1, 5], "lookat": [0, 1, 0]}], "name": ".hidden"})", "name"},
        {R"({"keys": [{"eye": [0, 1, 5], "lookat": [0, 1, 0]}], "name": 7})", "name"},
        {R"({"keys": [{"eye": [0, 1, 5], "lookat": [0, 1, 0]}], "name": "demo"})", "name"},  // the scene itself
    };
    for (const auto& [body, parameter] : cases) {
        const httplib::Result result = post(viewer, "/export", body);
        ASSERT_TRUE(result) << body;
        EXPECT_TRUE(result->status == 400 || result->status == 409) << body << ": " << result->status;
        EXPECT_NE(result->body.find("\"parameter\":\"" + parameter + "\""), std::string::npos) << body << ": " << result->body;
    }
    EXPECT_EQ(read_bytes(folder.file("demo.json")), scene_before);
    EXPECT_FALSE(fs::exists(folder.path() + "/../escape.json"));
    // A symbolic link under the export's name that points at the scene is not written through.
    fs::create_symlink("demo.json", folder.file("link.json"));
    const httplib::Result through_link =
        post(viewer, "/export", R"({"keys": [{"eye": [0, 1, 5], "lookat": [0, 1, 0]}], "name": "link"})");
    ASSERT_TRUE(through_link);
    EXPECT_EQ(through_link->status, 409) << through_link->body;
    EXPECT_EQ(read_bytes(folder.file("demo.json")), scene_before);
    // A body beyond the limit is refused without being read.
    const std::string huge(3 * 1024 * 1024, ' ');
    const httplib::Result too_large = post(viewer, "/export", huge);
    EXPECT_TRUE(!too_large || too_large->status == 413);
    EXPECT_EQ(viewer.stop(SIGTERM), 143);
}

// A mesh whose OBJ (or .mtl) is named like an export is an input like the images: the export
// is refused, and the exported scene names the mesh by its absolute path.
TEST(ViewExport, NeverReplacesAMeshAndNamesItAbsolutely) {
    TempFolder folder;
    const std::string obj = "mtllib tour.json\nusemtl red\nv -1 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    const std::string mtl = "newmtl red\nKd 1 0 0\n";
    folder.write("model.json", obj);  // an OBJ may have any name
    folder.write("tour.json", mtl);
    folder.write("scene.json", R"({"eye": [0, 0, 5], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60,
        "width": 16, "height": 12, "obj": {"filename": "model.json"}})");
    ViewerProcess viewer("scene.json", folder.path());
    ASSERT_TRUE(viewer.started()) << viewer.output();
    for (const char* name : {"model", "tour"}) {
        const httplib::Result result =
            post(viewer, "/export", R"({"keys": [{"eye": [0, 1, 5], "lookat": [0, 0, 0]}], "name": ")" + std::string(name) + "\"}");
        ASSERT_TRUE(result);
        EXPECT_EQ(result->status, 409) << name << ": " << result->body;
    }
    EXPECT_EQ(read_bytes(folder.file("model.json")), obj);
    EXPECT_EQ(read_bytes(folder.file("tour.json")), mtl);
    const httplib::Result saved = post(viewer, "/export", R"({"keys": [{"eye": [0, 1, 5], "lookat": [0, 0, 0]}], "name": "saved"})");
    ASSERT_TRUE(saved);
    ASSERT_EQ(saved->status, 200) << saved->body;
    const json scene = json::parse(read_bytes(folder.file("saved.json")));
    EXPECT_EQ(scene["obj"]["filename"], fs::path(folder.file("model.json")).lexically_normal().string());
    EXPECT_EQ(viewer.stop(SIGTERM), 143);
}

TEST(ViewExport, RenderVideoWritesTheMp4InTheBackground) {
    TempFolder folder;
    ViewerProcess viewer("'" + kDemo + "demo.json' --size 32x18", folder.path());
    ASSERT_TRUE(viewer.started()) << viewer.output();
    const httplib::Result started = post(viewer, "/render-video", kTwoKeys);
    ASSERT_TRUE(started);
    ASSERT_EQ(started->status, 200) << started->body;
    const json job = json::parse(started->body);
    ASSERT_TRUE(job["job"].is_number_integer());
    const std::string id = std::to_string(job["job"].get<int>());
    json state;
    for (int i = 0; i < 600; ++i) {
        const httplib::Result polled = viewer.client()->Get(viewer.with_token("/job?id=" + id).c_str());
        ASSERT_TRUE(polled);
        ASSERT_EQ(polled->status, 200);
        state = json::parse(polled->body);
        if (state["state"] != "running") break;
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    ASSERT_EQ(state["state"], "done") << state.dump();
    EXPECT_EQ(state["total"], 11);  // two keys, 10 frames per segment, and the last key's
    EXPECT_EQ(state["done"], 11);
    EXPECT_EQ(state["file"], "./tour.mp4");
    EXPECT_GT(fs::file_size(folder.file("tour.mp4")), 0u);
    EXPECT_TRUE(fs::exists(folder.file("tour.json")));
    EXPECT_EQ(viewer.client()->Get(viewer.with_token("/job?id=99").c_str())->status, 404);
    EXPECT_EQ(viewer.stop(SIGTERM), 143);
}

TEST(ViewExport, StoppingTheViewerStopsTheVideoAndLeavesNoPartialFile) {
    TempFolder folder;
    ViewerProcess viewer("'" + kDemo + "demo.json' --size 320x180 --spp 16", folder.path());
    ASSERT_TRUE(viewer.started()) << viewer.output();
    const std::string many_frames = R"({"keys": [{"eye": [-3, 2, 12], "lookat": [0, 1, 0]}, {"eye": [3, 1.5, 10], "lookat": [0, 1, 0]},
        {"eye": [5, 1.5, 10], "lookat": [0, 1, 0]}, {"eye": [7, 1.5, 10], "lookat": [0, 1, 0]}], "name": "long"})";
    const httplib::Result started = post(viewer, "/render-video", many_frames);
    ASSERT_TRUE(started);
    ASSERT_EQ(started->status, 200) << started->body;
    const httplib::Result busy = post(viewer, "/render-video", many_frames);
    ASSERT_TRUE(busy);
    EXPECT_EQ(busy->status, 409) << "one video at a time";
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    EXPECT_EQ(viewer.stop(SIGTERM), 143) << viewer.output();
    for (const auto& entry : fs::directory_iterator(folder.path())) {
        const std::string name = entry.path().filename().string();
        EXPECT_TRUE(name == "long.json" || name == "view-stderr.txt") << "left behind: " << name;
    }
}

}  // namespace
}  // namespace clr
