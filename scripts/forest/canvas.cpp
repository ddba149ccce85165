#include "scripts/forest/canvas.h"

#include <stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace forest {

namespace {

std::uint8_t to_byte(double value) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(value, 0.0, 1.0) * 255.0));
}

}  // namespace

Rgba opaque(const Colour& colour) { return {to_byte(colour.x), to_byte(colour.y), to_byte(colour.z), 255}; }

Colour lerp(const Colour& from, const Colour& to, double t) { return from + (to - from) * t; }

void save_png(const std::string& path, const Canvas& canvas, bool keep_alpha) {
    const int channels = keep_alpha ? 4 : 3;
    std::vector<std::uint8_t> bytes;
    bytes.reserve(canvas.texels.size() * channels);
    for (const Rgba& t : canvas.texels) {
        bytes.insert(bytes.end(), {t.r, t.g, t.b});
        if (keep_alpha) bytes.push_back(t.a);
    }
    if (stbi_write_png(path.c_str(), canvas.width, canvas.height, channels, bytes.data(), canvas.width * channels) == 0) {
        throw std::runtime_error("cannot write " + path);
    }
}

}  // namespace forest
