// The error benchmark's image metrics against values worked out by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include "bench/error_metrics.h"
#include "bench/error_report.h"

namespace clr::bench {
namespace {

// A width x height opaque image whose pixel (col, row) has the RGB bytes pick(col, row).
template <typename Pick>
Image make_image(int width, int height, Pick pick) {
    Image image;
    image.width = width;
    image.height = height;
    for (int row = 0; row < height; ++row)
        for (int col = 0; col < width; ++col) {
            std::array<int, 3> rgb = pick(col, row);
            image.rgba.insert(image.rgba.end(), {std::uint8_t(rgb[0]), std::uint8_t(rgb[1]), std::uint8_t(rgb[2]), 255});
        }
    return image;
}

Image flat(int width, int height, int value) {
    return make_image(width, height, [value](int, int) { return std::array<int, 3>{value, value, value}; });
}

// A 0/200 chessboard of 2x2-pixel squares, in all three channels.
Image chessboard(int size) {
    return make_image(size, size, [](int col, int row) {
        int v = (col / 2 + row / 2) % 2 ? 200 : 0;
        return std::array<int, 3>{v, v, v};
    });
}

// `image` plus uniform noise in [-amplitude, amplitude] on every byte, clamped to 0..255.
Image with_noise(const Image& image, int amplitude, unsigned seed) {
    Image noisy = image;
    std::mt19937 generator(seed);
    std::uniform_int_distribution<int> noise(-amplitude, amplitude);
    for (std::size_t i = 0; i < noisy.rgba.size(); ++i)
        if (i % 4 != 3) noisy.rgba[i] = std::uint8_t(std::clamp(noisy.rgba[i] + noise(generator), 0, 255));
    return noisy;
}

TEST(ErrorMetrics, IdenticalImagesHaveNoError) {
    Image image = with_noise(chessboard(24), 40, 1);
    ImageError error = compare_to_reference(image, image);
    EXPECT_EQ(error.rmse, 0);
    EXPECT_EQ(error.psnr, std::numeric_limits<double>::infinity());
    EXPECT_DOUBLE_EQ(error.ssim, 1);
}

TEST(ErrorMetrics, AConstantOffsetIsTheRmse) {
    // Every byte 10 brighter: RMSE 10, PSNR 20 log10(25.5) = 28.1308 dB.
    ImageError error = compare_to_reference(flat(16, 16, 110), flat(16, 16, 100));
    EXPECT_DOUBLE_EQ(error.rmse, 10);
    EXPECT_NEAR(error.psnr, 28.1308, 1e-4);
}

TEST(ErrorMetrics, OneByteOffIsAveragedOverEveryChannelOfEveryPixel) {
    // One green byte of 16 pixels differs by 48: sqrt(48^2 / (16 * 3)) = sqrt(48).
    Image image = flat(4, 4, 50);
    Image reference = image;
    reference.rgba[(2 * 4 + 1) * 4 + 1] = 98;
    EXPECT_DOUBLE_EQ(rmse(image, reference), std::sqrt(48.0));
}

TEST(ErrorMetrics, AlphaIsIgnored) {
    Image image = flat(12, 12, 80);
    Image reference = image;
    for (std::size_t i = 3; i < reference.rgba.size(); i += 4) reference.rgba[i] = 0;
    EXPECT_EQ(rmse(image, reference), 0);
    EXPECT_DOUBLE_EQ(ssim(image, reference), 1);
}

TEST(ErrorMetrics, PsnrOfKnownRmses) {
    EXPECT_DOUBLE_EQ(psnr_of_rmse(255), 0);
    EXPECT_NEAR(psnr_of_rmse(25.5), 20, 1e-12);
    EXPECT_NEAR(psnr_of_rmse(2.55), 40, 1e-12);
    EXPECT_EQ(psnr_of_rmse(0), std::numeric_limits<double>::infinity());
}

TEST(ErrorMetrics, SsimOfFlatImagesIsTheLuminanceTerm) {
    // No variance and no covariance: SSIM = (2 a b + C1) / (a^2 + b^2 + C1), C1 = 2.55^2.
    double c1 = 2.55 * 2.55;
    double expected = (2 * 100.0 * 110.0 + c1) / (100.0 * 100.0 + 110.0 * 110.0 + c1);  // 0.995477
    EXPECT_NEAR(ssim(flat(16, 16, 100), flat(16, 16, 110)), expected, 1e-12);
    EXPECT_NEAR(expected, 0.995477, 1e-6);
}

TEST(ErrorMetrics, SsimOfAnInvertedPatternIsNegative) {
    // Anti-correlated structure: the covariance is minus the variance in every window.
    Image image = chessboard(20);
    Image inverted = make_image(20, 20, [&](int col, int row) {
        int v = 200 - image.at(col, row, 0);
        return std::array<int, 3>{v, v, v};
    });
    EXPECT_LT(ssim(image, inverted), 0);
}

TEST(ErrorMetrics, SsimOfANoisyImageIsBelowOneSymmetricAndFallsWithTheNoise) {
    Image clean = chessboard(32);
    Image slightly = with_noise(clean, 8, 2), very = with_noise(clean, 40, 3);
    double slight = ssim(slightly, clean);
    EXPECT_LT(slight, 1);
    EXPECT_GT(slight, 0.9);
    EXPECT_DOUBLE_EQ(ssim(clean, slightly), slight);
    EXPECT_LT(ssim(very, clean), slight);
    EXPECT_LT(rmse(slightly, clean), rmse(very, clean));
    EXPECT_DOUBLE_EQ(rmse(clean, very), rmse(very, clean));
}

TEST(ErrorMetrics, SsimSeesStructureThatRmseDoesNot) {
    // The same RMSE (10) from a uniform offset and from noise of +-10: SSIM barely notices the
    // offset, and minds the noise, which destroys structure in the flat image.
    Image reference = flat(16, 16, 128);
    Image offset = flat(16, 16, 138);
    Image noisy = make_image(16, 16, [](int col, int row) {
        int v = (col + row) % 2 ? 138 : 118;
        return std::array<int, 3>{v, v, v};
    });
    ASSERT_DOUBLE_EQ(rmse(offset, reference), rmse(noisy, reference));
    EXPECT_GT(ssim(offset, reference), 0.99);
    EXPECT_LT(ssim(noisy, reference), 0.5);
}

TEST(ErrorMetrics, MismatchedOrTooSmallImagesAreRejected) {
    EXPECT_THROW(rmse(flat(16, 16, 0), flat(16, 15, 0)), std::invalid_argument);
    EXPECT_THROW(ssim(flat(16, 16, 0), flat(15, 16, 0)), std::invalid_argument);
    EXPECT_THROW(rmse(Image{}, Image{}), std::invalid_argument);
    EXPECT_THROW(ssim(flat(kSsimWindow - 1, 16, 0), flat(kSsimWindow - 1, 16, 0)), std::invalid_argument);
    EXPECT_NO_THROW(ssim(flat(kSsimWindow, kSsimWindow, 0), flat(kSsimWindow, kSsimWindow, 0)));
}

// A measured setting with one timed frame of `ms` and an error of `rmse`.
ErrorRow row(bool double_precision, int spp, double ms, double rmse) {
    ErrorRow r;
    r.double_precision = double_precision;
    r.spp = spp;
    r.kernel_ms = {ms};
    r.wall_ms = {ms};
    r.error.rmse = rmse;
    r.error.psnr = psnr_of_rmse(rmse);
    return r;
}

TEST(ErrorMetrics, ParetoFrontKeepsOnlyUnbeatenSettings) {
    std::vector<ErrorRow> rows = {
        row(false, 1, 1.0, 8.0),   // fastest: on the front
        row(false, 4, 3.0, 2.0),   // on the front
        row(true, 4, 3.5, 2.0),    // slower than float at 4 spp and no more accurate
        row(true, 1, 1.2, 9.0),    // slower and worse than float at 1 spp
        row(false, 16, 9.0, 0.5),  // most accurate: on the front
        row(true, 16, 8.0, 0.5),   // as accurate and faster than float at 16 spp: beats it
        row(true, 2, 2.5, 4.0),      // more accurate than float at 2 spp by 0.01%: no better
        row(false, 2, 2.0, 4.0004),  // on the front
        row(true, 32, 20.0, 0.2),    // more accurate than float at 32 spp by 0.5%: on the front
        row(false, 32, 18.0, 0.201), // on the front
    };
    mark_pareto(rows);
    std::vector<bool> on_front;
    for (const ErrorRow& r : rows) on_front.push_back(r.pareto);
    EXPECT_EQ(on_front, (std::vector<bool>{true, true, false, false, false, true, false, true, true, true}));
}

TEST(ErrorMetrics, FastestSettingMeetingATarget) {
    SceneErrors scene;
    scene.rows = {row(false, 1, 1.0, 8.0), row(false, 4, 3.0, 2.0), row(true, 4, 3.5, 2.0), row(false, 16, 9.0, 0.5)};
    const ErrorRow* pick = fastest_meeting(scene, {ErrorTarget::Metric::Rmse, 2.0});
    ASSERT_NE(pick, nullptr);
    EXPECT_EQ(pick->spp, 4);
    EXPECT_FALSE(pick->double_precision);
    // PSNR >= 40 dB means RMSE <= 2.55: the same pick; 60 dB (RMSE <= 0.255) is out of reach.
    EXPECT_EQ(fastest_meeting(scene, {ErrorTarget::Metric::Psnr, 40}), pick);
    EXPECT_EQ(fastest_meeting(scene, {ErrorTarget::Metric::Psnr, 60}), nullptr);
    EXPECT_EQ(fastest_meeting(scene, {ErrorTarget::Metric::Psnr, 0})->spp, 1);
}

}  // namespace
}  // namespace clr::bench
