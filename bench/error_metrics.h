// How far a rendered image is from a reference image: RMSE, PSNR and SSIM on the 8-bit RGB
// channels (alpha is ignored; rendered frames are opaque).
#pragma once

#include "core/image.h"

namespace clr::bench {

// All three figures for one image against its reference.
struct ImageError {
    double rmse = 0;  // root mean square difference over every R, G and B value, on the 0..255 scale
    double psnr = 0;  // dB; +infinity for identical images
    double ssim = 1;  // mean structural similarity, 1 for identical images
};

// Each throws std::invalid_argument when the images differ in size or are empty.
double rmse(const Image& image, const Image& reference);

// 20 log10(255 / rmse): +infinity for rmse 0.
double psnr_of_rmse(double rmse);

// SSIM (Wang, Bovik, Sheikh and Simoncelli, 2004) with its usual settings: an 11x11 Gaussian
// window of sigma 1.5, C1 = (0.01 * 255)^2 and C2 = (0.03 * 255)^2, computed per channel
// wherever the window lies wholly inside the image and averaged over positions and the three
// channels. Symmetric in its arguments. Also throws std::invalid_argument for an image
// smaller than the window.
double ssim(const Image& image, const Image& reference);

// The side of SSIM's window, in pixels: the smallest image ssim() accepts.
constexpr int kSsimWindow = 11;

ImageError compare_to_reference(const Image& image, const Image& reference);

}  // namespace clr::bench
