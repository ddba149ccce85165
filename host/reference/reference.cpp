// Reference frames: one primary ray per pixel centre, traced in double, written as bytes.
#include "reference/reference.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace clr::reference {

std::uint8_t to_byte(double channel) {
    // NaN compares false with everything and would survive the clamp; show it as black
    // rather than let the cast below be undefined.
    if (std::isnan(channel)) return 0;
    const double scaled = std::clamp(channel, 0.0, 1.0) * 255.0;
    return static_cast<std::uint8_t>(std::floor(scaled + 0.5));  // round half up
}

Image render(const Scene& scene, const CameraFrame& camera) {
    Image image;
    image.width = camera.width;
    image.height = camera.height;
    image.rgba.resize(static_cast<std::size_t>(camera.width) * camera.height * 4);
    for (int row = 0; row < camera.height; ++row) {
        for (int col = 0; col < camera.width; ++col) {
            const Color color = trace(scene, primary_ray(camera, col, row));
            std::uint8_t* texel = &image.rgba[(static_cast<std::size_t>(row) * camera.width + col) * 4];
            texel[0] = to_byte(color.x);
            texel[1] = to_byte(color.y);
            texel[2] = to_byte(color.z);
            texel[3] = 255;
        }
    }
    return image;
}

}  // namespace clr::reference
