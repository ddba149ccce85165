// Image error metrics for the run-time-against-error benchmark.
//
// SSIM is written here by hand from the paper's definition: Debian packages no small C++
// library for it (OpenCV would do it, but is a large dependency for one function), and the
// formula is short.
#include "bench/error_metrics.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace clr::bench {
namespace {

constexpr int kChannels = 3;  // R, G, B; the alpha byte is skipped
constexpr double kSigma = 1.5;
constexpr double kC1 = (0.01 * 255) * (0.01 * 255);
constexpr double kC2 = (0.03 * 255) * (0.03 * 255);

void check_same_size(const Image& image, const Image& reference) {
    if (image.width <= 0 || image.height <= 0) throw std::invalid_argument("image error: empty image");
    if (image.width != reference.width || image.height != reference.height)
        throw std::invalid_argument("image error: the image is " + std::to_string(image.width) + "x" +
                                    std::to_string(image.height) + ", its reference " + std::to_string(reference.width) +
                                    "x" + std::to_string(reference.height));
}

// One channel as doubles, row by row.
using Plane = std::vector<double>;

Plane channel_of(const Image& image, int channel) {
    Plane plane(static_cast<std::size_t>(image.width) * image.height);
    for (std::size_t i = 0; i < plane.size(); ++i) plane[i] = image.rgba[i * 4 + channel];
    return plane;
}

// The 1D Gaussian whose outer product is SSIM's window, normalised to sum 1.
std::vector<double> gaussian_taps() {
    std::vector<double> taps(kSsimWindow);
    int half = kSsimWindow / 2;
    double sum = 0;
    for (int i = 0; i < kSsimWindow; ++i) sum += taps[i] = std::exp(-(i - half) * (i - half) / (2 * kSigma * kSigma));
    for (double& tap : taps) tap /= sum;
    return taps;
}

// The Gaussian-weighted mean of `plane` (width x height) over every window wholly inside it:
// a (width - 10) x (height - 10) plane. The window is separable, so rows then columns.
Plane window_means(const Plane& plane, int width, int height, const std::vector<double>& taps) {
    int out_w = width - kSsimWindow + 1, out_h = height - kSsimWindow + 1;
    Plane across(static_cast<std::size_t>(out_w) * height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < out_w; ++x) {
            double sum = 0;
            for (int k = 0; k < kSsimWindow; ++k) sum += taps[k] * plane[static_cast<std::size_t>(y) * width + x + k];
            across[static_cast<std::size_t>(y) * out_w + x] = sum;
        }
    Plane out(static_cast<std::size_t>(out_w) * out_h);
    for (int y = 0; y < out_h; ++y)
        for (int x = 0; x < out_w; ++x) {
            double sum = 0;
            for (int k = 0; k < kSsimWindow; ++k) sum += taps[k] * across[static_cast<std::size_t>(y + k) * out_w + x];
            out[static_cast<std::size_t>(y) * out_w + x] = sum;
        }
    return out;
}

Plane product(const Plane& a, const Plane& b) {
    Plane out(a.size());
    for (std::size_t i = 0; i < a.size(); ++i) out[i] = a[i] * b[i];
    return out;
}

// Mean SSIM of one channel: local means, variances and covariance from the windowed means
// of x, y, x^2, y^2 and xy, then the paper's formula at every window position.
double channel_ssim(const Plane& x, const Plane& y, int width, int height) {
    static const std::vector<double> taps = gaussian_taps();
    Plane mean_x = window_means(x, width, height, taps);
    Plane mean_y = window_means(y, width, height, taps);
    Plane mean_xx = window_means(product(x, x), width, height, taps);
    Plane mean_yy = window_means(product(y, y), width, height, taps);
    Plane mean_xy = window_means(product(x, y), width, height, taps);
    double sum = 0;
    for (std::size_t i = 0; i < mean_x.size(); ++i) {
        double mx = mean_x[i], my = mean_y[i];
        double var_x = mean_xx[i] - mx * mx, var_y = mean_yy[i] - my * my, cov = mean_xy[i] - mx * my;
        sum += (2 * mx * my + kC1) * (2 * cov + kC2) / ((mx * mx + my * my + kC1) * (var_x + var_y + kC2));
    }
    return sum / static_cast<double>(mean_x.size());
}

}  // namespace

double rmse(const Image& image, const Image& reference) {
    check_same_size(image, reference);
    std::size_t pixels = static_cast<std::size_t>(image.width) * image.height;
    double sum = 0;
    for (std::size_t i = 0; i < pixels; ++i)
        for (int c = 0; c < kChannels; ++c) {
            double d = static_cast<double>(image.rgba[i * 4 + c]) - reference.rgba[i * 4 + c];
            sum += d * d;
        }
    return std::sqrt(sum / static_cast<double>(pixels * kChannels));
}

double psnr_of_rmse(double rmse) {
    return rmse > 0 ? 20 * std::log10(255 / rmse) : std::numeric_limits<double>::infinity();
}

double ssim(const Image& image, const Image& reference) {
    check_same_size(image, reference);
    if (image.width < kSsimWindow || image.height < kSsimWindow)
        throw std::invalid_argument("image error: SSIM needs at least " + std::to_string(kSsimWindow) + "x" +
                                    std::to_string(kSsimWindow) + " pixels");
    double sum = 0;
    for (int c = 0; c < kChannels; ++c)
        sum += channel_ssim(channel_of(image, c), channel_of(reference, c), image.width, image.height);
    return sum / kChannels;
}

ImageError compare_to_reference(const Image& image, const Image& reference) {
    ImageError error;
    error.rmse = rmse(image, reference);
    error.psnr = psnr_of_rmse(error.rmse);
    error.ssim = ssim(image, reference);
    return error;
}

}  // namespace clr::bench
