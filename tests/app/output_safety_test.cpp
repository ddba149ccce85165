// Every file clrender writes is a safe place to write, checked before anything renders: no
// output replaces the scene, a texture, a frame read back, or another output of the same run
// (compared by identity: hard and symbolic links too); symbolic links are written through;
// FIFOs and devices are refused without hanging; any legal file name works; a crashed run's
// temporary files are removed by the next run; and a failed write (a full disk) leaves every
// earlier file as it was. Each test runs the real binary.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <set>
#include <string>

#include "output/temp_files.h"
#include "scene/image_loader.h"
#include "support/command.h"
#include "support/small_disk.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using testing::read_bytes;
using testing::run_clrender;
using testing::TempFolder;

// A 2x2 PPM texture and a scene that shows it on a billboard behind a sphere.
const std::string kTexture = std::string("P6\n2 2\n255\n") + std::string(12, '\x40');
const std::string kTexturedScene = R"({
  "eye": [0, 0, 6], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60, "width": 16, "height": 12,
  "spheres": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "ambient": [1, 0, 0]}],
  "billboards": [{"type": "billboard", "UpperLeft": [-8, 6, -2], "LowerLeft": [-8, -6, -2],
                  "UpperRight": [8, 6, -2], "filename": "tex.ppm"}]
})";
const std::string kAnimatedScene = R"({
  "eyeLocations": [[-3, 1, 8], [3, 2, 7]], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 55,
  "width": 8, "height": 6, "clrender": {"frames_per_segment": 2},
  "spheres": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "ambient": [1, 0, 0]}]
})";
const std::string kOldImage = "an earlier image that must survive";

// A folder with the textured scene ("scene.json") and its texture ("tex.ppm").
struct SceneFolder {
    TempFolder folder;
    SceneFolder() {
        folder.write("scene.json", kTexturedScene);
        folder.write("tex.ppm", kTexture);
    }
    testing::CommandResult run(const std::string& arguments) const {
        // `timeout`: a FIFO that clrender opened would block it; the test must fail, not hang.
        return run_clrender(arguments + " --reference -q", folder.path(), "timeout 60");
    }
    bool inputs_unchanged() const {
        return read_bytes(folder.file("scene.json")) == kTexturedScene && read_bytes(folder.file("tex.ppm")) == kTexture;
    }
};

std::set<std::string> names_in(const std::string& folder) {
    std::set<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder)) names.insert(entry.path().filename().string());
    return names;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

void expect_refused(const testing::CommandResult& result, const std::string& output_role, const std::string& other_role) {
    EXPECT_EQ(result.exit_code, 4) << result.output;
    EXPECT_TRUE(contains(result.output, "the " + output_role + " would replace the " + other_role)) << result.output;
    EXPECT_EQ(result.output.rfind("clrender: error: ", 0), 0u) << result.output;
    EXPECT_EQ(result.output.find('\n'), result.output.size() - 1) << "one line: " << result.output;
}

// ---- Outputs that are inputs or other outputs ---------------------------------------------

TEST(OutputSafety, StatsNamingTheSceneIsRefused) {
    SceneFolder scene;
    expect_refused(scene.run("scene.json -o out.png --stats scene.json"), "--stats report", "scene file");
    EXPECT_TRUE(scene.inputs_unchanged());
    EXPECT_FALSE(fs::exists(scene.folder.file("out.png"))) << "refused before anything renders";
}

TEST(OutputSafety, OutputNamingTheSceneIsRefused) {
    TempFolder folder;
    folder.write("scene.ppm", kAnimatedScene);  // a scene file may have any name
    const auto result = run_clrender("scene.ppm -o scene.ppm --frames 0 --reference -q", folder.path());
    expect_refused(result, "image (-o)", "scene file");
    EXPECT_EQ(read_bytes(folder.file("scene.ppm")), kAnimatedScene);
}

TEST(OutputSafety, OutputNamingATextureIsRefused) {
    SceneFolder scene;
    expect_refused(scene.run("scene.json -o tex.ppm"), "image (-o)", "texture");
    fs::create_directory(scene.folder.file("sub"));
    expect_refused(scene.run("scene.json -o ./sub/../tex.ppm"), "image (-o)", "texture");
    EXPECT_TRUE(scene.inputs_unchanged());
}

// A mesh and its material are inputs too: --stats may name any file, and a PPM may be named
// what a user calls their model.
TEST(OutputSafety, OutputsNamingAMeshOrItsMaterialAreRefused) {
    TempFolder folder;
    const std::string obj = "mtllib look.mtl\nusemtl red\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    const std::string mtl = "newmtl red\nKd 1 0 0\n";
    folder.write("model.obj", obj);
    folder.write("look.mtl", mtl);
    folder.write("scene.json", R"({"eye": [0, 0, 6], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60,
        "width": 8, "height": 6, "obj": {"filename": "model.obj"}})");
    const auto run = [&](const std::string& arguments) {
        return run_clrender(arguments + " --reference -q", folder.path(), "timeout 60");
    };
    expect_refused(run("scene.json -o out.png --stats model.obj"), "--stats report", "mesh");
    expect_refused(run("scene.json -o out.png --stats ./look.mtl"), "--stats report", "mesh material");
    // Through a folder that does not exist yet: it would be made, and the report would land
    // on the mesh.
    expect_refused(run("scene.json -o model.obj.ppm --stats sub/../model.obj"), "--stats report", "mesh");
    expect_refused(run("scene.json -o new/../look.mtl.ppm --stats new/../look.mtl"), "--stats report", "mesh material");
    EXPECT_FALSE(fs::exists(folder.file("sub")));
    EXPECT_FALSE(fs::exists(folder.file("new")));
    EXPECT_EQ(read_bytes(folder.file("model.obj")), obj);
    EXPECT_EQ(read_bytes(folder.file("look.mtl")), mtl);
    EXPECT_FALSE(fs::exists(folder.file("out.png")));
}

// With --placeholders, a mesh that fails to load (here its .mtl has a bad Kd line) is drawn as
// a cube, but its files are still the scene's inputs: a report must not replace them.
TEST(OutputSafety, OutputsNamingAMeshThatFailedToLoadAreRefused) {
    TempFolder folder;
    const std::string obj = "mtllib look.mtl\nusemtl red\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    const std::string mtl = "newmtl red\nKd 1 0 0 0.5\n";
    folder.write("model.obj", obj);
    folder.write("look.mtl", mtl);
    folder.write("scene.json", R"({"eye": [0, 0, 6], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60,
        "width": 8, "height": 6, "obj": {"filename": "model.obj"}})");
    const auto run = [&](const std::string& arguments) {
        return run_clrender(arguments + " --placeholders --reference -q", folder.path(), "timeout 60");
    };
    for (const std::string check : {"", " --check"}) {
        const auto obj_report = run("scene.json -o out.png --stats model.obj" + check);
        EXPECT_EQ(obj_report.exit_code, 4) << obj_report.output;
        EXPECT_TRUE(contains(obj_report.output, "the --stats report would replace the mesh")) << obj_report.output;
        const auto mtl_report = run("scene.json -o out.png --stats look.mtl" + check);
        EXPECT_EQ(mtl_report.exit_code, 4) << mtl_report.output;
        EXPECT_TRUE(contains(mtl_report.output, "the --stats report would replace the mesh material")) << mtl_report.output;
    }
    // A missing .mtl is an input too: the report must not take its name.
    folder.write("model.obj", "mtllib gone.mtl\n" + obj);
    const auto missing = run("scene.json -o out.png --stats gone.mtl");
    EXPECT_EQ(missing.exit_code, 4) << missing.output;
    EXPECT_FALSE(fs::exists(folder.file("gone.mtl")));
    folder.write("model.obj", obj);
    EXPECT_EQ(read_bytes(folder.file("model.obj")), obj);
    EXPECT_EQ(read_bytes(folder.file("look.mtl")), mtl);
    EXPECT_FALSE(fs::exists(folder.file("out.png")));
}

// So is a model that clrender's own checks refuse (a corner out of range, no face with an area),
// with the texture its .mtl names: `-o wood.png` replaced the texture, and `--stats lib.mtl`
// the .mtl, of a model whose face named a missing position.
TEST(OutputSafety, OutputsNamingTheFilesOfAMeshThatFailedItsChecksAreRefused) {
    TempFolder folder;
    const std::string mtl = "newmtl red\nKd 1 0 0\nmap_Kd wood.png\n", texture = "PRECIOUS";
    folder.write("lib.mtl", mtl);
    folder.write("wood.png", texture);
    folder.write("scene.json", R"({"eye": [0, 0, 5], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60,
        "width": 8, "height": 6, "obj": {"filename": "model.obj"}})");
    const auto run = [&](const std::string& arguments) {
        return run_clrender(arguments + " --placeholders --reference -q", folder.path(), "timeout 60");
    };
    const auto expect_refused_with_a_cube = [&](const std::string& arguments, const std::string& refusal) {
        const auto result = run(arguments);
        EXPECT_EQ(result.exit_code, 4) << arguments << ": " << result.output;
        EXPECT_TRUE(contains(result.output, refusal)) << arguments << ": " << result.output;
    };
    for (const std::string face : {"f 1 2 9\n", "f 1 1 2\n"}) {
        folder.write("model.obj", "mtllib lib.mtl\nv -1 -1 0\nv 1 -1 0\nv 0 1 0\n" + face);
        expect_refused_with_a_cube("scene.json -o wood.png", "the image (-o) would replace the mesh texture");
        expect_refused_with_a_cube("scene.json -o out.png --stats lib.mtl",
                                   "the --stats report would replace the mesh material");
        expect_refused_with_a_cube("scene.json -o out.png --stats wood.png",
                                   "the --stats report would replace the mesh texture");
    }
    EXPECT_EQ(read_bytes(folder.file("lib.mtl")), mtl);
    EXPECT_EQ(read_bytes(folder.file("wood.png")), texture);
    EXPECT_FALSE(fs::exists(folder.file("out.png")));
}

// A mesh named "models/../m.obj" through a symbolic link `models` is the file the system
// opens (beside the link's target): that file is the input an output may not replace.
TEST(OutputSafety, AMeshNamedThroughALinkAndDotDotIsProtectedAsOpened) {
    TempFolder folder;
    const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    fs::create_directories(folder.file("elsewhere/models"));
    fs::create_directory_symlink(folder.file("elsewhere/models"), folder.file("models"));
    folder.write("elsewhere/m.obj", obj);
    folder.write("scene.json", R"({"eye": [0, 0, 6], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60,
        "width": 8, "height": 6, "obj": {"filename": "models/../m.obj"}})");
    const auto result = run_clrender("scene.json -o out.png --stats elsewhere/m.obj --reference -q", folder.path(), "timeout 60");
    expect_refused(result, "--stats report", "mesh");
    EXPECT_EQ(read_bytes(folder.file("elsewhere/m.obj")), obj);
}

TEST(OutputSafety, DefaultOutputNameNamingATextureIsRefused) {
    TempFolder folder;  // the scene tex.json: its default output is tex.png in the current folder
    const std::string texture = read_bytes(fs::path(CLRENDER_SOURCE_DIR) / "scenes/demo/checker.png");
    ASSERT_FALSE(texture.empty());
    std::string scene = kTexturedScene;
    scene.replace(scene.find("tex.ppm"), 7, "tex.png");
    folder.write("tex.json", scene);
    folder.write("tex.png", texture);
    const auto result = run_clrender("tex.json --reference -q", folder.path());
    expect_refused(result, "image (the default output name)", "texture");
    EXPECT_EQ(read_bytes(folder.file("tex.png")), texture);
}

TEST(OutputSafety, StatsNamingTheImageIsRefused) {
    SceneFolder scene;
    scene.folder.write("out.png", kOldImage);
    expect_refused(scene.run("scene.json -o out.png --stats out.png"), "--stats report", "image (-o)");
    expect_refused(scene.run("scene.json -o out.png --stats ./out.png"), "--stats report", "image (-o)");
    EXPECT_EQ(read_bytes(scene.folder.file("out.png")), kOldImage);
    // Neither exists yet: compared by normalised absolute path.
    expect_refused(scene.run("scene.json -o new.png --stats ../" + fs::path(scene.folder.path()).filename().string() +
                             "/new.png"),
                   "--stats report", "image (-o)");
    EXPECT_FALSE(fs::exists(scene.folder.file("new.png")));
}

TEST(OutputSafety, HardLinkToTheSceneIsRefused) {
    SceneFolder scene;
    ASSERT_EQ(::link(scene.folder.file("scene.json").c_str(), scene.folder.file("report.json").c_str()), 0);
    expect_refused(scene.run("scene.json -o out.png --stats report.json"), "--stats report", "scene file");
    ASSERT_EQ(::link(scene.folder.file("tex.ppm").c_str(), scene.folder.file("copy.ppm").c_str()), 0);
    expect_refused(scene.run("scene.json -o copy.ppm"), "image (-o)", "texture");
    EXPECT_TRUE(scene.inputs_unchanged());
    EXPECT_EQ(read_bytes(scene.folder.file("report.json")), kTexturedScene);
}

TEST(OutputSafety, SymbolicLinkToATextureIsRefused) {
    SceneFolder scene;
    fs::create_symlink("tex.ppm", scene.folder.file("alias.ppm"));
    expect_refused(scene.run("scene.json -o alias.ppm"), "image (-o)", "texture");
    fs::create_symlink("scene.json", scene.folder.file("alias.json"));
    expect_refused(scene.run("scene.json -o out.png --stats alias.json"), "--stats report", "scene file");
    EXPECT_TRUE(scene.inputs_unchanged());
    EXPECT_TRUE(fs::is_symlink(scene.folder.file("alias.ppm")));
}

TEST(OutputSafety, StatsNamingAFrameOfThePatternIsRefused) {
    TempFolder folder;
    folder.write("path.json", kAnimatedScene);
    const auto result = run_clrender("path.json -o f_%04d.png --stats f_0002.png --reference -q", folder.path());
    expect_refused(result, "--stats report", "frame 2 (-o)");
    EXPECT_EQ(names_in(folder.path()), std::set<std::string>{"path.json"}) << "no frame rendered";
}

TEST(OutputSafety, StatsNamingAFrameReadByAssembleIsRefused) {
    TempFolder folder;
    folder.write("path.json", kAnimatedScene);
    ASSERT_EQ(run_clrender("path.json -o f_%04d.png --reference -q", folder.path()).exit_code, 0);
    const std::string frame = read_bytes(folder.file("f_0001.png"));
    const auto result =
        run_clrender("path.json -o f_%04d.png --assemble --video v.gif --stats f_0001.png -q", folder.path());
    expect_refused(result, "--stats report", "frame 1 (read by --assemble)");
    EXPECT_EQ(read_bytes(folder.file("f_0001.png")), frame);
}

// ---- Targets that are not regular files ---------------------------------------------------

TEST(OutputSafety, SymbolicLinkIsWrittenThrough) {
    SceneFolder scene;
    fs::create_directory(scene.folder.file("renders"));
    scene.folder.write("renders/real.png", kOldImage);
    fs::create_symlink("renders/real.png", scene.folder.file("latest.png"));
    const auto result = scene.run("scene.json -o latest.png --stats stats.json");
    ASSERT_EQ(result.exit_code, 0) << result.output;
    ASSERT_TRUE(fs::is_symlink(scene.folder.file("latest.png"))) << "the link survives";
    EXPECT_EQ(fs::read_symlink(scene.folder.file("latest.png")), fs::path("renders/real.png"));
    const auto image = load_image(scene.folder.file("renders/real.png"));
    EXPECT_EQ(image->width, 16);
    EXPECT_EQ(names_in(scene.folder.file("renders")), std::set<std::string>{"real.png"}) << "no temporary file left";
    EXPECT_EQ(names_in(scene.folder.path()),
              (std::set<std::string>{"latest.png", "renders", "scene.json", "stats.json", "tex.ppm"}));
}

TEST(OutputSafety, DanglingSymbolicLinkIsRefused) {
    SceneFolder scene;
    fs::create_symlink("nowhere/real.png", scene.folder.file("latest.png"));
    const auto result = scene.run("scene.json -o latest.png");
    EXPECT_EQ(result.exit_code, 4) << result.output;
    EXPECT_TRUE(contains(result.output, "latest.png: is a symbolic link that cannot be followed")) << result.output;
    EXPECT_EQ(fs::read_symlink(scene.folder.file("latest.png")), fs::path("nowhere/real.png"));
}

TEST(OutputSafety, FifoIsRefusedWithoutHanging) {
    SceneFolder scene;
    ASSERT_EQ(::mkfifo(scene.folder.file("out.png").c_str(), 0644), 0);
    ASSERT_EQ(::mkfifo(scene.folder.file("stats.json").c_str(), 0644), 0);
    auto result = scene.run("scene.json -o out.png");
    EXPECT_EQ(result.exit_code, 4) << result.output;
    EXPECT_TRUE(contains(result.output, "out.png: is a named pipe (FIFO)")) << result.output;
    result = scene.run("scene.json -o image.png --stats stats.json");
    EXPECT_EQ(result.exit_code, 4) << result.output;
    EXPECT_TRUE(contains(result.output, "stats.json: is a named pipe (FIFO)")) << result.output;
    EXPECT_TRUE(fs::is_fifo(scene.folder.file("out.png")));
    EXPECT_TRUE(fs::is_fifo(scene.folder.file("stats.json")));
    EXPECT_FALSE(fs::exists(scene.folder.file("image.png"))) << "refused before anything renders";
}

// Never the system's /dev/null itself: a clrender without this check, run as root, would
// replace it with a regular file for the whole machine. A device node of the test's own, or
// a link to /dev/null (whose replacement would only replace the link).
TEST(OutputSafety, DevicesAreRefused) {
    SceneFolder scene;
    fs::create_symlink("/dev/null", scene.folder.file("null.png"));
    auto result = scene.run("scene.json -o null.png");
    EXPECT_EQ(result.exit_code, 4) << result.output;
    EXPECT_TRUE(contains(result.output, "null.png: is a symbolic link to a device")) << result.output;
    EXPECT_TRUE(fs::is_symlink(scene.folder.file("null.png")));
    if (::mknod(scene.folder.file("null.json").c_str(), S_IFCHR | 0666, makedev(1, 3)) != 0)
        GTEST_SKIP() << "cannot make a device node here (needs root): " << std::strerror(errno);
    result = scene.run("scene.json -o out.png --stats null.json");
    EXPECT_EQ(result.exit_code, 4) << result.output;
    EXPECT_TRUE(contains(result.output, "null.json: is a device")) << result.output;
    EXPECT_TRUE(fs::is_character_file(scene.folder.file("null.json")));
    EXPECT_FALSE(fs::exists(scene.folder.file("out.png")));
}

// ---- Names and temporary files ------------------------------------------------------------

TEST(OutputSafety, LongestLegalFileNameWorks) {
    SceneFolder scene;
    const std::string name = std::string(241, 'n') + ".png";  // 245 bytes: NAME_MAX is 255
    const auto result = scene.run("scene.json -o " + name + " --stats " + std::string(250, 's') + ".json");
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_EQ(load_image(scene.folder.file(name))->width, 16);
    EXPECT_EQ(names_in(scene.folder.path()).size(), 4u) << "scene, texture, image, stats and nothing else";
}

TEST(OutputSafety, LongestLegalVideoNameWorks) {
    if (std::system("command -v ffmpeg >/dev/null 2>&1") != 0) GTEST_SKIP() << "no ffmpeg";
    TempFolder folder;
    folder.write("path.json", kAnimatedScene);
    const std::string name = std::string(241, 'v') + ".gif";  // the encoder's temporary file and its log must fit too
    const auto result = run_clrender("path.json --video " + name + " --reference -q", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_GT(fs::file_size(folder.file(name)), 0u);
    EXPECT_EQ(names_in(folder.path()), (std::set<std::string>{"path.json", name}));
}

TEST(OutputSafety, VideoThroughASymbolicLinkKeepsTheLink) {
    if (std::system("command -v ffmpeg >/dev/null 2>&1") != 0) GTEST_SKIP() << "no ffmpeg";
    TempFolder folder;
    folder.write("path.json", kAnimatedScene);
    folder.write("real.gif", kOldImage);
    fs::create_symlink("real.gif", folder.file("latest.gif"));
    const auto result = run_clrender("path.json --video latest.gif --reference -q", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_TRUE(fs::is_symlink(folder.file("latest.gif")));
    EXPECT_EQ(read_bytes(folder.file("real.gif")).substr(0, 3), "GIF");
    EXPECT_EQ(names_in(folder.path()), (std::set<std::string>{"latest.gif", "path.json", "real.gif"}));
}

// A process id that is certainly not alive: a child that has exited and been reaped.
long dead_pid() {
    const pid_t child = ::fork();
    if (child == 0) ::_exit(0);
    ::waitpid(child, nullptr, 0);
    return child;
}

TEST(OutputSafety, NextRunRemovesTemporaryFilesOfDeadProcessesOnly) {
    SceneFolder scene;
    const std::string prefix = ".clrender-" + temp_host_id() + "-";
    const std::string dead = std::to_string(dead_pid());
    const std::string other_host = temp_host_id() == "00000000" ? "00000001" : "00000000";
    const std::set<std::string> stale = {prefix + dead + "-0.tmp", prefix + dead + "-7.tmp.log"};
    const std::set<std::string> foreign = {
        ".clrender-" + other_host + "-" + dead + "-0.tmp",     // another machine's: its pid means nothing here
        prefix + std::to_string(::getpid()) + "-0.tmp",         // a live process's
        prefix + dead + "-0.tmp.bak", "x" + prefix + dead + "-0.tmp", prefix + dead + ".tmp",
        ".out.png.tmp-" + dead + "-0",                          // not clrender's form
    };
    for (const std::string& name : stale) scene.folder.write(name, "left by a killed run");
    for (const std::string& name : foreign) scene.folder.write(name, "someone else's");
    fs::create_directory(scene.folder.file("sub"));
    scene.folder.write("sub/" + prefix + dead + "-1.tmp", "in a folder that gets no output");

    const auto result = scene.run("scene.json -o out.png");
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const std::set<std::string> names = names_in(scene.folder.path());
    for (const std::string& name : stale) EXPECT_EQ(names.count(name), 0u) << name;
    for (const std::string& name : foreign) EXPECT_EQ(read_bytes(scene.folder.file(name)), "someone else's") << name;
    EXPECT_TRUE(fs::exists(scene.folder.file("sub/" + prefix + dead + "-1.tmp")));
    EXPECT_TRUE(fs::exists(scene.folder.file("out.png")));
}

// ---- A full disk ------------------------------------------------------------------------

// The script's preamble: "disk" becomes a 512 KiB tmpfs holding the scene, the texture and an
// earlier image; then a file fills every free byte of it.
const char* kFullDisk =
    "mount -t tmpfs -o size=512k tmpfs disk; cp scene.json tex.ppm old.png disk/; "
    "(dd if=/dev/zero of=disk/filler bs=4096 2>/dev/null || true); ";

TEST(OutputSafety, ImageWriteOnAFullDiskFailsAndKeepsTheEarlierImage) {
    if (!testing::can_mount_small_disks()) GTEST_SKIP() << "cannot mount a small tmpfs here (needs root or unshare -rm)";
    SceneFolder scene;
    scene.folder.write("old.png", kOldImage);
    fs::create_directory(scene.folder.file("disk"));
    const int status = testing::run_in_mount_namespace(
        scene.folder.path(), std::string(kFullDisk) +
                                 "cd disk; code=0; \"$CLRENDER\" scene.json -o old.png --reference -q >../output 2>&1 || code=$?; "
                                 "echo $code >../exit_code; ls -A >../listing; cp old.png ../after.png");
    ASSERT_EQ(status, 0) << "the namespace script failed";
    EXPECT_EQ(read_bytes(scene.folder.file("exit_code")), "4\n") << read_bytes(scene.folder.file("output"));
    EXPECT_TRUE(contains(read_bytes(scene.folder.file("output")), "old.png: write failed: No space left on device"))
        << read_bytes(scene.folder.file("output"));
    EXPECT_EQ(read_bytes(scene.folder.file("after.png")), kOldImage);
    EXPECT_EQ(read_bytes(scene.folder.file("listing")), "filler\nold.png\nscene.json\ntex.ppm\n")
        << "no temporary file left";
}

TEST(OutputSafety, StatsWriteOnAFullDiskKeepsTheEarlierImage) {
    if (!testing::can_mount_small_disks()) GTEST_SKIP() << "cannot mount a small tmpfs here (needs root or unshare -rm)";
    SceneFolder scene;
    scene.folder.write("old.png", kOldImage);
    fs::create_directory(scene.folder.file("disk"));
    // The image goes to a folder with room, the stats to the full one: the image is written
    // completely, then the stats fail, and the image must not have been moved into place.
    const int status = testing::run_in_mount_namespace(
        scene.folder.path(), std::string(kFullDisk) +
                                 "code=0; \"$CLRENDER\" scene.json -o old.png --stats disk/stats.json --reference -q "
                                 ">output 2>&1 || code=$?; echo $code >exit_code; ls -A disk >listing");
    ASSERT_EQ(status, 0) << "the namespace script failed";
    EXPECT_EQ(read_bytes(scene.folder.file("exit_code")), "4\n") << read_bytes(scene.folder.file("output"));
    EXPECT_TRUE(contains(read_bytes(scene.folder.file("output")), "stats.json: write failed: No space left on device"))
        << read_bytes(scene.folder.file("output"));
    EXPECT_EQ(read_bytes(scene.folder.file("old.png")), kOldImage);
    EXPECT_EQ(read_bytes(scene.folder.file("listing")), "filler\nold.png\nscene.json\ntex.ppm\n");
    for (const std::string& name : names_in(scene.folder.path()))
        EXPECT_EQ(name.rfind(".clrender-", 0), std::string::npos) << "temporary file left: " << name;
}

}  // namespace
}  // namespace clr
