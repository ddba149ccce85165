// clrender compare through the real binary (docs/command-line.md, Comparing with an image):
// a batch render compared with the same scene is exit 0; one pixel changed by N+1 steps is
// exit 7 at tolerance N and 0 at N+1; the heat map marks that pixel; IMAGE missing, damaged,
// cut short or of another size is exit 2 naming it; -o over the scene or IMAGE is refused.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "output/image_writer.h"
#include "scene/image_loader.h"
#include "support/command.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using testing::read_bytes;
using testing::run_clrender;
using testing::TempFolder;

const std::string kScene = R"({
  "eye": [0, 1, 8], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 50,
  "width": 32, "height": 24, "SunLocation": [10, 20, 10], "DefaultColor": [0.1, 0.2, 0.4],
  "spheres": [{"center": [0, 0, 0], "radius": 1.5, "ambient": [0.9, 0.4, 0.2]},
              {"center": [2, 0.5, -1], "radius": 0.8, "ambient": [0.2, 0.8, 0.3]}]
})";
constexpr int kPixels = 32 * 24;

const std::string kAnimation = R"({
  "eyeLocations": [[-4, 1, 8], [4, 2, 7]], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 50,
  "width": 32, "height": 24, "clrender": {"frames": 3},
  "spheres": [{"center": [0, 0, 0], "radius": 1.5, "ambient": [0.9, 0.4, 0.2]},
              {"center": [2, 0.5, -1], "radius": 0.8, "ambient": [0.2, 0.8, 0.3]}]
})";

// A folder with the scene and its batch render, ref.png.
struct Rendered {
    TempFolder folder;
    Rendered() {
        folder.write("scene.json", kScene);
        const auto render = run_clrender("scene.json -q -o ref.png", folder.path());
        EXPECT_EQ(render.exit_code, 0) << render.output;
    }
};

// ref.png with pixel (x, y)'s channel c moved by `steps` (down from a bright value, up from a
// dark one), written as `name`.
void write_changed(const TempFolder& folder, const std::string& name, int x, int y, int c, int steps) {
    Image image = *load_image(folder.file("ref.png"));
    std::uint8_t& value = image.rgba[(static_cast<std::size_t>(y) * image.width + x) * 4 + c];
    value = static_cast<std::uint8_t>(value >= 128 ? value - steps : value + steps);
    write_image(folder.file(name), image);
}

// Runs clrender with standard output alone captured (standard error to stderr.txt).
testing::CommandResult run_for_stdout(const std::string& arguments, const TempFolder& folder) {
    const std::string command =
        "cd '" + folder.path() + "' && '" + CLRENDER_BINARY + "' " + arguments + " 2>stderr.txt";
    testing::CommandResult result;
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return result;
    std::array<char, 4096> buffer;
    std::size_t count;
    while ((count = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) result.output.append(buffer.data(), count);
    const int status = pclose(pipe);
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

TEST(CompareCli, TheBatchRenderOfTheSceneIsTheSame) {
    Rendered rendered;
    const auto compared = run_clrender("compare scene.json ref.png", rendered.folder.path());
    EXPECT_EQ(compared.exit_code, 0) << compared.output;
    EXPECT_NE(compared.output.find("differing: 0 of " + std::to_string(kPixels) + " pixels (0%)"), std::string::npos)
        << compared.output;
    EXPECT_NE(compared.output.find("largest difference: 0/255"), std::string::npos) << compared.output;
}

// One channel of one pixel changed by 3 steps: within --tolerance 3, beyond --tolerance 2.
TEST(CompareCli, ToleranceBoundary) {
    Rendered rendered;
    for (int c = 0; c < 3; ++c) {
        write_changed(rendered.folder, "changed.png", 11, 7, c, 3);
        const auto beyond = run_clrender("compare scene.json changed.png --tolerance 2", rendered.folder.path());
        EXPECT_EQ(beyond.exit_code, 7) << beyond.output;
        EXPECT_NE(beyond.output.find("differing: 1 of " + std::to_string(kPixels) + " pixels"), std::string::npos)
            << beyond.output;
        EXPECT_NE(beyond.output.find("  11,7: "), std::string::npos) << beyond.output;
        EXPECT_NE(beyond.output.find("(3/255)"), std::string::npos) << beyond.output;
        const auto within = run_clrender("compare scene.json changed.png --tolerance 3", rendered.folder.path());
        EXPECT_EQ(within.exit_code, 0) << within.output;
        EXPECT_NE(within.output.find("differing: 0 of"), std::string::npos) << within.output;
        EXPECT_NE(within.output.find("largest difference: 3/255"), std::string::npos) << within.output;
    }
}

TEST(CompareCli, JsonReport) {
    Rendered rendered;
    write_changed(rendered.folder, "changed.png", 30, 2, 1, 40);
    const auto compared = run_for_stdout("compare scene.json changed.png --json", rendered.folder);
    ASSERT_EQ(compared.exit_code, 7) << compared.output;
    const nlohmann::json report = nlohmann::json::parse(compared.output);
    EXPECT_EQ(report["differing"], 1);
    EXPECT_EQ(report["pixels"], kPixels);
    EXPECT_EQ(report["width"], 32);
    EXPECT_EQ(report["height"], 24);
    EXPECT_EQ(report["largest"], 40);
    ASSERT_EQ(report["largest_pixels"].size(), 1u);
    EXPECT_EQ(report["largest_pixels"][0]["x"], 30);
    EXPECT_EQ(report["largest_pixels"][0]["y"], 2);
    const Image ref = *load_image(rendered.folder.file("ref.png"));
    const Image changed = *load_image(rendered.folder.file("changed.png"));
    for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(report["largest_pixels"][0]["rendered"][c], ref.at(30, 2, c));
        EXPECT_EQ(report["largest_pixels"][0]["image"][c], changed.at(30, 2, c));
    }
    EXPECT_TRUE(report["heat_map"].is_null());
}

TEST(CompareCli, HeatMapMarksTheDifferingPixelsOnly) {
    Rendered rendered;
    write_changed(rendered.folder, "changed.png", 5, 9, 0, 255 / 2);
    const auto compared = run_clrender("compare scene.json changed.png -o maps/heat.png", rendered.folder.path());
    ASSERT_EQ(compared.exit_code, 7) << compared.output;
    const Image map = *load_image(rendered.folder.file("maps/heat.png"));  // its folder made, as for -o
    ASSERT_EQ(map.width, 32);
    ASSERT_EQ(map.height, 24);
    for (int y = 0; y < 24; ++y) {
        for (int x = 0; x < 32; ++x) {
            const bool grey = map.at(x, y, 0) == map.at(x, y, 1) && map.at(x, y, 1) == map.at(x, y, 2);
            if (x == 5 && y == 9) {
                EXPECT_FALSE(grey);  // 127 steps: between yellow (64) and red (255)
                EXPECT_EQ(map.at(x, y, 0), 255);
                EXPECT_EQ(map.at(x, y, 2), 0);
            } else {
                EXPECT_TRUE(grey && map.at(x, y, 0) <= 64) << x << "," << y;
            }
        }
    }
    // The same images compared again: the heat map is replaced, exit 0 when they are the same.
    const auto same = run_clrender("compare scene.json ref.png -o maps/heat.png", rendered.folder.path());
    EXPECT_EQ(same.exit_code, 0) << same.output;
    const Image quiet = *load_image(rendered.folder.file("maps/heat.png"));
    EXPECT_TRUE(quiet.at(5, 9, 0) == quiet.at(5, 9, 1) && quiet.at(5, 9, 1) == quiet.at(5, 9, 2));
}

TEST(CompareCli, AMissingImageIsAnInputError) {
    Rendered rendered;
    const auto compared = run_clrender("compare scene.json nowhere.png", rendered.folder.path());
    EXPECT_EQ(compared.exit_code, 2) << compared.output;
    EXPECT_NE(compared.output.find("clrender: error: nowhere.png: cannot read the image to compare with: no such file"),
              std::string::npos)
        << compared.output;
}

TEST(CompareCli, ADamagedOrTruncatedPngIsAnInputError) {
    Rendered rendered;
    const std::string png = read_bytes(rendered.folder.file("ref.png"));
    const std::size_t data = png.find("IDAT");
    ASSERT_NE(data, std::string::npos);
    std::string damaged = png;
    damaged[data + 20] = static_cast<char>(damaged[data + 20] ^ 0x01);  // one bit of the pixel data
    rendered.folder.write("damaged.png", damaged);
    // The pixel data intact, its chunk's CRC wrong: a decoder that skips checksums takes it.
    const std::size_t length = (static_cast<unsigned char>(png[data - 4]) << 24) |
                               (static_cast<unsigned char>(png[data - 3]) << 16) |
                               (static_cast<unsigned char>(png[data - 2]) << 8) | static_cast<unsigned char>(png[data - 1]);
    std::string bad_crc = png;
    bad_crc[data + 4 + length] = static_cast<char>(bad_crc[data + 4 + length] ^ 0x01);
    rendered.folder.write("bad_crc.png", bad_crc);
    rendered.folder.write("short.png", png.substr(0, png.size() / 2));
    rendered.folder.write("empty.png", "");
    rendered.folder.write("text.png", "not an image at all\n");
    fs::create_directory(rendered.folder.file("folder.png"));
    ASSERT_EQ(::mkfifo(rendered.folder.file("fifo.png").c_str(), 0600), 0);  // must not block the read
    for (const char* name : {"damaged.png", "bad_crc.png", "short.png", "empty.png", "text.png", "folder.png", "fifo.png"}) {
        const auto compared = run_clrender(std::string("compare scene.json ") + name, rendered.folder.path());
        EXPECT_EQ(compared.exit_code, 2) << name << ": " << compared.output;
        EXPECT_NE(compared.output.find(std::string("clrender: error: ") + name + ": cannot read the image"),
                  std::string::npos)
            << compared.output;
    }
}

TEST(CompareCli, AnImageOfAnotherSizeNamesBothSizes) {
    Rendered rendered;
    const auto small = run_clrender("scene.json -q --size 16x12 -o small.png", rendered.folder.path());
    ASSERT_EQ(small.exit_code, 0) << small.output;
    const auto compared = run_clrender("compare scene.json small.png", rendered.folder.path());
    EXPECT_EQ(compared.exit_code, 2) << compared.output;
    EXPECT_NE(compared.output.find("small.png: the image is 16x12, the render is 32x24"), std::string::npos)
        << compared.output;
    // --size makes the render the image's size.
    const auto sized = run_clrender("compare scene.json small.png --size 16x12", rendered.folder.path());
    EXPECT_EQ(sized.exit_code, 0) << sized.output;
}

TEST(CompareCli, PpmImagesAreCompared) {
    Rendered rendered;
    const auto ppm = run_clrender("scene.json -q -o ref.ppm", rendered.folder.path());
    ASSERT_EQ(ppm.exit_code, 0) << ppm.output;
    const auto compared = run_clrender("compare scene.json ref.ppm", rendered.folder.path());
    EXPECT_EQ(compared.exit_code, 0) << compared.output;
}

// Alpha is not compared: an --alpha render (RGB of the plain render where every sample hit or
// none did, with --spp 1) is the same in R, G and B, with a warning that alpha is ignored.
TEST(CompareCli, AlphaIsIgnoredWithAWarning) {
    Rendered rendered;
    const auto alpha = run_clrender("scene.json -q --alpha -o alpha.png", rendered.folder.path());
    ASSERT_EQ(alpha.exit_code, 0) << alpha.output;
    const auto compared = run_clrender("compare scene.json alpha.png", rendered.folder.path());
    EXPECT_EQ(compared.exit_code, 0) << compared.output;
    EXPECT_NE(compared.output.find("clrender: warning: alpha.png: the image has transparent pixels"), std::string::npos)
        << compared.output;
}

TEST(CompareCli, TheHeatMapNeverReplacesAnInput) {
    Rendered rendered;
    const std::string scene_before = read_bytes(rendered.folder.file("scene.json"));
    const std::string image_before = read_bytes(rendered.folder.file("ref.png"));
    for (const char* output : {"scene.json", "ref.png", "./ref.png"}) {
        const auto compared = run_clrender(std::string("compare scene.json ref.png -o ") + output, rendered.folder.path());
        EXPECT_EQ(compared.exit_code, output == std::string("scene.json") ? 1 : 4) << output << ": " << compared.output;
    }
    // A heat map named like the scene but with an image extension through a link to it.
    fs::create_symlink("scene.json", rendered.folder.file("link.png"));
    const auto linked = run_clrender("compare scene.json ref.png -o link.png", rendered.folder.path());
    EXPECT_EQ(linked.exit_code, 4) << linked.output;
    EXPECT_NE(linked.output.find("scene file"), std::string::npos) << linked.output;
    EXPECT_EQ(read_bytes(rendered.folder.file("scene.json")), scene_before);
    EXPECT_EQ(read_bytes(rendered.folder.file("ref.png")), image_before);
}

TEST(CompareCli, UsageErrors) {
    Rendered rendered;
    for (const char* arguments : {"compare", "compare scene.json", "compare scene.json ref.png --tolerance 256",
                                  "compare scene.json ref.png --tolerance -1", "compare scene.json ref.png --tolerance 1.5",
                                  "compare scene.json ref.png -o ''", "compare scene.json ''",
                                  "compare scene.json ref.png -o heat.exr", "compare scene.json ref.png -o heat.bmp",
                                  "compare scene.json ref.png --frames 0-1", "compare scene.json ref.png --bogus"}) {
        const auto compared = run_clrender(arguments, rendered.folder.path());
        EXPECT_EQ(compared.exit_code, 1) << arguments << ": " << compared.output;
        EXPECT_NE(compared.output.find("clrender: error: "), std::string::npos) << compared.output;
    }
    const auto help = run_clrender("compare --help", rendered.folder.path());
    EXPECT_EQ(help.exit_code, 0);
    EXPECT_NE(help.output.find("--tolerance"), std::string::npos) << help.output;
}

// --frames N compares frame N of a camera path with that frame's batch render, not another's.
TEST(CompareCli, OneFrameOfACameraPath) {
    TempFolder folder;
    folder.write("path.json", kAnimation);
    const auto frame = run_clrender("path.json -q --frames 1 -o f1.png", folder.path());
    ASSERT_EQ(frame.exit_code, 0) << frame.output;
    EXPECT_EQ(run_clrender("compare path.json f1.png --frames 1", folder.path()).exit_code, 0);
    const auto other = run_clrender("compare path.json f1.png --frames 2", folder.path());
    EXPECT_EQ(other.exit_code, 7) << other.output;
    const auto outside = run_clrender("compare path.json f1.png --frames 3", folder.path());
    EXPECT_EQ(outside.exit_code, 1) << outside.output;
}

// Ctrl-C while the render for a comparison runs: exit 130 at once, no heat map and no
// temporary file left, IMAGE untouched.
TEST(CompareCli, InterruptedWhileRenderingLeavesNothing) {
    TempFolder folder;
    folder.write("scene.json", kScene);
    std::string ppm = "P6\n800 600\n255\n";
    ppm.append(static_cast<std::size_t>(800) * 600 * 3, '\x40');
    folder.write("image.ppm", ppm);
    // The single-threaded reference at 64 samples a pixel takes many seconds for this size.
    const auto run = testing::run_clrender_interrupted(
        "compare scene.json image.ppm --reference --size 800x600 --spp 64 -o heat.png", folder.path(), 1);
    EXPECT_EQ(run.exit_code, 130) << run.output;
    EXPECT_NE(run.output.find("interrupted by SIGINT"), std::string::npos);
    EXPECT_EQ(folder.entry_count(), 2);  // scene and image: no heat map, no temporary file
    EXPECT_EQ(read_bytes(folder.file("image.ppm")), ppm);
}

}  // namespace
}  // namespace clr
