// --explain-pixel on a scene moved far from the origin, inside the documented ±1e15
// (docs/scene-format.md, Numeric ranges): the reference explains, relative to the eye as the
// kernels compute, the same texel as for the scene at the origin, and its bytes are the
// kernels' (docs/explain-pixel.md). Every position is a multiple of 1/8, so the moved scene is
// the same scene exactly (doubles near 1e15 are 1/8 apart).
#include <gtest/gtest.h>
#include <stb_image_write.h>

#include <cstdio>
#include <string>

#include "support/command.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

using testing::run_clrender;
using testing::TempFolder;

// 16x16 texels, each its own colour: red 16 * column, green 16 * row.
void write_texture(const TempFolder& folder) {
    unsigned char rgb[16 * 16 * 3];
    for (int row = 0; row < 16; ++row)
        for (int col = 0; col < 16; ++col) {
            unsigned char* texel = &rgb[(row * 16 + col) * 3];
            texel[0] = static_cast<unsigned char>(16 * col);
            texel[1] = static_cast<unsigned char>(16 * row);
            texel[2] = 77;
        }
    ASSERT_TRUE(stbi_write_png(folder.file("texels.png").c_str(), 16, 16, 3, rgb, 16 * 3));
}

std::string point(double x, double y, double z) {
    char text[100];
    std::snprintf(text, sizeof text, "[%.17g, %.17g, %.17g]", x, y, z);
    return text;
}

// A textured billboard behind a lit sphere, seen from 8 units away, all moved by (ox, oy, oz).
std::string scene_at(double ox, double oy, double oz) {
    const auto at = [&](double x, double y, double z) { return point(ox + x, oy + y, oz + z); };
    return R"({"eye": )" + at(0.5, 1.25, 8) + R"(, "lookat": )" + at(0, 0, 0) +
           R"(, "up": [0, 1, 0], "fov_angle": 50, "width": 160, "height": 120, "DefaultColor": [0.2, 0.3, 0.5],
  "SunLocation": )" + at(20, 30, 15) + R"(,
  "spheres": [{"center": )" + at(0, 0, 0) + R"(, "radius": 1, "ambient": [0.9, 0.4, 0.2]}],
  "billboards": [{"UpperLeft": )" + at(-4, 3, -3) + R"(, "LowerLeft": )" + at(-4, -2, -3) +
           R"(, "UpperRight": )" + at(4, 3, -3) + R"(, "filename": "texels.png"}]})";
}

// The text of the line that starts with `label`, from `label` to the line's end ("" if none).
std::string line_from(const std::string& text, const std::string& label) {
    const std::size_t start = text.find(label);
    if (start == std::string::npos) return "";
    return text.substr(start, text.find('\n', start) - start);
}

TEST(ExplainPixelFarFromOrigin, ExplainsTheTexelTheKernelsShow) {
    TempFolder folder;
    write_texture(folder);
    folder.write("origin.json", scene_at(0, 0, 0));
    const double far = 1e15 - 64;  // the sun, 30 units further, stays inside the range
    folder.write("far_x.json", scene_at(far, 0, 0));
    folder.write("far_diagonal.json", scene_at(-far, far, -far));
    folder.write("far_million.json", scene_at(1e6, -1e6, 1e6));
    for (const char* pixel : {"20,15", "131,22", "36,70"}) {
        SCOPED_TRACE(pixel);
        const auto origin = run_clrender("origin.json --explain-pixel " + std::string(pixel), folder.path());
        ASSERT_EQ(origin.exit_code, 0) << origin.output;
        const std::string texel = line_from(origin.output, "colour: texel (column ");
        ASSERT_FALSE(texel.empty()) << "the pixel must show the billboard's image\n" << origin.output;
        const std::string coordinates = line_from(origin.output, "t_hit = ((UL - o).n) / (d.n) = ");
        ASSERT_NE(coordinates.find("(alpha, beta)"), std::string::npos) << origin.output;
        const std::string coordinates_only = coordinates.substr(coordinates.find("(alpha, beta)"));
        for (const char* moved : {"far_x.json", "far_diagonal.json", "far_million.json"}) {
            SCOPED_TRACE(moved);
            const auto result = run_clrender(std::string(moved) + " --explain-pixel " + pixel, folder.path());
            ASSERT_EQ(result.exit_code, 0) << result.output;
            EXPECT_EQ(line_from(result.output, "colour: texel (column "), texel) << result.output;
            EXPECT_NE(result.output.find(coordinates_only), std::string::npos)
                << "the same billboard coordinates: " << coordinates_only << "\n" << result.output;
            EXPECT_EQ(line_from(result.output, "bytes the reference writes"),
                      line_from(origin.output, "bytes the reference writes"));
            EXPECT_NE(line_from(result.output, "bytes the OpenCL kernels write").find("(the same)"), std::string::npos)
                << result.output;
        }
    }
}

}  // namespace
}  // namespace clr
