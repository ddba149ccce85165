// An EXR and a PNG of one render agree through the sRGB transfer function (docs/command-line.md,
// HDR and alpha outputs), checked on files read back independently of clrender's code: the PNG
// with libpng's own reader, the EXR with OpenEXR's, and the rule written from IEC 61966-2-1
// (support/srgb_rule.h). Tolerance: none. The documented rule gives each PNG byte exactly, in
// float and in double, because clrender keeps every stored value 1/100 of a byte step from a
// rounding threshold, a hundred times float's error in srgb_encode.
#include <gtest/gtest.h>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfStandardAttributes.h>
#include <png.h>

#include <cmath>
#include <string>
#include <vector>

#include "support/command.h"
#include "support/srgb_rule.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

using testing::png_byte_of;
using testing::run_clrender;
using testing::srgb_encode;
using testing::TempFolder;

// Lit spheres (one brighter than the display's white: ambient 1.6), a mirror and a flat
// billboard before a visible background; --spp 4 averages samples into colours anywhere
// between the bytes and gives partly covered pixels along the silhouettes.
const char* kScene = R"({
  "eye": [1, 1, 9], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 50,
  "width": 64, "height": 48, "DefaultColor": [0.2, 0.3, 0.5], "SunLocation": [-10, 20, 10],
  "spheres": [{"center": [0, 0, 0], "radius": 1.5, "ambient": [1.6, 0.3, 0.2]},
              {"center": [-2, -1, 1], "radius": 0.7, "ambient": [0.1, 0.9, 0.45]},
              {"center": [2.2, 0.5, -1], "radius": 0.8, "ambient": [0, 0, 0], "IsMirror": 1}],
  "billboards": [{"UpperLeft": [-4, 3, -3], "LowerLeft": [-4, 0, -3], "UpperRight": [-1, 3, -3], "ambient": [0.9, 0.8, 0.1]}]
})";
constexpr int kWidth = 64, kHeight = 48;
constexpr std::size_t kValues = static_cast<std::size_t>(kWidth) * kHeight * 4;

struct Png {
    std::vector<std::uint8_t> rgba;  // 4 bytes a pixel; alpha 255 where the file has none
    bool has_alpha = false;
};

Png read_png(const std::string& path) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    Png png;
    if (!png_image_begin_read_from_file(&image, path.c_str())) {
        ADD_FAILURE() << path << ": " << image.message;
        return png;
    }
    EXPECT_EQ(image.width, static_cast<png_uint_32>(kWidth));
    EXPECT_EQ(image.height, static_cast<png_uint_32>(kHeight));
    png.has_alpha = (image.format & PNG_FORMAT_FLAG_ALPHA) != 0;
    image.format = PNG_FORMAT_RGBA;  // 8-bit sRGB in, 8-bit sRGB out: the bytes as stored
    png.rgba.resize(PNG_IMAGE_SIZE(image));
    if (!png_image_finish_read(&image, nullptr, png.rgba.data(), 0, nullptr)) {
        ADD_FAILURE() << path << ": " << image.message;
        png.rgba.clear();
    }
    return png;
}

struct Exr {
    std::vector<std::string> channels;
    std::vector<float> rgba;  // 4 floats a pixel; A is 1 where the file has none
    bool has_chromaticities = false;
    Imf::Chromaticities chromaticities;
};

Exr read_exr(const std::string& path) {
    Imf::InputFile file(path.c_str());
    Exr exr;
    const Imath::Box2i window = file.header().dataWindow();
    EXPECT_EQ(window.max.x - window.min.x + 1, kWidth);
    EXPECT_EQ(window.max.y - window.min.y + 1, kHeight);
    for (auto channel = file.header().channels().begin(); channel != file.header().channels().end(); ++channel) {
        exr.channels.push_back(channel.name());
        EXPECT_EQ(channel.channel().type, Imf::FLOAT) << channel.name();
    }
    exr.has_chromaticities = Imf::hasChromaticities(file.header());
    if (exr.has_chromaticities) exr.chromaticities = Imf::chromaticities(file.header());
    exr.rgba.assign(kValues, 0.0f);
    Imf::FrameBuffer frame;
    const char* names[] = {"R", "G", "B", "A"};
    char* base = reinterpret_cast<char*>(exr.rgba.data());
    for (int c = 0; c < 4; ++c)
        frame.insert(names[c], Imf::Slice(Imf::FLOAT, base + c * sizeof(float), 4 * sizeof(float),
                                          4 * sizeof(float) * kWidth, 1, 1, c == 3 ? 1.0 : 0.0));
    file.setFrameBuffer(frame);
    file.readPixels(window.min.y, window.max.y);
    return exr;
}

void expect_xy(const Imath::V2f& actual, float x, float y, const char* what) {
    EXPECT_NEAR(actual.x, x, 1e-6) << what;
    EXPECT_NEAR(actual.y, y, 1e-6) << what;
}

class ExrPngAgreement : public ::testing::TestWithParam<const char*> {
protected:
    void SetUp() override { folder_.write("scene.json", kScene); }
    // Renders with this test's renderer (the kernels, or --reference).
    void render(const std::string& arguments) {
        auto result = run_clrender("scene.json -q --spp 4 " + std::string(GetParam()) + arguments, folder_.path());
        ASSERT_EQ(result.exit_code, 0) << result.output;
    }
    TempFolder folder_;
};

TEST_P(ExrPngAgreement, ExrIsThePngsColoursInLinearLight) {
    render("-o plain.png");
    render("-o hdr.exr");
    const Png png = read_png(folder_.file("plain.png"));
    const Exr exr = read_exr(folder_.file("hdr.exr"));
    ASSERT_EQ(png.rgba.size(), kValues);
    EXPECT_FALSE(png.has_alpha);
    EXPECT_EQ(exr.channels, (std::vector<std::string>{"B", "G", "R"}));
    // sRGB's primaries and white point (IEC 61966-2-1, the same as Rec. 709's).
    ASSERT_TRUE(exr.has_chromaticities);
    expect_xy(exr.chromaticities.red, 0.64f, 0.33f, "red");
    expect_xy(exr.chromaticities.green, 0.30f, 0.60f, "green");
    expect_xy(exr.chromaticities.blue, 0.15f, 0.06f, "blue");
    expect_xy(exr.chromaticities.white, 0.3127f, 0.3290f, "white");

    int above_white = 0, mid_tones = 0;
    for (std::size_t i = 0; i < kValues; ++i) {
        if (i % 4 == 3) continue;
        const float v = exr.rgba[i];
        ASSERT_EQ(png_byte_of<float>(v), png.rgba[i]) << "value " << i << " = " << v << " in float";
        ASSERT_EQ(png_byte_of<double>(v), png.rgba[i]) << "value " << i << " = " << v << " in double";
        above_white += srgb_encode<double>(v) > 1.05;
        // Linear light, not the display value: byte 128 is about 0.216, not 0.5.
        if (png.rgba[i] > 20 && png.rgba[i] < 235) {
            ++mid_tones;
            ASSERT_LT(v, png.rgba[i] / 255.0f) << "value " << i << " is not in linear light";
        }
    }
    EXPECT_GT(above_white, 50) << "the 1.6-bright sphere stays above 1, unclamped";
    EXPECT_GT(mid_tones, 500);
}

TEST_P(ExrPngAgreement, AlphaExrIsTheAlphaPngPremultipliedInLinearLight) {
    render("--alpha -o alpha.png");
    render("--alpha -o alpha.exr");
    const Png png = read_png(folder_.file("alpha.png"));
    const Exr exr = read_exr(folder_.file("alpha.exr"));
    ASSERT_EQ(png.rgba.size(), kValues);
    EXPECT_TRUE(png.has_alpha);
    EXPECT_EQ(exr.channels, (std::vector<std::string>{"A", "B", "G", "R"}));
    int transparent = 0, partial = 0;
    for (std::size_t i = 0; i < kValues; i += 4) {
        const float a = exr.rgba[i + 3];
        ASSERT_EQ(png.rgba[i + 3], static_cast<int>(std::floor(a * 255 + 0.5))) << "pixel " << i / 4;
        if (a == 0) {
            ++transparent;
            for (int c = 0; c < 3; ++c) ASSERT_EQ(exr.rgba[i + c], 0.0f) << "premultiplied: no coverage, no colour";
            continue;
        }
        partial += a < 1;
        for (int c = 0; c < 3; ++c) {
            const float v = exr.rgba[i + c];
            ASSERT_EQ(png_byte_of<float>(v / a), png.rgba[i + c]) << "pixel " << i / 4 << " channel " << c << " in float";
            ASSERT_EQ(png_byte_of<double>(static_cast<double>(v) / a), png.rgba[i + c])
                << "pixel " << i / 4 << " channel " << c << " in double";
        }
    }
    EXPECT_GT(transparent, 100);
    EXPECT_GT(partial, 20) << "--spp 4 gives partly covered pixels";
}

INSTANTIATE_TEST_SUITE_P(Renderers, ExrPngAgreement, ::testing::Values("", "--reference "),
                         [](const ::testing::TestParamInfo<const char*>& info) {
                             return std::string(info.param).empty() ? "Kernels" : "Reference";
                         });

}  // namespace
}  // namespace clr
