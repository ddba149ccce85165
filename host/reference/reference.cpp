// Reference frames: each pixel's samples traced in double, averaged, written as bytes. The
// sample positions are the one thing shared with the kernels (kernels/shared/clr_samples.h):
// they define where a pixel is looked at, not how a ray is traced.
#include "reference/reference.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "reference/eye_relative.h"
#include "reference/impostors.h"
#include "reference/trace_observer.h"
#include "shared/clr_samples.h"

namespace clr::reference {

std::uint8_t to_byte(double channel) {
    // NaN compares false with everything and would survive the clamp; show it as black
    // rather than let the cast below be undefined.
    if (std::isnan(channel)) return 0;
    const double scaled = std::clamp(channel, 0.0, 1.0) * 255.0;
    return static_cast<std::uint8_t>(std::floor(scaled + 0.5));  // round half up
}

namespace {

// The mean colour of the pixel's samples, at the positions the kernels use; with `coverage`,
// also the fraction of them whose primary ray hits an object.
Color pixel_color(const Scene& scene, const CameraFrame& camera, unsigned frame_seed, int col, int row,
                  TraceObserver* observer, double* coverage = nullptr) {
    const int samples = scene.sampling.samples_per_pixel;
    Color sum{0, 0, 0};
    int hits = 0;
    for (int sample = 0; sample < samples; ++sample) {
        double ox = clr_sample_offset_x(frame_seed, col, row, sample, samples);
        double oy = clr_sample_offset_y(frame_seed, col, row, sample, samples);
        const Ray ray = primary_ray_through(camera, col, row, ox, oy);
        if (coverage && intersect_in_view(scene, ray).kind != HitKind::None) ++hits;
        if (!observer) {
            sum = sum + trace(scene, ray);
            continue;
        }
        observer->sample_started(sample, samples, ox, oy, witness_direction(camera, col, row, ox, oy), ray);
        const Color colour = trace(scene, ray, observer);
        observer->sample_finished(sample, colour);
        sum = sum + colour;
    }
    if (coverage) *coverage = static_cast<double>(hits) / samples;
    return sum / samples;
}

unsigned frame_seed_of(const Scene& scene, int frame) {
    return clr_frame_seed(scene.sampling.seed, static_cast<unsigned>(frame));
}

Image render_frame(const Scene& scene, const CameraFrame& camera, int frame,
                   const std::function<void()>& between_rows, const std::optional<PixelRect>& crop, bool linear) {
    // Relative to the eye, as the kernels trace (reference/eye_relative.h); the moved camera's
    // eye is the origin, so this recurses once.
    if (camera.eye != Vec3(0, 0, 0)) {
        const EyeRelative relative = relative_to_eye(scene, camera);
        return render_frame(relative.scene, relative.camera, frame, between_rows, crop, linear);
    }
    // Impostors face this frame's eye; once placed they are billboards like any other, which
    // is all trace() knows about. The placed scene has no impostors, so this recurses once.
    if (!scene.impostors.empty())
        return render_frame(with_impostors_placed(scene, camera), camera, frame, between_rows, crop, linear);
    const unsigned frame_seed = frame_seed_of(scene, frame);
    const PixelRect region = crop.value_or(PixelRect{0, camera.width, 0, camera.height});
    Image image;
    image.width = region.width();
    image.height = region.height();
    image.rgba.resize(static_cast<std::size_t>(image.width) * image.height * 4);
    if (linear) image.linear.resize(image.rgba.size());
    for (int row = region.y0; row < region.y1; ++row) {
        if (between_rows) between_rows();
        for (int col = region.x0; col < region.x1; ++col) {
            double coverage = 0;
            const Color color = pixel_color(scene, camera, frame_seed, col, row, nullptr, linear ? &coverage : nullptr);
            const std::size_t offset = (static_cast<std::size_t>(row - region.y0) * image.width + (col - region.x0)) * 4;
            std::uint8_t* texel = &image.rgba[offset];
            texel[0] = to_byte(color.x);
            texel[1] = to_byte(color.y);
            texel[2] = to_byte(color.z);
            texel[3] = 255;
            if (!linear) continue;
            float* values = &image.linear[offset];
            values[0] = static_cast<float>(color.x);
            values[1] = static_cast<float>(color.y);
            values[2] = static_cast<float>(color.z);
            values[3] = static_cast<float>(coverage);
        }
    }
    return image;
}

}  // namespace

Color pixel_colour(const Scene& scene, const CameraFrame& camera, int frame, int col, int row,
                   TraceObserver* observer) {
    return pixel_color(scene, camera, frame_seed_of(scene, frame), col, row, observer);
}

Image render(const Scene& scene, const CameraFrame& camera, int frame, const std::function<void()>& between_rows,
             const std::optional<PixelRect>& crop) {
    return render_frame(scene, camera, frame, between_rows, crop, false);
}

Image render_linear(const Scene& scene, const CameraFrame& camera, int frame,
                    const std::function<void()>& between_rows, const std::optional<PixelRect>& crop) {
    return render_frame(scene, camera, frame, between_rows, crop, true);
}

}  // namespace clr::reference
