// -o x.exr and --alpha through the real binary (docs/command-line.md, HDR and alpha outputs):
// the EXR read back with OpenEXR and the RGBA PNG read back, each against the double
// reference's colours and coverage, and against the plain PNG's bytes (the EXR through the
// sRGB transfer function; exr_png_agreement_test.cpp checks that rule value for value).
#include <gtest/gtest.h>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "reference/reference.h"
#include "scene/image_loader.h"
#include "scene/scene_loader.h"
#include "support/command.h"
#include "support/png_chunks.h"
#include "support/srgb_rule.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

using testing::png_byte_of;
using testing::read_bytes;
using testing::run_clrender;
using testing::srgb_encode;
using testing::TempFolder;

// Lit spheres, a mirror and a billboard in front of a visible background; --spp 4 gives
// partly covered pixels along the silhouettes.
const char* kScene = R"({
  "eye": [1, 1, 9], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 50,
  "width": 64, "height": 48, "DefaultColor": [0.2, 0.3, 0.5], "SunLocation": [-10, 20, 10],
  "spheres": [{"center": [0, 0, 0], "radius": 1.5, "ambient": [1, 0.3, 0.2]},
              {"center": [2.2, 0.5, -1], "radius": 0.8, "ambient": [0, 0, 0], "IsMirror": 1}],
  "billboards": [{"UpperLeft": [-4, 3, -3], "LowerLeft": [-4, 0, -3], "UpperRight": [-1, 3, -3], "ambient": [0.9, 0.8, 0.1]}]
})";
constexpr int kWidth = 64, kHeight = 48, kSamples = 4;

struct Exr {
    std::vector<std::string> channels;
    std::vector<float> rgba;  // 4 floats a pixel; A is 1 where the file has none
};

// Reads an EXR of width x height pixels (the scene's size unless a crop's).
Exr read_exr(const std::string& path, int width = kWidth, int height = kHeight) {
    Imf::InputFile file(path.c_str());
    Exr exr;
    const Imath::Box2i window = file.header().dataWindow();
    EXPECT_EQ(window.max.x - window.min.x + 1, width);
    EXPECT_EQ(window.max.y - window.min.y + 1, height);
    if (window.max.x - window.min.x + 1 != width || window.max.y - window.min.y + 1 != height) return exr;
    for (auto channel = file.header().channels().begin(); channel != file.header().channels().end(); ++channel) {
        exr.channels.push_back(channel.name());
        EXPECT_EQ(channel.channel().type, Imf::FLOAT) << channel.name();
    }
    exr.rgba.assign(static_cast<std::size_t>(width) * height * 4, 0.0f);
    Imf::FrameBuffer frame;
    const char* names[] = {"R", "G", "B", "A"};
    char* base = reinterpret_cast<char*>(exr.rgba.data());
    for (int c = 0; c < 4; ++c)
        frame.insert(names[c], Imf::Slice(Imf::FLOAT, base + c * sizeof(float), 4 * sizeof(float),
                                          4 * sizeof(float) * width, 1, 1, c == 3 ? 1.0 : 0.0));
    file.setFrameBuffer(frame);
    file.readPixels(window.min.y, window.max.y);
    return exr;
}

// The reference's linear colours and coverage of the scene as clrender loads it.
Image reference_of(const std::string& scene_path) {
    LoadOptions options;
    options.samples_override = kSamples;
    Scene scene = load_scene(scene_path, options);
    return reference::render_linear(scene, reference::camera_of(scene, scene.camera_path.front()));
}

float at(const std::vector<float>& values, int col, int row, int c) {
    return values[(static_cast<std::size_t>(row) * kWidth + col) * 4 + c];
}

// Off the silhouettes: the reference's coverage and red are the same in all 8 neighbours.
bool interior(const Image& reference, int col, int row) {
    if (col == 0 || row == 0 || col + 1 == kWidth || row + 1 == kHeight) return false;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
            for (int c : {0, 3})
                if (at(reference.linear, col + dx, row + dy, c) != at(reference.linear, col, row, c)) return false;
    return true;
}


class HdrAlphaCli : public ::testing::Test {
protected:
    void SetUp() override { folder_.write("scene.json", kScene); }
    void render(const std::string& arguments) {
        auto result = run_clrender("scene.json -q --spp 4 " + arguments, folder_.path());
        ASSERT_EQ(result.exit_code, 0) << result.output;
        EXPECT_TRUE(result.output.empty()) << result.output;
    }
    TempFolder folder_;
};

TEST_F(HdrAlphaCli, ExrHoldsTheReferencesLinearColoursAndThePngsBytes) {
    render("-o plain.png");
    render("-o hdr.exr");
    const Exr exr = read_exr(folder_.file("hdr.exr"));
    EXPECT_EQ(exr.channels, (std::vector<std::string>{"B", "G", "R"}));
    auto png = load_image(folder_.file("plain.png"));
    for (std::size_t i = 0; i < exr.rgba.size(); ++i) {
        if (i % 4 == 3) continue;
        ASSERT_EQ(png_byte_of<float>(exr.rgba[i]), png->rgba[i]) << "value " << i << ": " << exr.rgba[i];
    }
    const Image reference = reference_of(folder_.file("scene.json"));
    int compared = 0;
    for (int row = 0; row < kHeight; ++row)
        for (int col = 0; col < kWidth; ++col) {
            if (!interior(reference, col, row)) continue;
            ++compared;
            // The EXR in linear light, the reference's colours display values; the EXR may keep a
            // value up to 1/100 of a byte step from a rounding threshold (docs/command-line.md).
            for (int c = 0; c < 3; ++c)
                ASSERT_NEAR(srgb_encode<double>(at(exr.rgba, col, row, c)), at(reference.linear, col, row, c),
                            1e-4 + 0.01 / 255)
                    << "(" << col << ", " << row << ") channel " << c;
        }
    EXPECT_GT(compared, kWidth * kHeight / 2);
}

TEST_F(HdrAlphaCli, AlphaPngIsStraightRgbaWithTheReferencesCoverage) {
    render("-o plain.png");
    render("--alpha -o alpha.png");
    const std::string bytes = read_bytes(folder_.file("alpha.png"));
    ASSERT_GT(bytes.size(), 26u);
    EXPECT_EQ(bytes[25], 6) << "PNG colour type: RGBA";
    auto plain = load_image(folder_.file("plain.png"));
    auto alpha = load_image(folder_.file("alpha.png"));
    const Image reference = reference_of(folder_.file("scene.json"));
    int transparent = 0, opaque = 0, partial = 0;
    for (int row = 0; row < kHeight; ++row)
        for (int col = 0; col < kWidth; ++col) {
            const int a = alpha->at(col, row, 3);
            transparent += a == 0;
            opaque += a == 255;
            partial += a > 0 && a < 255;
            if (a == 0 || a == 255) {  // straight alpha: RGB as without --alpha
                for (int c = 0; c < 3; ++c) ASSERT_EQ(alpha->at(col, row, c), plain->at(col, row, c));
            }
            if (!interior(reference, col, row)) continue;
            const float coverage = at(reference.linear, col, row, 3);
            ASSERT_EQ(a, static_cast<int>(std::lround(coverage * 255))) << "(" << col << ", " << row << ")";
        }
    EXPECT_GT(transparent, 0);
    EXPECT_GT(opaque, 0);
    EXPECT_GT(partial, 0) << "--spp 4 must give partly covered pixels";
    EXPECT_EQ(alpha->at(0, 0, 3), 0) << "a corner sees only the background";
    EXPECT_EQ(alpha->at(kWidth / 2, kHeight / 2, 3), 255) << "the centre is on the sphere";
}

TEST_F(HdrAlphaCli, AlphaExrIsPremultipliedWithTheReferencesCoverage) {
    render("-o hdr.exr");
    render("--alpha -o alpha.exr");
    const Exr plain = read_exr(folder_.file("hdr.exr"));
    const Exr alpha = read_exr(folder_.file("alpha.exr"));
    EXPECT_EQ(alpha.channels, (std::vector<std::string>{"A", "B", "G", "R"}));
    const Image reference = reference_of(folder_.file("scene.json"));
    const float background[] = {0.2f, 0.3f, 0.5f};
    for (int row = 0; row < kHeight; ++row)
        for (int col = 0; col < kWidth; ++col) {
            const float a = at(alpha.rgba, col, row, 3);
            ASSERT_EQ(a * kSamples, std::round(a * kSamples)) << "coverage counts whole samples";
            for (int c = 0; c < 3; ++c) {  // premultiplied in linear light: the mean less the background's share
                const double value = at(alpha.rgba, col, row, c);
                if (a == 0) {
                    ASSERT_EQ(value, 0.0) << "(" << col << ", " << row << ")";
                    continue;
                }
                const double mean = srgb_encode<double>(at(plain.rgba, col, row, c));
                ASSERT_NEAR(srgb_encode(value / a) * a, mean - (1 - a) * background[c], 1e-4)
                    << "(" << col << ", " << row << ")";
            }
            if (interior(reference, col, row)) {
                ASSERT_EQ(a, at(reference.linear, col, row, 3));
            }
        }
    EXPECT_EQ(at(alpha.rgba, 0, 0, 0), 0.0f) << "no object, no colour";
}

TEST_F(HdrAlphaCli, ReferenceRendererWritesTheSameCoverage) {
    render("--alpha -o kernels.exr");
    render("--reference --alpha -o reference.exr");
    const Exr kernels = read_exr(folder_.file("kernels.exr"));
    const Exr reference = read_exr(folder_.file("reference.exr"));
    int differing = 0;
    for (std::size_t i = 3; i < kernels.rgba.size(); i += 4) differing += kernels.rgba[i] != reference.rgba[i];
    EXPECT_LT(differing, kWidth * kHeight / 20) << "only silhouette pixels may differ";
}

// Crops (docs/command-line.md, Crop): one of whole rows, and one whose columns start and end
// inside screen tiles (16 pixels), so the kernels' global offset is exercised.
struct Crop {
    int x0, x1, y0, y1;
    std::string argument() const {
        return std::to_string(x0) + "," + std::to_string(x1) + "," + std::to_string(y0) + "," + std::to_string(y1);
    }
    int width() const { return x1 - x0; }
    int height() const { return y1 - y0; }
};
const Crop kCrops[] = {{13, 45, 7, 40}, {0, kWidth, 5, 29}};

// The values of `crop`'s pixels in an image of the full frame (4 values a pixel).
template <typename Value>
std::vector<Value> rectangle_of(const std::vector<Value>& full, const Crop& crop) {
    std::vector<Value> values;
    for (int row = crop.y0; row < crop.y1; ++row)
        for (int col = crop.x0; col < crop.x1; ++col)
            for (int c = 0; c < 4; ++c) values.push_back(full[(static_cast<std::size_t>(row) * kWidth + col) * 4 + c]);
    return values;
}

TEST_F(HdrAlphaCli, CropOfAnExrIsTheFullFramesRectangle) {
    for (const char* renderer : {"", "--reference "}) {
        for (const char* alpha : {"", "--alpha "}) {
            const std::string options = std::string(renderer) + alpha;
            SCOPED_TRACE(options);
            render(options + "-o full.exr");
            const Exr full = read_exr(folder_.file("full.exr"));
            for (const Crop& crop : kCrops) {
                SCOPED_TRACE(crop.argument());
                render(options + "--crop " + crop.argument() + " -o crop.exr");
                const Exr cropped = read_exr(folder_.file("crop.exr"), crop.width(), crop.height());
                EXPECT_EQ(cropped.channels, full.channels);
                ASSERT_EQ(cropped.rgba, rectangle_of(full.rgba, crop)) << "value for value, coverage included";
            }
        }
    }
}

TEST_F(HdrAlphaCli, CropOfAnAlphaPngIsTheFullFramesRectangle) {
    for (const char* renderer : {"", "--reference "}) {
        SCOPED_TRACE(renderer);
        render(std::string(renderer) + "--alpha -o full.png");
        const auto full = load_image(folder_.file("full.png"));
        for (const Crop& crop : kCrops) {
            SCOPED_TRACE(crop.argument());
            render(std::string(renderer) + "--alpha --crop " + crop.argument() + " -o crop.png");
            const std::string bytes = read_bytes(folder_.file("crop.png"));
            ASSERT_GT(bytes.size(), 26u);
            EXPECT_EQ(bytes[25], 6) << "PNG colour type: RGBA";
            const auto cropped = load_image(folder_.file("crop.png"));
            ASSERT_EQ(cropped->width, crop.width());
            ASSERT_EQ(cropped->height, crop.height());
            ASSERT_EQ(cropped->rgba, rectangle_of(full->rgba, crop)) << "alpha included";
        }
    }
}

TEST_F(HdrAlphaCli, AlphaPngCarriesThePngMetadata) {
    render("--alpha -o alpha.png");
    const testing::PngDescription description = testing::read_png_description(folder_.file("alpha.png"));
    ASSERT_TRUE(description.readable);
    EXPECT_EQ(description.srgb_intent, 0) << "perceptual";
    EXPECT_EQ(description.text.at("Scene"), "scene.json");
    EXPECT_EQ(description.text.at("Size"), "64x48");
    EXPECT_EQ(description.text.at("Samples per pixel"), "4");
}

TEST(HdrAlphaCliAnimation, FramesOfAnAnimationAsExr) {
    TempFolder folder;
    folder.write("path.json", R"({
      "eyeLocations": [[-3, 1, 8], [3, 2, 7]], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 55,
      "width": 64, "height": 48, "DefaultColor": [0.1, 0.1, 0.2],
      "spheres": [{"center": [0, 0, 0], "radius": 1.5, "ambient": [1, 0.3, 0.2]}]})");
    auto result = run_clrender("path.json -q --frames 0,10 -o f_%04d.exr --video v.mp4", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const Exr first = read_exr(folder.file("f_0000.exr"));
    const Exr last = read_exr(folder.file("f_0010.exr"));
    EXPECT_NE(first.rgba, last.rgba);
    EXPECT_TRUE(std::filesystem::is_regular_file(folder.file("v.mp4"))) << "the video from the display colours";
}

TEST(HdrAlphaCliHelp, HelpNamesAlphaAndExr) {
    auto result = run_clrender("--help");
    EXPECT_NE(result.output.find("--alpha"), std::string::npos);
    EXPECT_NE(result.output.find(".exr"), std::string::npos);
}

}  // namespace
}  // namespace clr
