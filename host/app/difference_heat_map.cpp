#include "app/difference_heat_map.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "app/image_difference.h"

namespace clr {
namespace {

// The scale's stops, evenly spaced in log(d) from d = 1 to d = 255: a difference four
// times as large is one stop further, so that both a rounding step and a wrong colour are
// told apart at a glance.
constexpr std::array<std::array<double, 3>, 5> kStops = {{
    {0, 0, 255},    // blue
    {0, 255, 255},  // cyan
    {0, 255, 0},    // green
    {255, 255, 0},  // yellow
    {255, 0, 0},    // red
}};

}  // namespace

std::array<std::uint8_t, 3> heat_colour(int difference) {
    const int d = std::clamp(difference, 1, 255);
    const double position = 4.0 * std::log(static_cast<double>(d)) / std::log(255.0);  // 0..4
    const int stop = std::min(3, static_cast<int>(position));
    const double t = position - stop;
    std::array<std::uint8_t, 3> colour{};
    for (int c = 0; c < 3; ++c)
        colour[c] = static_cast<std::uint8_t>(std::lround(kStops[stop][c] + t * (kStops[stop + 1][c] - kStops[stop][c])));
    return colour;
}

std::uint8_t context_grey(std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    const double luminance = 0.2126 * r + 0.7152 * g + 0.0722 * b;  // 0..255
    return static_cast<std::uint8_t>(std::lround(luminance / 4.0));
}

Image difference_heat_map(const Image& rendered, const Image& image, int tolerance) {
    if (rendered.width != image.width || rendered.height != image.height)
        throw std::invalid_argument("difference_heat_map: images of different sizes");
    Image map;
    map.width = rendered.width;
    map.height = rendered.height;
    map.rgba.resize(static_cast<std::size_t>(map.width) * map.height * 4);
    for (int y = 0; y < map.height; ++y) {
        for (int x = 0; x < map.width; ++x) {
            const int difference = channel_difference(rendered, image, x, y);
            std::array<std::uint8_t, 3> colour{};
            if (difference > tolerance) {
                colour = heat_colour(difference);
            } else {
                const std::uint8_t grey = context_grey(rendered.at(x, y, 0), rendered.at(x, y, 1), rendered.at(x, y, 2));
                colour = {grey, grey, grey};
            }
            std::uint8_t* out = &map.rgba[(static_cast<std::size_t>(y) * map.width + x) * 4];
            out[0] = colour[0];
            out[1] = colour[1];
            out[2] = colour[2];
            out[3] = 255;
        }
    }
    return map;
}

}  // namespace clr
