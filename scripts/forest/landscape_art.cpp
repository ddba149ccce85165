#include "scripts/forest/landscape_art.h"

#include <algorithm>
#include <cmath>

#include "scripts/forest/noise.h"

namespace forest {

using clr::Vec3;

namespace {

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

double haze_amount(double distance) { return 0.7 * (1 - std::exp(-std::max(0.0, distance - 120) / 3500)); }

Colour lowland_colour(double x, double z, double detail, std::uint32_t seed) {
    const Colour meadow{0.40, 0.50, 0.20}, dry_meadow{0.52, 0.53, 0.27};
    const Colour conifers{0.12, 0.25, 0.11}, broadleaves{0.24, 0.36, 0.13}, autumn{0.45, 0.30, 0.10};
    // Woods close round the forest and break into copses and meadows further out.
    const double distance = std::hypot(x, z);
    const double cover = fractal_noise_2d(x / 300, z / 300, 4, seed) + 0.1 * (1 - smoothstep(200, 500, distance));
    const double woodland = smoothstep(0.47, 0.52, cover);
    const Colour grass = lerp(meadow, dry_meadow, smoothstep(0.35, 0.7, fractal_noise_2d(x / 90, z / 90, 3, seed + 1)));
    // Mixed woods like the forest's own: stands of conifers and broadleaves, a few turning.
    const double kind = fractal_noise_2d(x / 45, z / 45, 2, seed + 4);
    Colour stand = lerp(conifers, broadleaves, smoothstep(0.45, 0.65, kind));
    stand = lerp(stand, autumn, 0.5 * smoothstep(0.68, 0.78, kind));
    // Close by, single crowns some 6 m across: bright tops, dark gaps.
    const double crowns = detail > 0 ? value_noise_2d(x / 6, z / 6, seed + 2) : 0.5;
    const Colour trees = stand * (1 + detail * (1.1 * crowns - 0.55));
    const double blades = detail > 0 ? value_noise_2d(x / 4, z / 4, seed + 3) : 0.5;
    return lerp(grass * (1 + detail * 0.16 * (blades - 0.5)), trees, woodland);
}

Canvas draw_country(double half_size, int texels, std::uint32_t seed) {
    Canvas canvas(texels, texels);
    const double texel_size = 2 * half_size / texels;
    for (int row = 0; row < texels; ++row) {
        for (int column = 0; column < texels; ++column) {
            const double x = -half_size + (column + 0.5) * texel_size, z = -half_size + (row + 0.5) * texel_size;
            const double distance = std::hypot(x, z);
            // Beyond a few hundred metres a pixel spans several crowns: fine detail would only flicker.
            const double detail = 1 - smoothstep(200, 500, distance);
            canvas.at(column, row) = opaque(lerp(lowland_colour(x, z, detail, seed), kHaze, haze_amount(distance)));
        }
    }
    return canvas;
}

}  // namespace forest
