#include "output/alpha_convention.h"

#include <cmath>

#include "core/display_bytes.h"

namespace clr {
namespace {

double snapped_coverage(float coverage, int samples) { return std::round(coverage * samples) / samples; }

// The colour of the samples that hit alone: (m - (1 - a) B) / a, for 0 < a < 1.
Vec3 straight(const float* pixel, double coverage, const Vec3& background) {
    const Vec3 mean{pixel[0], pixel[1], pixel[2]};
    return (mean - background * (1 - coverage)) / coverage;
}

}  // namespace

void apply_alpha_convention(Image& image, const Vec3& background, int samples) {
    for (std::size_t i = 0; i < image.linear.size(); i += 4) {
        float* pixel = &image.linear[i];
        std::uint8_t* bytes = &image.rgba[i];
        const double coverage = snapped_coverage(pixel[3], samples);
        pixel[3] = static_cast<float>(coverage);
        bytes[3] = display_byte(pixel[3]);
        if (coverage == 0 || coverage == 1) continue;  // the colours and bytes as without --alpha
        const Vec3 colour = straight(pixel, coverage, background);
        pixel[0] = static_cast<float>(colour.x);
        pixel[1] = static_cast<float>(colour.y);
        pixel[2] = static_cast<float>(colour.z);
        for (int c = 0; c < 3; ++c) bytes[c] = display_byte(pixel[c]);
    }
    image.write_alpha = true;
}

}  // namespace clr
