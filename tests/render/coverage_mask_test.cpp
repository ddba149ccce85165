// Coverage masks (render/coverage_mask.h): the packet kernel decides a billboard's holes from
// one bit per texel and reads a texel only for the winning hit. It must decide exactly as the
// texels' alpha does (only alpha 255 stops rays, docs/scene-format.md, Conventions:
// Billboards) for the edge alphas 0, 1, 254 and 255 and for the transparency of PNG tRNS
// chunks (a colour key, palette alphas), in every shading mode, and show the winner's texel.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include "render/compiled_scene.h"
#include "render/feature_set.h"
#include "scene/image_loader.h"
#include "support/keyed_png.h"
#include "support/render_helpers.h"
#include "support/scene_builder.h"

namespace clr {
namespace {

using Texel = std::array<std::uint8_t, 4>;
using testing::Rgb;

constexpr int kSize = 20;
constexpr std::uint8_t kEdgeAlphas[] = {0, 1, 254, 255};

// Texel (col, row) with the edge alpha that (col + 2 row) picks and a random colour.
std::shared_ptr<Image> edge_alpha_image(std::uint32_t seed) {
    std::mt19937 random(seed);
    return testing::make_image(kSize, kSize, [&random](int col, int row) {
        return Texel{std::uint8_t(random() & 255), std::uint8_t(random() & 255), std::uint8_t(random() & 255),
                     kEdgeAlphas[(col + 2 * row) % 4]};
    });
}

// An RGB PNG whose colour (10, 200, 30) is transparent: a third of its texels have it, some
// others differ from it in the last bit of blue only (and stay opaque).
std::shared_ptr<const Image> colour_keyed_image() {
    const Rgb key{10, 200, 30};
    std::vector<Rgb> rgb;
    for (int row = 0; row < kSize; ++row)
        for (int col = 0; col < kSize; ++col) {
            if ((col + row) % 3 == 0)
                rgb.push_back(key);
            else if ((col + row) % 3 == 1 && col % 2 == 0)
                rgb.push_back({10, 200, 31});
            else
                rgb.push_back({std::uint8_t(col * 12), std::uint8_t(row * 12), 90});
        }
    return load_image_from_bytes(testing::rgb_png_with_colour_key(kSize, kSize, rgb, key), "keyed.png");
}

// A palette PNG whose entries have the edge alphas 0, 1, 254, 255, and a fifth entry no tRNS
// alpha (opaque).
std::shared_ptr<const Image> palette_alpha_image() {
    std::vector<std::uint8_t> indices;
    for (int row = 0; row < kSize; ++row)
        for (int col = 0; col < kSize; ++col) indices.push_back(static_cast<std::uint8_t>((3 * col + row) % 5));
    const std::vector<Rgb> palette{{250, 0, 0}, {0, 250, 0}, {0, 0, 250}, {250, 250, 0}, {0, 250, 250}};
    return load_image_from_bytes(testing::palette_png_with_alphas(kSize, kSize, indices, palette, {0, 1, 254, 255}),
                                 "palette.png");
}

enum class Shading { Flat, Sun, Mirrors };

// Camera at distance D on +z with a 90 degree field of view: the front billboard at z = 0
// spans [-D, D]^2 and the back one at z = -1 spans [-(D + 1), D + 1]^2, so pixel (col, row)
// sees the centre of texel (col, row) of each. A sphere behind the eye, out of view, turns on
// the sun or the mirror path without changing a pixel (billboards are unlit).
Scene front_and_back(std::shared_ptr<const Image> front, std::shared_ptr<const Image> back, Shading shading) {
    const double D = 2, B = D + 1;
    Scene scene = testing::make_scene({0, 0, D}, {0, 0, 0}, {0, 1, 0}, 90, kSize, kSize);
    scene.background = {0.1, 0.2, 0.3};
    scene.billboards.push_back(testing::make_billboard({-D, D, 0}, {-D, -D, 0}, {D, D, 0}, {1, 0, 1}, front));
    scene.billboards.push_back(testing::make_billboard({-B, B, -1}, {-B, -B, -1}, {B, B, -1}, {0, 1, 1}, back));
    if (shading != Shading::Flat) {
        scene.spheres.push_back(testing::make_sphere({0, 0, D + 10}, 1, {1, 1, 1}, shading == Shading::Mirrors));
        scene.has_sun = true;
        scene.sun_location = {5, 20, 10};
    }
    return scene;
}

void expect_texel_colour(const Image& rendered, int col, int row, const Image& texels, const char* which) {
    for (int c = 0; c < 3; ++c)
        ASSERT_EQ(rendered.at(col, row, c), texels.at(col, row, c))
            << "pixel (" << col << ", " << row << ") channel " << c << " should show the " << which << " texel";
}

// Every pixel shows the front texel where its alpha is 255 and the back texel elsewhere, from
// the screen-tile kernel (coverage bits), the general brute-force kernel (texel alpha) and the
// reference alike, in each shading mode.
void expect_holes_exactly_below_alpha_255(std::shared_ptr<const Image> front) {
    auto back = edge_alpha_image(99);  // its holes only show the background: use an opaque copy
    for (std::size_t i = 3; i < back->rgba.size(); i += 4) back->rgba[i] = 255;
    int holes = 0;
    for (int row = 0; row < kSize; ++row)
        for (int col = 0; col < kSize; ++col) holes += front->at(col, row, 3) != 255;
    ASSERT_GT(holes, kSize) << "the front image must have holes";
    ASSERT_LT(holes, kSize * kSize - kSize) << "and opaque texels";

    for (Shading shading : {Shading::Flat, Shading::Sun, Shading::Mirrors}) {
        SCOPED_TRACE("shading " + std::to_string(static_cast<int>(shading)));
        Scene scene = front_and_back(front, back, shading);
        const FeatureSet features = FeatureSet::of(scene);
        ASSERT_TRUE(features.alpha && features.textures);
        ASSERT_EQ(features.sun, shading != Shading::Flat);
        ASSERT_EQ(features.mirrors, shading == Shading::Mirrors);

        Image tiles = testing::render_with_kernels(scene);
        for (int row = 0; row < kSize; ++row)
            for (int col = 0; col < kSize; ++col) {
                const bool opaque = front->at(col, row, 3) == 255;
                expect_texel_colour(tiles, col, row, opaque ? *front : *back, opaque ? "front" : "back");
            }
        RendererOptions brute_force;
        brute_force.features = FeatureSet::all();
        brute_force.screen_tiles = false;
        EXPECT_TRUE(tiles.rgba == testing::render_with_kernels(scene, brute_force).rgba);
        EXPECT_TRUE(tiles.rgba == testing::render_with_reference(scene).rgba);
    }
}

TEST(CoverageMask, EdgeAlphasDecideAsTheTexelAlpha) { expect_holes_exactly_below_alpha_255(edge_alpha_image(5)); }

TEST(CoverageMask, PngColourKeyMakesHolesOfExactlyThatColour) {
    auto keyed = colour_keyed_image();
    EXPECT_EQ(keyed->at(0, 0, 3), 0) << "the key colour decodes transparent";
    EXPECT_EQ(keyed->at(0, 1, 3), 255) << "a colour one off the key stays opaque";
    EXPECT_EQ(keyed->at(0, 1, 2), 31);
    expect_holes_exactly_below_alpha_255(keyed);
}

TEST(CoverageMask, PngPaletteAlphasDecideAsTheTexelAlpha) {
    auto palette = palette_alpha_image();
    EXPECT_EQ(palette->at(0, 2, 3), 254) << "palette entry 2's tRNS alpha";
    EXPECT_EQ(palette->at(0, 4, 3), 255) << "an entry past the tRNS alphas is opaque";
    expect_holes_exactly_below_alpha_255(palette);
}

// The host's bits: set exactly where the packed texel's alpha is 255, for two images that
// share a 32-bit word (35 and 33 texels), and no bit past the last texel.
TEST(CoverageMask, BitsMatchPackedTexelAlphasAcrossImagesAndWords) {
    auto first = testing::make_image(5, 7, [](int col, int row) { return Texel{1, 2, 3, kEdgeAlphas[(col + row) % 4]}; });
    auto second = testing::make_image(3, 11, [](int col, int row) {
        return Texel{4, 5, 6, kEdgeAlphas[(col * 3 + row) % 4]};
    });
    Scene scene = testing::make_scene({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 60, 8, 8);
    scene.billboards.push_back(testing::make_billboard({-1, 1, 0}, {-1, -1, 0}, {1, 1, 0}, {0, 0, 0}, first));
    scene.billboards.push_back(testing::make_billboard({-2, 1, -1}, {-2, -1, -1}, {0, 1, -1}, {0, 0, 0}, second));
    scene.billboards.push_back(testing::make_billboard({0, 1, -1}, {0, -1, -1}, {2, 1, -1}, {0, 0, 0}, first));
    FrameGeometry frame(scene);
    CompiledScene compiled = compile_scene(frame);
    const std::size_t texels = compiled.texels.size() / 4;
    ASSERT_EQ(texels, 35u + 33u) << "each image packed once";
    ASSERT_EQ(compiled.coverage.size(), 3u + CLR_COVERAGE_WINDOW_WORDS) << "the kernel's window read past the last word";
    for (std::size_t k = 0; k < compiled.coverage.size() * 32; ++k) {
        const bool bit = (compiled.coverage[k / 32] >> (k % 32)) & 1u;
        EXPECT_EQ(bit, k < texels && compiled.texels[4 * k + 3] == 255) << "texel " << k;
    }
}

// An image's coverage words as the packet kernel addresses them: its first and last word.
std::pair<std::uint32_t, std::uint32_t> coverage_words(const ClrBillboard& billboard) {
    const std::uint64_t texels = std::uint64_t(billboard.texture_width) * std::uint64_t(billboard.texture_height);
    return {billboard.texel_offset / 32, static_cast<std::uint32_t>((billboard.texel_offset + texels - 1) / 32)};
}

// The packet kernel reads an image's coverage bits as one window of CLR_COVERAGE_WINDOW_WORDS
// words when they lie within it, and gathers them word by word otherwise: images exactly as
// large as the window, smaller, straddling one word more and much larger all show the holes
// of their edge alphas as the reference and the general kernel (texel alphas) do, byte for
// byte. Each image spans as many pixels as it has texels, so every ray meets a texel's centre
// (float and double agree on which texel), over a one-colour backdrop.
TEST(CoverageMask, WindowedAndGatheredBitsDecideAsTheReference) {
    // Packed one after another: 1,600 texels end on a word's edge, 35 do not.
    const std::vector<std::pair<int, int>> sizes = {{40, 40}, {32, 32}, {5, 7}, {32, 32}, {3, 3}};
    const std::vector<int> first_columns = {1, 43, 77, 84, 118};
    const int width = 128, height = 48, top_row = 4;
    // 90 degrees across 128 columns from 64 units away: a pixel is one unit on the plane z = 0.
    Scene scene = testing::make_scene({0, 0, 64}, {0, 0, 0}, {0, 1, 0}, 90, width, height);
    scene.background = {0.1, 0.2, 0.3};
    for (std::size_t k = 0; k < sizes.size(); ++k) {
        std::mt19937 random(static_cast<std::uint32_t>(k) + 40);
        auto image = testing::make_image(sizes[k].first, sizes[k].second, [&random](int, int) {
            return Texel{std::uint8_t(random() & 255), std::uint8_t(random() & 255), std::uint8_t(random() & 255),
                         kEdgeAlphas[random() % 4]};
        });
        const double left = first_columns[k] - width / 2.0, top = height / 2.0 - top_row;
        scene.billboards.push_back(testing::make_billboard({left, top, 0}, {left, top - sizes[k].second, 0},
                                                           {left + sizes[k].first, top, 0}, {1, 0, 1}, image));
    }
    auto backdrop = testing::make_image(1, 1, [](int, int) { return Texel{60, 120, 200, 255}; });
    scene.billboards.push_back(testing::make_billboard({-80, 40, -1}, {-80, -40, -1}, {80, 40, -1}, {0, 1, 1}, backdrop));

    FrameGeometry frame(scene);
    const CompiledScene compiled = compile_scene(frame);
    std::vector<std::uint32_t> spans;
    for (std::size_t k = 0; k < sizes.size(); ++k) {
        auto [first, last] = coverage_words(compiled.billboards[k]);
        spans.push_back(last - first + 1);
    }
    EXPECT_GT(spans[0], CLR_COVERAGE_WINDOW_WORDS) << "gathered";
    EXPECT_EQ(spans[1], CLR_COVERAGE_WINDOW_WORDS) << "a 32x32 image from a word's start fills the window";
    EXPECT_LT(spans[2], CLR_COVERAGE_WINDOW_WORDS);
    EXPECT_EQ(spans[3], CLR_COVERAGE_WINDOW_WORDS + 1) << "the second 32x32 image starts mid-word: gathered";
    EXPECT_LT(spans[4], CLR_COVERAGE_WINDOW_WORDS) << "the last image with holes: its window reads the padding";

    const Image reference = testing::render_with_reference(scene);
    int holes = 0;
    for (int row = 0; row < height; ++row)
        for (int col = 0; col < width; ++col) holes += reference.at(col, row, 2) == 200;
    ASSERT_GT(holes, 2000) << "the backdrop shows around and through the images";
    const Image tiles = testing::render_with_kernels(scene);
    RendererOptions brute_force;
    brute_force.features = FeatureSet::all();
    brute_force.screen_tiles = false;
    EXPECT_TRUE(tiles.rgba == reference.rgba);
    EXPECT_TRUE(tiles.rgba == testing::render_with_kernels(scene, brute_force).rgba);
    for (std::size_t k = 0; k < sizes.size(); ++k)  // every texel shown, the holes included
        for (int row = 0; row < sizes[k].second; ++row)
            for (int col = 0; col < sizes[k].first; ++col) {
                const bool opaque = scene.billboards[k].image->at(col, row, 3) == 255;
                const int x = first_columns[k] + col, y = top_row + row;
                ASSERT_EQ(tiles.at(x, y, 2), opaque ? scene.billboards[k].image->at(col, row, 2) : 200)
                    << "image " << k << " texel (" << col << ", " << row << ")";
            }
}

}  // namespace
}  // namespace clr
