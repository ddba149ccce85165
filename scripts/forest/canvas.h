// An RGBA picture being drawn, and how it is written as PNG.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/vec3.h"

namespace forest {

using Colour = clr::Vec3;  // linear display values in [0, 1]

struct Rgba {
    std::uint8_t r = 0, g = 0, b = 0, a = 0;
};

// Starts fully transparent; (0, 0) is the top-left texel.
struct Canvas {
    int width = 0, height = 0;
    std::vector<Rgba> texels;

    Canvas(int w, int h) : width(w), height(h), texels(static_cast<std::size_t>(w) * h) {}
    Rgba& at(int x, int y) { return texels[static_cast<std::size_t>(y) * width + x]; }
    const Rgba& at(int x, int y) const { return texels[static_cast<std::size_t>(y) * width + x]; }
};

// An opaque texel of `colour`, each channel clamped to [0, 1] and rounded.
Rgba opaque(const Colour& colour);

Colour lerp(const Colour& from, const Colour& to, double t);

// Writes RGBA (or RGB when keep_alpha is false) PNG; throws std::runtime_error on failure.
void save_png(const std::string& path, const Canvas& canvas, bool keep_alpha);

}  // namespace forest
