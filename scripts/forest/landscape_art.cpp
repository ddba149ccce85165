#include "scripts/forest/landscape_art.h"

#include <algorithm>
#include <cmath>

#include "scripts/forest/noise.h"

namespace forest {

using clr::Vec3;

namespace {

double smoothstep(double edge0, double edge1, double x) {
    const double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
    return t * t * (3 - 2 * t);
}

// Grass and dirt at a point of the ground, before trees and clearings.
Colour ground_colour(double x, double z, std::uint32_t seed) {
    const Colour dark_grass{0.17, 0.29, 0.10}, light_grass{0.36, 0.45, 0.17}, moss{0.24, 0.36, 0.12};
    const Colour dirt{0.38, 0.29, 0.18}, needles{0.42, 0.30, 0.17};
    const double grass = fractal_noise(x / 7, z / 7, 0, 4, seed);
    Colour colour = lerp(dark_grass, light_grass, smoothstep(0.3, 0.75, grass));
    colour = lerp(colour, moss, 0.5 * smoothstep(0.5, 0.8, fractal_noise(x / 3, z / 3, 1, 3, seed + 1)));
    const double patch = fractal_noise(x / 16, z / 16, 2, 4, seed + 2);
    colour = lerp(colour, lerp(dirt, needles, grass), smoothstep(0.56, 0.68, patch));
    const double blade = hash_unit(static_cast<std::int32_t>(std::floor(x * 8)), static_cast<std::int32_t>(std::floor(z * 8)),
                                   0, seed + 3);
    return colour * (0.94 + 0.12 * blade);
}

// Per texel, how much of the tree's shade and litter darkens it (1: none).
std::vector<double> tree_shade(const ForestLayout& layout, double half_size, int texels, const Vec3& towards_sun) {
    std::vector<double> shade(static_cast<std::size_t>(texels) * texels, 1.0);
    const double texel_size = 2 * half_size / texels;
    const double horizontal = std::hypot(towards_sun.x, towards_sun.z);
    for (const TreeInstance& tree : layout.trees) {
        // The shade falls away from the sun; a small disc of litter lies right at the trunk.
        const double reach = tree.height * 0.35 * horizontal / std::max(towards_sun.y, 0.3);
        const double cx = tree.base.x - towards_sun.x / horizontal * reach;
        const double cz = tree.base.z - towards_sun.z / horizontal * reach;
        const double radius = tree.width * 0.45;
        const int first_column = std::max(0, static_cast<int>((cx - radius + half_size) / texel_size));
        const int last_column = std::min(texels - 1, static_cast<int>((cx + radius + half_size) / texel_size));
        const int first_row = std::max(0, static_cast<int>((cz - radius + half_size) / texel_size));
        const int last_row = std::min(texels - 1, static_cast<int>((cz + radius + half_size) / texel_size));
        for (int row = first_row; row <= last_row; ++row) {
            for (int column = first_column; column <= last_column; ++column) {
                const double x = -half_size + (column + 0.5) * texel_size, z = -half_size + (row + 0.5) * texel_size;
                const double d = std::hypot(x - cx, z - cz) / radius;
                double& s = shade[static_cast<std::size_t>(row) * texels + column];
                s = std::min(s, 0.55 + 0.45 * smoothstep(0.5, 1.0, d));
            }
        }
    }
    return shade;
}

// 1 inside a clearing, fading to 0 at its edge.
double clearing_weight(const ForestLayout& layout, double x, double z) {
    double weight = 0;
    for (const Clearing& c : layout.clearings) {
        weight = std::max(weight, 1 - smoothstep(c.radius * 0.7, c.radius * 1.1, std::hypot(c.x - x, c.z - z)));
    }
    return weight;
}

}  // namespace

Canvas draw_forest_floor(const ForestLayout& layout, double half_size, int texels, std::uint32_t seed,
                         const Vec3& towards_sun) {
    const std::vector<double> shade = tree_shade(layout, half_size, texels, towards_sun);
    const Colour meadow{0.40, 0.52, 0.20};
    Canvas canvas(texels, texels);
    const double texel_size = 2 * half_size / texels;
    for (int row = 0; row < texels; ++row) {
        for (int column = 0; column < texels; ++column) {
            const double x = -half_size + (column + 0.5) * texel_size, z = -half_size + (row + 0.5) * texel_size;
            Colour colour = ground_colour(x, z, seed);
            colour = lerp(colour, meadow * (colour.y / 0.35), 0.45 * clearing_weight(layout, x, z));
            canvas.at(column, row) = opaque(colour * shade[static_cast<std::size_t>(row) * texels + column]);
        }
    }
    return canvas;
}

Canvas draw_far_ground(int texels, std::uint32_t seed) {
    const Colour meadow{0.32, 0.42, 0.16}, woods{0.13, 0.24, 0.11}, haze{0.55, 0.66, 0.72};
    Canvas canvas(texels, texels);
    for (int row = 0; row < texels; ++row) {
        for (int column = 0; column < texels; ++column) {
            const double u = (column + 0.5) / texels, v = (row + 0.5) / texels;
            const double woodland = smoothstep(0.45, 0.6, fractal_noise(u * 12, v * 12, 0, 5, seed));
            Colour colour = lerp(meadow, woods, woodland) * (0.9 + 0.2 * value_noise(u * 90, v * 90, 1, seed + 1));
            // Distance from the centre as a fraction of the half size: the edge melts into haze.
            const double edge = std::max(std::abs(2 * u - 1), std::abs(2 * v - 1));
            colour = lerp(colour, haze, smoothstep(0.25, 0.95, edge) * 0.85);
            canvas.at(column, row) = opaque(colour);
        }
    }
    return canvas;
}

namespace {

// Crest of the snowy range at u in [0, 1], as a fraction of the picture height from the bottom.
double far_crest(double u, std::uint32_t seed) {
    const double broad = fractal_noise(u * 4, 0.5, 0, 3, seed);
    const double sharp = 1 - std::abs(2 * fractal_noise(u * 11, 1.5, 0, 3, seed + 1) - 1);
    return 0.22 + 0.55 * broad * broad + 0.22 * sharp * sharp + 0.015 * value_noise(u * 150, 2.5, 0, seed + 2);
}

// Crest of the wooded ridge in front: low, with a ragged edge of treetops.
double near_crest(double u, std::uint32_t seed) {
    const double hills = fractal_noise(u * 7, 3.5, 0, 3, seed + 5);
    const double treetops = hash_unit(static_cast<std::int32_t>(std::floor(u * 1400)), 0, 0, seed + 6);
    return 0.08 + 0.12 * hills + 0.006 * treetops;
}

// Rock and snow, lit from the left: near the crest the side of each peak that faces left is
// bright; lower down, gullies (a noise stretched along the slope) break the faces up.
Colour rock_colour(double u, double height, double crest, std::uint32_t seed) {
    const Colour lit{0.60, 0.62, 0.70}, shadowed{0.34, 0.38, 0.50}, snow{0.96, 0.97, 1.0}, snow_shadow{0.70, 0.76, 0.88};
    const double below = crest - height;
    const double slope = (far_crest(u + 0.002, seed) - far_crest(u - 0.002, seed)) / 0.004;
    const double gully = fractal_noise(u * 70 + height * 25, height * 6, 0, 3, seed + 3) - 0.5;
    const double face = -slope * std::exp(-below * 6) + 1.6 * gully;
    const double light = smoothstep(-0.5, 0.5, face);
    const double snowline = 0.55 + 0.08 * value_noise(u * 30, 0, 0, seed + 4) + 0.1 * gully;
    const bool snowy = height > snowline || below < 0.035 + 0.05 * value_noise(u * 80, 0, 0, seed + 7);
    const Colour surface = snowy && height > 0.4 ? lerp(snow_shadow, snow, light) : lerp(shadowed, lit, light);
    return surface * (0.93 + 0.1 * value_noise(u * 300, height * 60, 0, seed + 8));
}

}  // namespace

Canvas draw_mountains(int width, int height, int ground_row, std::uint32_t seed) {
    const Colour haze{0.70, 0.80, 0.90}, ridge_top{0.24, 0.36, 0.32}, ridge_foot{0.17, 0.27, 0.22};
    Canvas canvas(width, height);
    for (int column = 0; column < width; ++column) {
        const double u = (column + 0.5) / width;
        const double far = far_crest(u, seed), near = near_crest(u, seed);
        for (int row = 0; row < height; ++row) {
            // Height above the ground line, as a fraction of the part of the picture above it.
            const double above = static_cast<double>(ground_row - row) / ground_row;
            if (above > far) continue;  // sky
            Colour colour;
            if (above > near) {
                colour = lerp(rock_colour(u, above, far, seed), haze, 0.35 + 0.25 * (1 - above));
            } else {
                const double depth = std::clamp((near - above) / 0.3, 0.0, 1.0);
                colour = lerp(ridge_top, ridge_foot, depth) * (0.88 + 0.2 * value_noise(u * 500, above * 80, 0, seed + 9));
                colour = lerp(colour, haze, 0.25);
            }
            canvas.at(column, row) = opaque(colour);
        }
    }
    return canvas;
}

}  // namespace forest
