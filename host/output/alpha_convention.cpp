#include "output/alpha_convention.h"

#include <cmath>

#include "core/display_bytes.h"

namespace clr {
namespace {

double snapped_coverage(float coverage, int samples) { return std::round(coverage * samples) / samples; }

// The colour of the samples that hit, weighted by their share: m - (1 - a) B (0 where none hit).
Vec3 premultiplied(const float* pixel, double coverage, const Vec3& background) {
    if (coverage == 0) return {0, 0, 0};
    const Vec3 mean{pixel[0], pixel[1], pixel[2]};
    if (coverage == 1) return mean;
    return mean - background * (1 - coverage);
}

void premultiply(Image& image, const Vec3& background, int samples) {
    for (std::size_t i = 0; i < image.linear.size(); i += 4) {
        float* pixel = &image.linear[i];
        const double coverage = snapped_coverage(pixel[3], samples);
        const Vec3 colour = premultiplied(pixel, coverage, background);
        pixel[0] = static_cast<float>(colour.x);
        pixel[1] = static_cast<float>(colour.y);
        pixel[2] = static_cast<float>(colour.z);
        pixel[3] = static_cast<float>(coverage);
    }
}

void straighten(Image& image, const Vec3& background, int samples) {
    for (std::size_t i = 0; i < image.linear.size(); i += 4) {
        const float* pixel = &image.linear[i];
        std::uint8_t* bytes = &image.rgba[i];
        const double coverage = snapped_coverage(pixel[3], samples);
        bytes[3] = display_byte(static_cast<float>(coverage));
        if (coverage == 0 || coverage == 1) continue;  // the display bytes as without --alpha
        const Vec3 colour = premultiplied(pixel, coverage, background) / coverage;
        bytes[0] = display_byte(static_cast<float>(colour.x));
        bytes[1] = display_byte(static_cast<float>(colour.y));
        bytes[2] = display_byte(static_cast<float>(colour.z));
    }
}

}  // namespace

void apply_alpha_convention(Image& image, ImageFormat format, const Vec3& background, int samples) {
    if (format == ImageFormat::Exr)
        premultiply(image, background, samples);
    else
        straighten(image, background, samples);
    image.write_alpha = true;
}

}  // namespace clr
