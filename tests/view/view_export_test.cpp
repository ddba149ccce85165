// POST /export and /render-video: the recorded keys as the course's camera path, a scene that
// clrender renders, written atomically into --output-dir and never over the scene or its
// images; and its video, rendered in the background through the normal render path.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <functional>
#include <mutex>
#include <nlohmann/json.hpp>
#include <thread>
#include <vector>

#include "support/command.h"
#include "support/process_memory.h"
#include "support/process_table.h"
#include "support/temp_folder.h"
#include "view/viewer_process.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using testing::read_bytes;
using testing::rise_during;
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

// The state of job `id` once it no longer runs (or after a minute).
json finished_job(const ViewerProcess& viewer, int id) {
    json state;
    for (int i = 0; i < 600; ++i) {
        const httplib::Result polled = viewer.client()->Get(viewer.with_token("/job?id=" + std::to_string(id)).c_str());
        if (!polled || polled->status != 200) return json();
        state = json::parse(polled->body);
        if (state["state"] != "running") break;
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    return state;
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
    EXPECT_EQ(scene["billboards"][0]["filename"], (fs::canonical(kDemo) / "backdrop.png").string());
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
    };
    for (const auto& [body, parameter] : cases) {
        const httplib::Result result = post(viewer, "/export", body);
        ASSERT_TRUE(result) << body;
        EXPECT_TRUE(result->status == 400 || result->status == 409) << body << ": " << result->status;
        EXPECT_NE(result->body.find("\"parameter\":\"" + parameter + "\""), std::string::npos) << body << ": " << result->body;
    }
    EXPECT_EQ(read_bytes(folder.file("demo.json")), scene_before);
    EXPECT_FALSE(fs::exists(folder.path() + "/../escape.json"));
    // The scene's own name, or a symbolic link to the scene: the export takes the next free name.
    fs::create_symlink("demo.json", folder.file("link.json"));
    for (const std::string name : {"demo", "link"}) {
        const httplib::Result result =
            post(viewer, "/export", R"({"keys": [{"eye": [0, 1, 5], "lookat": [0, 1, 0]}], "name": ")" + name + "\"}");
        ASSERT_TRUE(result);
        ASSERT_EQ(result->status, 200) << result->body;
        EXPECT_EQ(json::parse(result->body)["file"], "./" + name + "-2.json");
    }
    EXPECT_EQ(read_bytes(folder.file("demo.json")), scene_before);
    EXPECT_TRUE(fs::is_symlink(folder.file("link.json")));
    // A body beyond the limit is refused without being read. The viewer answers 413 and closes
    // while the client still sends: its write then fails with EPIPE rather than end this test by
    // SIGPIPE (cpp-httplib's client sends without MSG_NOSIGNAL).
    struct sigaction ignore = {}, before = {};
    ignore.sa_handler = SIG_IGN;
    ASSERT_EQ(::sigaction(SIGPIPE, &ignore, &before), 0);
    const std::string huge(3 * 1024 * 1024, ' ');
    const httplib::Result too_large = post(viewer, "/export", huge);
    ::sigaction(SIGPIPE, &before, nullptr);
    EXPECT_TRUE(!too_large || too_large->status == 413);
    EXPECT_EQ(viewer.stop(SIGTERM), 143);
}

// A mesh whose OBJ (or .mtl) is named like an export is an input like the images: the export
// takes the next free name, and the exported scene names the mesh by its absolute path.
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
        ASSERT_EQ(result->status, 200) << name << ": " << result->body;
        EXPECT_EQ(json::parse(result->body)["name"], std::string(name) + "-2");
    }
    EXPECT_EQ(read_bytes(folder.file("model.json")), obj);
    EXPECT_EQ(read_bytes(folder.file("tour.json")), mtl);
    const httplib::Result saved = post(viewer, "/export", R"({"keys": [{"eye": [0, 1, 5], "lookat": [0, 0, 0]}], "name": "saved"})");
    ASSERT_TRUE(saved);
    ASSERT_EQ(saved->status, 200) << saved->body;
    const json scene = json::parse(read_bytes(folder.file("saved.json")));
    EXPECT_EQ(scene["obj"]["filename"], (fs::canonical(folder.path()) / "model.json").string());
    EXPECT_EQ(viewer.stop(SIGTERM), 143);
}

// A texture that a .mtl names is an input no output may replace, though clrender never reads it
// and it need not exist: a name that one holds is passed over as a taken one. The export was
// refused (409, "choose another output name", which the page cannot), and a video's scene was
// written before the name of its MP4 was refused.
TEST(ViewExport, ANameThatAMissingTextureHoldsIsPassedOver) {
    TempFolder folder;
    folder.write("model.obj", "mtllib model.mtl\nusemtl red\nv -1 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    folder.write("model.mtl", "newmtl red\nKd 1 0 0\nmap_Ks tour.json\nbump clip.mp4\n");  // neither file exists
    folder.write("scene.json", R"({"eye": [0, 0, 5], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60,
        "width": 16, "height": 12, "obj": {"filename": "model.obj"}})");
    ViewerProcess viewer("scene.json", folder.path());
    ASSERT_TRUE(viewer.started()) << viewer.output();
    const httplib::Result exported =
        post(viewer, "/export", R"({"keys": [{"eye": [0, 1, 5], "lookat": [0, 0, 0]}], "name": "tour"})");
    ASSERT_TRUE(exported);
    ASSERT_EQ(exported->status, 200) << exported->body;
    EXPECT_EQ(json::parse(exported->body)["name"], "tour-2");
    const httplib::Result video = post(viewer, "/render-video",
                                       R"({"keys": [{"eye": [0, 1, 5], "lookat": [0, 0, 0]}, {"eye": [1, 1, 5], "lookat": [0, 0, 0]}],
                                           "name": "clip"})");
    ASSERT_TRUE(video);
    ASSERT_EQ(video->status, 200) << video->body;
    EXPECT_EQ(json::parse(video->body)["name"], "clip-2");
    EXPECT_EQ(finished_job(viewer, json::parse(video->body)["job"].get<int>())["state"], "done");
    EXPECT_EQ(viewer.stop(SIGTERM), 143);
    EXPECT_FALSE(fs::exists(folder.file("tour.json")));
    EXPECT_FALSE(fs::exists(folder.file("clip.json")));
    EXPECT_FALSE(fs::exists(folder.file("clip.mp4")));
    EXPECT_TRUE(fs::exists(folder.file("clip-2.mp4")));
}

// The meshes were read when the viewer started, and keys do not change them: an export's check
// does not read the OBJ files again (exports sent at once held a copy of every mesh each, many
// times the memory of the scene). An OBJ broken since the start does not stop the export.
TEST(ViewExport, AnExportDoesNotReadTheMeshesAgain) {
    TempFolder folder;
    folder.write("model.obj", "v -1 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    folder.write("scene.json", R"({"eye": [0, 0, 5], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60,
        "width": 16, "height": 12, "obj": {"filename": "model.obj"}})");
    ViewerProcess viewer("scene.json", folder.path());
    ASSERT_TRUE(viewer.started()) << viewer.output();
    folder.write("model.obj", "v -1 0 0\nf 1 2 3\n");  // an index out of range: not read again
    const httplib::Result result = post(viewer, "/export", R"({"keys": [{"eye": [0, 1, 5], "lookat": [0, 0, 0]}]})");
    ASSERT_TRUE(result);
    EXPECT_EQ(result->status, 200) << result->body;
    EXPECT_EQ(viewer.stop(SIGTERM), 143);
}

// The folder the viewer was started in may go while it runs: the scene's folder was resolved
// at start, so the export still works, and names its images by their own folder, never
// through the one that went ("START/../scene/backdrop.png").
TEST(ViewExport, ExportsOnceTheStartFolderIsGone) {
    TempFolder folder;
    fs::create_directories(folder.file("scene"));
    fs::create_directories(folder.file("start"));
    fs::create_directories(folder.file("out"));
    for (const char* name : {"demo.json", "backdrop.png", "checker.png", "cutout.png", "sign.ppm"})
        fs::copy_file(kDemo + name, folder.file(std::string("scene/") + name));
    ViewerProcess viewer("../scene/demo.json --size 32x18 --output-dir '" + folder.file("out") + "'", folder.file("start"));
    ASSERT_TRUE(viewer.started()) << viewer.output();
    fs::remove_all(folder.file("start"));  // with the viewer's view-stderr.txt: its output is not read after this
    const httplib::Result result = post(viewer, "/export", kTwoKeys);
    ASSERT_TRUE(result);
    ASSERT_EQ(result->status, 200) << result->body;
    const json scene = json::parse(read_bytes(folder.file("out/tour.json")));
    EXPECT_EQ(scene["billboards"][0]["filename"], (fs::canonical(folder.path()) / "scene/backdrop.png").string());
    const auto render = run_clrender("out/tour.json -q --frames 0 -o first.png", folder.path());
    EXPECT_EQ(render.exit_code, 0) << render.output;
    EXPECT_EQ(viewer.stop(SIGTERM), 143);
}

// A scene of 100,000 spheres (a 7 MB file) as `name` in `folder`: one whose JSON is costly to hold.
void write_many_spheres(TempFolder& folder, const std::string& name) {
    json scene = json::parse(R"({"eye": [0, 1.5, 14], "lookat": [0, 1, 0], "up": [0, 1, 0], "fov_angle": 60,
                                 "width": 32, "height": 18, "spheres": []})");
    for (int i = 0; i < 100000; ++i)
        scene["spheres"].push_back({{"center", {i % 100, (i / 100) % 100, -50 - i / 10000}}, {"radius", 0.3},
                                    {"ambient", {0.5, 0.5, 0.5}}});
    folder.write(name, scene.dump());
}

// Each export holds the scene's JSON as a tree twice (about 18 times the file each) while it
// runs: exports sent at once run one at a time, and give back what they held, so that 4 at once
// take about what one takes. Sent at once, 8 exports of this 7 MB scene took the viewer about
// 7 times as far as one did (8 at once of a 21 MB scene, 2.2 GB). The clients wait up to 8
// minutes for their answer: under the sanitizers an export of this scene takes about 15 s, and
// the last of the 4 waits for the 3 before it.
TEST(ViewExport, ExportsSentAtOnceDoNotEachHoldTheScene) {
    TempFolder folder;
    write_many_spheres(folder, "many.json");
    ViewerProcess viewer("many.json", folder.path());
    ASSERT_TRUE(viewer.started()) << viewer.output();
    const std::string one_key = R"({"keys": [{"eye": [0, 1.5, 14], "lookat": [0, 1, 0]}], "name": "e"})";
    std::atomic<int> written{0};
    const auto export_once = [&] {
        const auto client = viewer.client();
        client->set_read_timeout(480, 0);
        const httplib::Headers origin = {{"Origin", "http://127.0.0.1:" + std::to_string(viewer.port())}};
        const httplib::Result result =
            client->Post(viewer.with_token("/export").c_str(), origin, one_key, "application/json");
        if (result && result->status == 200) ++written;
    };
    const long one = rise_during(viewer.pid(), export_once);
    const long four = rise_during(viewer.pid(), [&] {
        std::vector<std::thread> clients;
        for (int i = 0; i < 4; ++i) clients.emplace_back(export_once);
        for (std::thread& client : clients) client.join();
    });
    ASSERT_EQ(written, 5);
    EXPECT_GT(one, 20) << "one export holds the scene's JSON as a tree";
    EXPECT_LT(four, 2 * one + 64) << "one export: +" << one << " MiB, 4 at once: +" << four << " MiB";
    EXPECT_EQ(viewer.stop(SIGTERM), 143);
}

// Bodies of the largest size (2 MiB) sent together, each of 700,000 empty arrays: the body is
// refused before it is built into a tree of about 24 times its bytes. Built, 16 at once took the
// viewer 820 MB further, and it kept 660 MB of that once they were answered (32, one for each of
// the server's threads: 1.5 GB, 1.2 GB kept). 16, not 32: with every thread busy, a connection
// that has sent nothing for 0.1 s is closed, which a client of a loaded machine may meet.
TEST(ViewExport, LargeBodiesSentAtOnceAreNotEachBuiltIntoATree) {
    TempFolder folder;
    ViewerProcess viewer("'" + kDemo + "demo.json' --size 32x18", folder.path());
    ASSERT_TRUE(viewer.started()) << viewer.output();
    std::string body = R"({"keys": [)";
    while (body.size() < (std::size_t(2) << 20) - 8) body += "[],";
    body.back() = ']';
    body += "}";
    std::atomic<int> refused{0};
    std::mutex answers_mutex;
    std::string other_answers;
    const long rise = rise_during(viewer.pid(), [&] {
        std::vector<std::thread> clients;
        for (int i = 0; i < 16; ++i)
            clients.emplace_back([&] {
                const auto client = viewer.client();
                client->set_read_timeout(60, 0);  // 16 bodies read at once by 2 busy cores
                client->set_write_timeout(60, 0);
                const httplib::Headers origin = {{"Origin", "http://127.0.0.1:" + std::to_string(viewer.port())}};
                const httplib::Result result =
                    client->Post(viewer.with_token("/export").c_str(), origin, body, "application/json");
                if (result && result->status == 400 && json::parse(result->body)["parameter"] == "body") {
                    ++refused;
                    return;
                }
                const std::lock_guard<std::mutex> lock(answers_mutex);
                other_answers += result ? std::to_string(result->status) + " " + result->body.substr(0, 200) + "\n"
                                        : "no answer: " + httplib::to_string(result.error()) + "\n";
            });
        for (std::thread& client : clients) client.join();
    });
    EXPECT_EQ(refused, 16) << other_answers;
    // The bodies themselves, 32 MiB, and what the allocator keeps of them.
    EXPECT_LT(rise, 200) << "16 bodies of 2 MiB at once: +" << rise << " MiB";
    EXPECT_EQ(viewer.stop(SIGTERM), 143);
}

// The viewer stopped while exports sent together wait their turn: those still waiting write
// nothing. They ran one after another after the signal, each writing a file that no client
// heard of (3 files of a 21 MB scene, up to 4.4 s after SIGTERM), until the 5 s watchdog ended
// the viewer blaming "a step that cannot be interrupted".
TEST(ViewExport, ExportsWaitingTheirTurnAtAStopWriteNothing) {
    TempFolder folder;
    fs::create_directories(folder.file("out"));
    write_many_spheres(folder, "many.json");
    ViewerProcess viewer("many.json --output-dir out", folder.path());
    ASSERT_TRUE(viewer.started()) << viewer.output();
    const auto written = [&] {
        int files = 0;
        for (const auto& entry : fs::directory_iterator(folder.file("out")))
            files += entry.path().extension() == ".json";
        return files;
    };
    const std::string one_key = R"({"keys": [{"eye": [0, 1.5, 14], "lookat": [0, 1, 0]}], "name": "e"})";
    std::vector<std::thread> clients;
    for (int i = 0; i < 8; ++i) clients.emplace_back([&] { post(viewer, "/export", one_key); });
    for (int i = 0; i < 600 && written() == 0; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    const int before = written();
    ASSERT_GE(before, 1);
    EXPECT_EQ(viewer.stop(SIGTERM), 143);
    for (std::thread& client : clients) client.join();
    EXPECT_LE(written() - before, 1) << "at most the export that was running at the signal";
#ifndef __SANITIZE_ADDRESS__  // there the running export's check alone can outlast the watchdog
    EXPECT_EQ(viewer.output().find("cannot be interrupted"), std::string::npos) << viewer.output();
#endif
}

// GET /scene.json of a path of 100,000 keys (a scene may have a million: 21 MB) is made once and
// sent from that one text: made for each request as one tree, about 1.6 KB a key, 4 asked at
// once of 200,000 keys took the viewer 1.3 GB further (8 of a million keys, to 14 GB). The text
// is still the one the whole tree gave (members by name, numbers as nlohmann writes them).
TEST(ViewSceneJson, ManyAskedAtOnceOfALongPathShareOneText) {
    TempFolder folder;
    json scene = json::parse(R"({"up": [0, 1, 0], "fov_angle": 60, "width": 32, "height": 18,
                                 "clrender": {"frames_per_segment": 1},
                                 "spheres": [{"center": [0, 0, 0], "radius": 1, "ambient": [1, 0, 0]}]})");
    constexpr int kKeys = 100000;
    for (int i = 0; i < kKeys; ++i) {
        scene["eyeLocations"].push_back({i % 1000 + 0.5, 2, 10 + i % 7});
        scene["lookatLocations"].push_back({0, 0, i % 5 - 2});
    }
    folder.write("long.json", scene.dump());
    ViewerProcess viewer("long.json", folder.path());
    ASSERT_TRUE(viewer.started()) << viewer.output();
    const httplib::Result first = viewer.client()->Get(viewer.with_token("/scene.json"));
    ASSERT_TRUE(first);
    ASSERT_EQ(first->status, 200);
    const json summary = json::parse(first->body);
    EXPECT_EQ(first->body, summary.dump());
    ASSERT_EQ(summary["path"].size(), std::size_t(kKeys));
    EXPECT_EQ(summary["path"][kKeys - 1]["eye"], json::parse("[999.5, 2, 14]"));
    EXPECT_EQ(summary["path"][kKeys - 1]["lookat"], json::parse("[0, 0, 2]"));
    EXPECT_EQ(summary["frames"], kKeys);
    EXPECT_EQ(summary["name"], "long.json");
    const long answer_mib = static_cast<long>(first->body.size() >> 20);
    std::atomic<int> answered{0};
    const long four = rise_during(viewer.pid(), [&] {
        std::vector<std::thread> clients;
        for (int i = 0; i < 4; ++i)
            clients.emplace_back([&] {
                const httplib::Result result = viewer.client()->Get(viewer.with_token("/scene.json"));
                if (result && result->status == 200 && result->body == first->body) ++answered;
            });
        for (std::thread& client : clients) client.join();
    });
    EXPECT_EQ(answered, 4);
    EXPECT_LT(four, 3 * answer_mib + 64) << "the answer: " << answer_mib << " MiB";
    EXPECT_EQ(viewer.stop(SIGTERM), 143);
}

// A right-to-left override (U+202E) in the scene's file name would reverse what follows it on
// screen: the names the page shows come escaped, as clrender's messages escape them; the file
// written keeps its name.
TEST(ViewExport, NamesForThePageAreEscapedAsOnTheTerminal) {
    TempFolder folder;
    const std::string name = "report\u202Enosj";  // U+202E RIGHT-TO-LEFT OVERRIDE
    const std::string shown = "report\\xE2\\x80\\xAEnosj";
    fs::copy_file(kDemo + "demo.json", folder.file(name + ".json"));
    for (const char* image : {"backdrop.png", "checker.png", "cutout.png", "sign.ppm"})
        fs::copy_file(kDemo + image, folder.file(image));
    ViewerProcess viewer("'" + name + ".json' --size 32x18", folder.path());
    ASSERT_TRUE(viewer.started()) << viewer.output();
    const httplib::Result summary = viewer.client()->Get(viewer.with_token("/scene.json"));
    ASSERT_TRUE(summary);
    EXPECT_EQ(json::parse(summary->body)["name"], shown + ".json");
    const httplib::Result result = post(viewer, "/export", R"({"keys": [{"eye": [0, 1, 5], "lookat": [0, 1, 0]}]})");
    ASSERT_TRUE(result);
    ASSERT_EQ(result->status, 200) << result->body;
    const json answer = json::parse(result->body);
    EXPECT_EQ(answer["file"], "./" + shown + "_path.json");
    EXPECT_EQ(answer["name"], shown + "_path");
    EXPECT_TRUE(fs::exists(folder.file(name + "_path.json")));
    EXPECT_EQ(viewer.stop(SIGTERM), 143);
}

std::string export_body(const std::string& name) {
    return R"({"keys": [{"eye": [0, 1.5, 14], "lookat": [0, 1, 0]}])" + (name.empty() ? "" : R"(, "name": ")" + name + "\"") + "}";
}

// A link under the export's name, to a file outside --output-dir or to nothing, is a taken
// name: the file behind it keeps its bytes and its mode, and nothing is made where it points.
TEST(ViewExport, NeverWritesThroughALink) {
    TempFolder folder;
    fs::create_directories(folder.file("out"));
    folder.write("secret.txt", "secret\n");
    fs::permissions(folder.file("secret.txt"), fs::perms::owner_read | fs::perms::owner_write);
    fs::create_symlink(folder.file("secret.txt"), folder.file("out/demo_path.json"));
    fs::create_symlink(folder.file("missing.txt"), folder.file("out/dangling.json"));
    ViewerProcess viewer("'" + kDemo + "demo.json' --size 32x18 --output-dir out", folder.path());
    ASSERT_TRUE(viewer.started()) << viewer.output();
    const httplib::Result page_export = post(viewer, "/export", export_body(""));  // the page sends no name
    ASSERT_TRUE(page_export);
    ASSERT_EQ(page_export->status, 200) << page_export->body;
    EXPECT_EQ(json::parse(page_export->body)["file"], "out/demo_path-2.json");
    EXPECT_EQ(json::parse(page_export->body)["name"], "demo_path-2");
    EXPECT_EQ(read_bytes(folder.file("secret.txt")), "secret\n");
    EXPECT_EQ(fs::status(folder.file("secret.txt")).permissions() & fs::perms::all,
              fs::perms::owner_read | fs::perms::owner_write);
    EXPECT_TRUE(fs::is_symlink(folder.file("out/demo_path.json")));
    const httplib::Result dangling = post(viewer, "/export", export_body("dangling"));
    ASSERT_TRUE(dangling);
    ASSERT_EQ(dangling->status, 200) << dangling->body;
    EXPECT_EQ(json::parse(dangling->body)["file"], "out/dangling-2.json");
    EXPECT_FALSE(fs::exists(folder.file("missing.txt")));
    EXPECT_EQ(viewer.stop(SIGTERM), 143);
}

// Nothing in --output-dir is replaced: not a user's file of the same name, not the export of
// the click before, not a neighbouring scene; and a video's scene and MP4 share a free name.
TEST(ViewExport, NeverReplacesAnExistingFile) {
    TempFolder folder;
    folder.write("important.json", "{\"my\": \"data\"}\n");
    folder.write("clip.mp4", "not mine to replace");
    ViewerProcess viewer("'" + kDemo + "demo.json' --size 32x18", folder.path());
    ASSERT_TRUE(viewer.started()) << viewer.output();
    const httplib::Result named = post(viewer, "/export", export_body("important"));
    ASSERT_TRUE(named);
    ASSERT_EQ(named->status, 200) << named->body;
    EXPECT_EQ(json::parse(named->body)["file"], "./important-2.json");
    EXPECT_EQ(read_bytes(folder.file("important.json")), "{\"my\": \"data\"}\n");
    EXPECT_EQ(json::parse(read_bytes(folder.file("important-2.json")))["eyeLocations"], json::parse("[[0, 1.5, 14]]"));
    // Three clicks of the page: three files, the first two as they were written.
    std::vector<std::string> files;
    for (int click = 0; click < 3; ++click) {
        const httplib::Result result = post(viewer, "/export", export_body(""));
        ASSERT_TRUE(result);
        ASSERT_EQ(result->status, 200) << result->body;
        files.push_back(json::parse(result->body)["file"]);
    }
    EXPECT_EQ(files, (std::vector<std::string>{"./demo_path.json", "./demo_path-2.json", "./demo_path-3.json"}));
    // clip.json is free but clip.mp4 is not: the video takes clip-2 for both.
    const httplib::Result video = post(viewer, "/render-video",
                                       R"({"keys": [{"eye": [0, 1.5, 14], "lookat": [0, 1, 0]}, {"eye": [1, 1.5, 14], "lookat": [0, 1, 0]}],
                                           "name": "clip"})");
    ASSERT_TRUE(video);
    ASSERT_EQ(video->status, 200) << video->body;
    EXPECT_EQ(json::parse(video->body)["file"], "./clip-2.mp4");
    EXPECT_EQ(json::parse(video->body)["scene"], "./clip-2.json");
    EXPECT_FALSE(fs::exists(folder.file("clip.json")));
    EXPECT_EQ(viewer.stop(SIGTERM), 143);
    EXPECT_EQ(read_bytes(folder.file("clip.mp4")), "not mine to replace");
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
    EXPECT_EQ(state["frame"], 11) << "the last frame rendered";
    EXPECT_EQ(state["file"], "./tour.mp4");
    EXPECT_GT(fs::file_size(folder.file("tour.mp4")), 0u);
    EXPECT_TRUE(fs::exists(folder.file("tour.json")));
    EXPECT_EQ(viewer.client()->Get(viewer.with_token("/job?id=99").c_str())->status, 404);
    // Without an id, the last job, named: what a page loaded again follows.
    const httplib::Result latest = viewer.client()->Get(viewer.with_token("/job").c_str());
    ASSERT_TRUE(latest);
    ASSERT_EQ(latest->status, 200) << latest->body;
    const json last = json::parse(latest->body);
    EXPECT_EQ(last["id"], job["job"]);
    EXPECT_EQ(last["state"], "done");
    EXPECT_EQ(last["file"], "./tour.mp4");
    EXPECT_EQ(viewer.stop(SIGTERM), 143);
}

// A video asked for after the viewer's program was replaced (a rebuild or an install renames a
// new file over its name) is rendered by the program that serves the page, not by whatever
// now has its name: the viewer looked its name up, found "clrender (deleted)", and every
// video failed with 409 after writing its scene.
TEST(ViewExport, AVideoRendersAfterTheViewersProgramIsReplaced) {
    TempFolder folder;
    fs::create_directory(folder.file("bin"));
    const std::string program = folder.file("bin/clrender");
    fs::copy_file(CLRENDER_BINARY, program);
    ViewerProcess viewer("'" + kDemo + "demo.json' --size 32x18", folder.path(), "", false, program);
    ASSERT_TRUE(viewer.started()) << viewer.output();
    const std::string replacement = folder.write("bin/new", "#!/bin/sh\necho 'not the viewer's clrender' >&2\nexit 3\n");
    fs::permissions(replacement, fs::perms::owner_all);
    fs::rename(replacement, program);
    const httplib::Result started = post(viewer, "/render-video", kTwoKeys);
    ASSERT_TRUE(started);
    ASSERT_EQ(started->status, 200) << started->body;
    const json state = finished_job(viewer, json::parse(started->body)["job"].get<int>());
    EXPECT_EQ(state["state"], "done") << state.dump();
    EXPECT_EQ(state["done"], 11);
    EXPECT_GT(fs::file_size(folder.file("tour.mp4")), 0u);
    EXPECT_EQ(viewer.stop(SIGTERM), 143);
}

// A video whose render fails reports the render's own message, not its --progress json line;
// its scene stays (the input of the render, the scene the page showed), its video is not made.
TEST(ViewExport, AFailedVideoReportsTheRendersMessage) {
    TempFolder folder;
    ViewerProcess viewer("'" + kDemo + "demo.json' --size 32x18", folder.path(), "PATH=/nonexistent");  // no ffmpeg
    ASSERT_TRUE(viewer.started()) << viewer.output();
    const httplib::Result started = post(viewer, "/render-video", kTwoKeys);
    ASSERT_TRUE(started);
    ASSERT_EQ(started->status, 200) << started->body;
    const std::string id = std::to_string(json::parse(started->body)["job"].get<int>());
    json state;
    for (int i = 0; i < 600; ++i) {
        state = json::parse(viewer.client()->Get(viewer.with_token("/job?id=" + id).c_str())->body);
        if (state["state"] != "running") break;
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    ASSERT_EQ(state["state"], "failed") << state.dump();
    EXPECT_EQ(state["error"], "video encoder 'ffmpeg' not found on PATH; install the ffmpeg package (apt-get install ffmpeg)");
    EXPECT_FALSE(fs::exists(folder.file("tour.mp4")));
    EXPECT_TRUE(fs::exists(folder.file("tour.json")));
    EXPECT_EQ(viewer.stop(SIGTERM), 143);
}

// A one-triangle mesh scene in `folder`, its .mtl without a warning.
void write_mesh_scene(const TempFolder& folder) {
    folder.write("cube.obj", "mtllib cube.mtl\nusemtl red\nv -1 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    folder.write("cube.mtl", "newmtl red\nKd 1 0 0\n");
    folder.write("scene.json", R"({"eye": [0, 0, 5], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60,
        "width": 16, "height": 12, "obj": {"filename": "cube.obj"}})");
}

// The final state of a video of kTwoKeys that `viewer` makes of write_mesh_scene()'s scene once
// its .mtl names a texture the mesh does not draw (a warning; the video reads the meshes again).
json video_after_the_mtl_changed(const TempFolder& folder, const ViewerProcess& viewer) {
    folder.write("cube.mtl", "newmtl red\nKd 1 0 0\nmap_Kd wood.png\n");
    const httplib::Result started = post(viewer, "/render-video", kTwoKeys);
    EXPECT_TRUE(started && started->status == 200) << (started ? started->body : "no answer");
    if (!started || started->status != 200) return json();
    return finished_job(viewer, json::parse(started->body)["job"].get<int>());
}

// The video reads the meshes again: a .mtl edited since the viewer started may now give a
// warning (a texture the mesh does not draw). Under the viewer's --strict the video is refused,
// as `clrender --strict` refuses the scene; it was rendered without --strict, warning unseen.
TEST(ViewExport, AVideoUnderStrictIsRefusedForAWarningOfAFileChangedSinceTheStart) {
    TempFolder folder;
    write_mesh_scene(folder);
    ViewerProcess viewer("scene.json --strict", folder.path());
    ASSERT_TRUE(viewer.started()) << viewer.output();
    const json state = video_after_the_mtl_changed(folder, viewer);
    ASSERT_EQ(state["state"], "failed") << state.dump();
    EXPECT_NE(state["error"].get<std::string>().find("--strict makes warnings errors"), std::string::npos)
        << state.dump();
    EXPECT_FALSE(fs::exists(folder.file("tour.mp4")));
    EXPECT_EQ(viewer.stop(SIGTERM), 143);
}

// Without --strict the video is made, and the warning of the changed file is printed on the
// viewer's terminal, as a render prints it: it was seen nowhere, neither there nor in the page.
TEST(ViewExport, AVideosWarningsArePrintedByTheViewer) {
    TempFolder folder;
    write_mesh_scene(folder);
    ViewerProcess viewer("scene.json", folder.path());
    ASSERT_TRUE(viewer.started()) << viewer.output();
    const json state = video_after_the_mtl_changed(folder, viewer);
    ASSERT_EQ(state["state"], "done") << state.dump();
    EXPECT_NE(viewer.output().find("clrender: warning: ./tour.json: /obj/filename: OBJ '"), std::string::npos)
        << viewer.output();
    EXPECT_NE(viewer.output().find("this texture is not drawn"), std::string::npos) << viewer.output();
    EXPECT_EQ(viewer.stop(SIGTERM), 143);
}

// Four keys of a video that takes seconds at 640x360 and 64 samples: still rendering when the
// tests below act.
const std::string kLongVideo =
    R"({"keys": [{"eye": [-3, 2, 12], "lookat": [0, 1, 0]}, {"eye": [3, 1.5, 10], "lookat": [0, 1, 0]},
        {"eye": [5, 1.5, 10], "lookat": [0, 1, 0]}, {"eye": [7, 1.5, 10], "lookat": [0, 1, 0]}], "name": "long"})";

// The folder holds only kLongVideo's scene and the viewer's log: no video, no other scene.
void expect_only_the_long_videos_scene(const TempFolder& folder) {
    for (const auto& entry : fs::directory_iterator(folder.path())) {
        const std::string name = entry.path().filename().string();
        EXPECT_TRUE(name == "long.json" || name == "view-stderr.txt") << "left behind: " << name;
    }
}

// The demo at a size and sample count that make kLongVideo take seconds to render.
const std::string kSlowDemo = "'" + kDemo + "demo.json' --size 640x360 --spp 64";

// Asks `viewer` for kLongVideo; fails the test unless the video starts.
void start_long_video(ViewerProcess& viewer) {
    ASSERT_TRUE(viewer.started()) << viewer.output();
    const httplib::Result started = post(viewer, "/render-video", kLongVideo);
    ASSERT_TRUE(started);
    ASSERT_EQ(started->status, 200) << started->body;
}

TEST(ViewExport, StoppingTheViewerStopsTheVideoAndLeavesNoPartialFile) {
    TempFolder folder;
    ViewerProcess viewer(kSlowDemo, folder.path());
    ASSERT_NO_FATAL_FAILURE(start_long_video(viewer));
    const httplib::Result busy = post(viewer, "/render-video", kLongVideo);
    ASSERT_TRUE(busy);
    EXPECT_EQ(busy->status, 409) << "one video at a time";
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    EXPECT_EQ(viewer.stop(SIGTERM), 143) << viewer.output();
    expect_only_the_long_videos_scene(folder);
}

// A symbolic link made at the video's name while it renders (by another program, or another
// user who may write into --output-dir) is replaced by the video, as a file made there would
// be: the render wrote through it, replacing the file it led to, outside the output folder.
TEST(ViewExport, AVideoReplacesALinkMadeAtItsNameNotTheFileItLeadsTo) {
    TempFolder folder, elsewhere;
    elsewhere.write("holiday.mp4", "the user's own video");
    ViewerProcess viewer(kSlowDemo, folder.path());
    ASSERT_NO_FATAL_FAILURE(start_long_video(viewer));
    fs::create_symlink(elsewhere.file("holiday.mp4"), folder.file("long.mp4"));
    const json state = finished_job(viewer, 1);
    EXPECT_EQ(state["state"], "done") << state.dump();
    EXPECT_TRUE(read_bytes(elsewhere.file("holiday.mp4")) == "the user's own video") << "replaced by the video";
    EXPECT_FALSE(fs::is_symlink(folder.file("long.mp4")));
    EXPECT_GT(fs::file_size(folder.file("long.mp4")), 0u);
    EXPECT_EQ(viewer.stop(SIGTERM), 143);
}

// The processes whose parent is `parent`.
std::vector<pid_t> children_of(pid_t parent) {
    std::vector<pid_t> children;
    for (const testing::ProcessEntry& process : testing::process_table())
        if (process.parent == parent) children.push_back(process.pid);
    return children;
}

// Whether process `pid` still runs (a zombie has ended: it only waits to be collected).
bool runs(pid_t pid) { return testing::still_runs(testing::process_table(), pid); }

// The viewer killed outright (SIGKILL: the OOM killer, kill -9) cannot stop its video itself:
// the video's render, in a process group of its own, rendered on for as long as the video took
// and wrote it, for nobody. It stops with the viewer, removing its unfinished files.
TEST(ViewExport, AVideoStopsWhenTheViewerIsKilled) {
    TempFolder folder;
    ViewerProcess viewer(kSlowDemo, folder.path());
    ASSERT_NO_FATAL_FAILURE(start_long_video(viewer));
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    const std::vector<pid_t> renders = children_of(viewer.pid());
    ASSERT_EQ(renders.size(), 1u) << "the video's render";
    EXPECT_EQ(viewer.stop(SIGKILL), 128 + SIGKILL + 1000);
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (runs(renders[0]) && std::chrono::steady_clock::now() < give_up)
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    EXPECT_FALSE(runs(renders[0])) << "the render outlived the viewer by 10 s";
    expect_only_the_long_videos_scene(folder);
}

// Another program that may write into --output-dir (a shared folder) renames a scene of its own
// over the video's exported scene as soon as the viewer has written it: the render read the scene
// by its name and rendered the other one (31 frames here) into the video, job done. The render is
// handed the text the viewer wrote and checked (CLRENDER_SCENE_ON_STDIN), not the name.
TEST(ViewExport, AVideoRendersTheSceneTheViewerWroteNotOneRenamedOverIt) {
    TempFolder folder;
    folder.write(".other.json", R"({"up": [0, 1, 0], "fov_angle": 60, "width": 32, "height": 18, "spheres": [],
        "eyeLocations": [[0, 0, 5], [0, 0, 6]], "lookatLocations": [[0, 0, 0], [0, 0, 0]],
        "clrender": {"frames_per_segment": 30}})");
    ViewerProcess viewer("'" + kDemo + "demo.json' --size 32x18", folder.path());
    ASSERT_TRUE(viewer.started()) << viewer.output();
    std::atomic<bool> swapped{false};
    std::thread other_program([&] {
        const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(20);
        while (std::chrono::steady_clock::now() < give_up) {
            if (fs::exists(folder.file("tour.json"))) {
                fs::rename(folder.file(".other.json"), folder.file("tour.json"));
                swapped = true;
                return;
            }
            std::this_thread::sleep_for(std::chrono::microseconds(200));
        }
    });
    const httplib::Result started = post(viewer, "/render-video", kTwoKeys);
    other_program.join();
    ASSERT_TRUE(started);
    ASSERT_EQ(started->status, 200) << started->body;
    ASSERT_TRUE(swapped) << "the scene was never renamed over: the test tested nothing";
    const json state = finished_job(viewer, json::parse(started->body)["job"].get<int>());
    EXPECT_EQ(state["state"], "done") << state.dump();
    EXPECT_EQ(state["total"], 11) << "frames of the scene the viewer wrote (31: the other one's)";
    EXPECT_EQ(viewer.stop(SIGTERM), 143);
}

// Clicks on "Render video" while a video is being started or rendered are refused (409) before
// they write anything: four at once leave one scene, the video's.
TEST(ViewExport, ARefusedVideoWritesNothing) {
    TempFolder folder;
    ViewerProcess viewer("'" + kDemo + "demo.json' --size 640x360 --spp 64", folder.path());  // seconds to render
    ASSERT_TRUE(viewer.started()) << viewer.output();
    std::vector<int> statuses(4, 0);
    std::vector<std::thread> clicks;
    for (std::size_t c = 0; c < statuses.size(); ++c)
        clicks.emplace_back([&, c] {
            const httplib::Result result = post(viewer, "/render-video", kLongVideo);
            statuses[c] = result ? result->status : -1;
        });
    for (std::thread& click : clicks) click.join();
    EXPECT_EQ(std::count(statuses.begin(), statuses.end(), 200), 1);
    EXPECT_EQ(std::count(statuses.begin(), statuses.end(), 409), 3);
    EXPECT_EQ(viewer.stop(SIGTERM), 143) << viewer.output();
    expect_only_the_long_videos_scene(folder);
}

// One key makes a still, not a video: refused naming the keys, with nothing written, rather
// than a scene written for a job that then fails.
TEST(ViewExport, AVideoOfOneKeyIsRefusedAndWritesNothing) {
    TempFolder folder;
    ViewerProcess viewer("'" + kDemo + "demo.json' --size 32x18", folder.path());
    ASSERT_TRUE(viewer.started()) << viewer.output();
    const httplib::Result result =
        post(viewer, "/render-video", R"({"keys": [{"eye": [-3, 2, 12], "lookat": [0, 1, 0]}], "name": "still"})");
    ASSERT_TRUE(result);
    EXPECT_EQ(result->status, 400) << result->body;
    const json answer = json::parse(result->body);
    EXPECT_EQ(answer["parameter"], "keys");
    EXPECT_NE(answer["error"].get<std::string>().find("two or more keys"), std::string::npos) << result->body;
    EXPECT_EQ(viewer.stop(SIGTERM), 143) << viewer.output();
    for (const auto& entry : fs::directory_iterator(folder.path()))
        EXPECT_EQ(entry.path().filename(), "view-stderr.txt") << "left behind: " << entry.path();
}

// An --output-dir whose name begins with '-': the video's render gets its scene and video as
// paths, never as options.
TEST(ViewExport, AVideoRendersIntoAFolderNamedLikeAnOption) {
    TempFolder folder;
    fs::create_directories(folder.file("-out"));
    ViewerProcess viewer("'" + kDemo + "demo.json' --size 32x18 --output-dir=-out", folder.path());
    ASSERT_TRUE(viewer.started()) << viewer.output();
    const httplib::Result started = post(viewer, "/render-video", kTwoKeys);
    ASSERT_TRUE(started);
    ASSERT_EQ(started->status, 200) << started->body;
    EXPECT_EQ(json::parse(started->body)["file"], "-out/tour.mp4");
    const json state = finished_job(viewer, json::parse(started->body)["job"].get<int>());
    EXPECT_EQ(state["state"], "done") << state.dump();
    EXPECT_GT(fs::exists(folder.file("-out/tour.mp4")) ? fs::file_size(folder.file("-out/tour.mp4")) : 0u, 0u);
    EXPECT_EQ(viewer.stop(SIGTERM), 143);
}

}  // namespace
}  // namespace clr
