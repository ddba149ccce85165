#include "scripts/forest/mountain_ring.h"

#include <algorithm>
#include <cmath>

#include "scripts/forest/landscape_art.h"
#include "scripts/forest/noise.h"

namespace forest {

using clr::Vec3;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegrees = kPi / 180;
// The panorama: about one column per pixel of a 1280-wide frame, and the range reaching this far
// behind the ring.
constexpr int kPanoramaColumns = 6144, kPanoramaRows = 400;
constexpr double kRangeDepth = 3600;
// Each sample along a line of sight lies this fraction further than the last: finer near the
// ring, where a metre of depth spans more rows.
constexpr double kDepthStep = 0.004;

// From the centre towards angle `theta` (radians), and the way the angle grows.
Vec3 direction_at(double theta) { return {std::sin(theta), 0, -std::cos(theta)}; }
Vec3 rightwards_at(double theta) { return {std::cos(theta), 0, std::sin(theta)}; }

// The land's height at (x, z): level with the far ground at the ring, then wooded hills, and
// the high range rising behind them, all carved by the same ridges and valleys.
double terrain_height(double x, double z, double ring_distance, std::uint32_t seed) {
    const double distance = std::hypot(x, z), beyond = distance - ring_distance;
    const double ridges = ridged_noise(x / 2200, z / 2200, 7, seed + 11);
    const double massif = 0.6 + 0.7 * value_noise_2d(x / 6000, z / 6000, seed + 10);  // higher here, lower there
    const double hills = smoothstep(0, 1000, beyond) * (30 + 300 * ridges);
    const double peaks = smoothstep(900, 2600, beyond) * (100 + 1100 * massif * ridges * ridges);
    // Softly capped at about 12 degrees seen from the centre, so that no peak reaches the
    // pictures' top row and comes out flat.
    const double cap = 0.21 * distance;
    return cap * std::tanh((hills + peaks) / cap);
}

// The mountains seen from the centre at ground level: per column the skyline's elevation and
// the colour of each row below it (rows above it repeat the crest's colour, for blending).
struct Panorama {
    double top = 0;  // elevation of the top row's upper edge, radians
    std::vector<double> skyline;
    std::vector<Colour> colours;  // colours[column * kPanoramaRows + row], row 0 at the horizon

    double row_elevation(int row) const { return (row + 0.5) / kPanoramaRows * top; }
};

// Distances from the centre of the samples along every line of sight.
std::vector<double> sample_distances(double ring_distance) {
    std::vector<double> distances;
    for (double d = ring_distance; d < ring_distance + kRangeDepth; d *= 1 + kDepthStep) distances.push_back(d);
    return distances;
}

// Rock, forest and snow at a point of the range, lit from `light`. Low flat land keeps the
// lowland's colour, so the range's foot matches the far ground in front of it.
Colour terrain_colour(const Vec3& point, const Vec3& normal, const Vec3& light, std::uint32_t seed) {
    const Colour dark_rock{0.36, 0.34, 0.34}, light_rock{0.58, 0.55, 0.52}, forest{0.12, 0.22, 0.11};
    const Colour snow{0.97, 0.97, 1.0}, snow_shade{0.62, 0.68, 0.82};
    const double steep = 1 - normal.y;
    // Strata: bands that follow the height, bent by noise.
    const double strata = fractal_noise(point.x / 160, point.y / 35, point.z / 160, 3, seed + 12);
    const Colour rock = lerp(dark_rock, light_rock, smoothstep(0.3, 0.7, strata));
    const Colour low = lerp(lowland_colour(point.x, point.z, 0, seed), forest, smoothstep(40, 160, point.y));
    const double tree_line = 420 + 160 * value_noise_2d(point.x / 500, point.z / 500, seed + 13);
    const double wooded = (1 - smoothstep(tree_line - 80, tree_line + 80, point.y)) * (1 - smoothstep(0.3, 0.5, steep));
    const Colour ground = lerp(rock, low, wooded);
    // Snow lies above a wavy line, and not on the steepest faces.
    const double snow_line = 640 + 150 * fractal_noise_2d(point.x / 700, point.z / 700, 3, seed + 14);
    const double snowy = smoothstep(snow_line - 30, snow_line + 30, point.y) * (1 - smoothstep(0.5, 0.6, steep));
    const double lit = std::max(0.0, clr::dot(normal, light)), flat_lit = std::max(0.0, light.y);
    const Colour shaded_ground = ground * ((0.45 + 0.8 * lit) / (0.45 + 0.8 * flat_lit));
    return lerp(shaded_ground, lerp(snow_shade, snow, std::min(1.0, 1.2 * lit)), snowy);
}

// Heights of the samples of every column, column after column.
std::vector<double> panorama_heights(const MountainRing& ring, const std::vector<double>& distances, std::uint32_t seed) {
    std::vector<double> heights;
    heights.reserve(distances.size() * kPanoramaColumns);
    for (int column = 0; column < kPanoramaColumns; ++column) {
        const Vec3 towards = direction_at((column + 0.5) / kPanoramaColumns * 2 * kPi);
        for (double d : distances) heights.push_back(terrain_height(towards.x * d, towards.z * d, ring.distance, seed));
    }
    return heights;
}

// The surface's normal at sample `i` of `column`, from its neighbours along and across the line of sight.
Vec3 sample_normal(const std::vector<double>& heights, const std::vector<double>& distances, int column, int i) {
    const int n = static_cast<int>(distances.size());
    auto height = [&](int c, int s) {
        return heights[static_cast<std::size_t>((c + kPanoramaColumns) % kPanoramaColumns) * n + std::clamp(s, 0, n - 1)];
    };
    const int before = std::max(i - 1, 0), after = std::min(i + 1, n - 1);
    const double along = (height(column, after) - height(column, before)) / (distances[after] - distances[before]);
    const double step = 2 * kPi / kPanoramaColumns;
    const double across = (height(column + 1, i) - height(column - 1, i)) / (2 * distances[i] * step);
    const double theta = (column + 0.5) * step;
    const Vec3 slope = direction_at(theta) * along + rightwards_at(theta) * across;
    return clr::normalize(Vec3(-slope.x, 1, -slope.z));
}

// Fills one column front to back: each sample that rises above everything nearer shows on the
// rows between the old skyline and its own elevation, its colour blended with the last sample's.
void fill_column(Panorama& panorama, const std::vector<double>& heights, const std::vector<double>& distances,
                 int column, const Vec3& light, std::uint32_t seed) {
    const double theta = (column + 0.5) / kPanoramaColumns * 2 * kPi;
    Colour* colours = &panorama.colours[static_cast<std::size_t>(column) * kPanoramaRows];
    int next_row = 0;
    double skyline = 0, last_elevation = 0;
    bool last_shown = false;  // whether the last sample was in sight: then the slope runs on from it
    Colour last_colour;
    for (int i = 0; i < static_cast<int>(distances.size()); ++i) {
        const double d = distances[i], height = heights[static_cast<std::size_t>(column) * distances.size() + i];
        const double elevation = std::atan2(height, d);
        if (elevation <= skyline && i > 0) {
            last_shown = false;
            continue;
        }
        const Vec3 point = direction_at(theta) * d + Vec3(0, height, 0);
        const Colour colour = lerp(terrain_colour(point, sample_normal(heights, distances, column, i), light, seed), kHaze,
                                   haze_amount(d));
        for (; next_row < kPanoramaRows && panorama.row_elevation(next_row) < elevation; ++next_row) {
            // Behind a ridge the farther slope starts crisply; on an open slope colours blend.
            const double t = last_shown ? (panorama.row_elevation(next_row) - last_elevation) / (elevation - last_elevation) : 1;
            colours[next_row] = lerp(last_colour, colour, std::clamp(t, 0.0, 1.0));
        }
        skyline = std::max(skyline, elevation);
        last_elevation = elevation;
        last_colour = colour;
        last_shown = true;
    }
    for (; next_row < kPanoramaRows; ++next_row) colours[next_row] = next_row > 0 ? colours[next_row - 1] : last_colour;
    panorama.skyline[column] = skyline;
}

Panorama draw_panorama(const MountainRing& ring, std::uint32_t seed, const Vec3& light) {
    Panorama panorama;
    panorama.top = std::atan2(ring.above_ground, ring.distance);
    panorama.skyline.resize(kPanoramaColumns);
    panorama.colours.resize(static_cast<std::size_t>(kPanoramaColumns) * kPanoramaRows);
    const std::vector<double> distances = sample_distances(ring.distance);
    const std::vector<double> heights = panorama_heights(ring, distances, seed);
    for (int column = 0; column < kPanoramaColumns; ++column) fill_column(panorama, heights, distances, column, light, seed);
    return panorama;
}

// The skyline and the colour at (theta, elevation), blended between the nearest columns and rows.
struct PanoramaSample {
    double skyline;
    Colour colour;
};

PanoramaSample sample_panorama(const Panorama& panorama, double theta, double elevation) {
    const double u = theta / (2 * kPi) * kPanoramaColumns - 0.5;
    const double fu = std::floor(u), tu = u - fu;
    const int c0 = ((static_cast<int>(fu) % kPanoramaColumns) + kPanoramaColumns) % kPanoramaColumns;
    const int c1 = (c0 + 1) % kPanoramaColumns;
    const double v = std::clamp(elevation / panorama.top * kPanoramaRows - 0.5, 0.0, kPanoramaRows - 1.0);
    const int r0 = std::min(static_cast<int>(v), kPanoramaRows - 2);
    const double tv = v - r0;
    auto at = [&](int c, int r) { return panorama.colours[static_cast<std::size_t>(c) * kPanoramaRows + r]; };
    const Colour left = lerp(at(c0, r0), at(c0, r0 + 1), tv), right = lerp(at(c1, r0), at(c1, r0 + 1), tv);
    return {panorama.skyline[c0] + (panorama.skyline[c1] - panorama.skyline[c0]) * tu, lerp(left, right, tu)};
}

// Picture `index`: each texel shows what the centre sees through it.
Canvas cut_picture(const MountainRing& ring, const Panorama& panorama, int index) {
    Canvas canvas(ring.texels_wide, ring.texels_high);
    const double width = picture_width(ring), height = ring.above_ground + ring.below_ground;
    const double centre_angle = index * 2 * kPi / ring.count;
    for (int column = 0; column < ring.texels_wide; ++column) {
        const double x = ((column + 0.5) / ring.texels_wide - 0.5) * width;
        const double off_centre = std::atan2(x, ring.distance);
        const double sinking = 1 - smoothstep(ring.full_half_angle, ring.half_angle, std::abs(off_centre) / kDegrees);
        const double reach = std::hypot(x, ring.distance);  // from the centre to this column
        for (int row = 0; row < ring.texels_high; ++row) {
            const double y = ring.above_ground - (row + 0.5) / ring.texels_high * height;
            const double elevation = std::atan2(y, reach);
            const PanoramaSample sample = sample_panorama(panorama, centre_angle + off_centre, elevation);
            if (elevation < sample.skyline * sinking) canvas.at(column, row) = opaque(sample.colour);
        }
    }
    return canvas;
}

}  // namespace

double picture_width(const MountainRing& ring) { return 2 * ring.distance * std::tan(ring.half_angle * kDegrees); }

Vec3 picture_direction(const MountainRing& ring, int index) { return direction_at(index * 2 * kPi / ring.count); }

std::vector<Canvas> draw_mountain_ring(const MountainRing& ring, std::uint32_t seed, const Vec3& towards_sun) {
    // The sun from its own side but only 30 degrees up: long light across the slopes.
    const Vec3 level = clr::normalize(Vec3(towards_sun.x, 0, towards_sun.z));
    const Vec3 light = level * std::cos(30 * kDegrees) + Vec3(0, std::sin(30 * kDegrees), 0);
    const Panorama panorama = draw_panorama(ring, seed, light);
    std::vector<Canvas> pictures;
    for (int index = 0; index < ring.count; ++index) pictures.push_back(cut_picture(ring, panorama, index));
    return pictures;
}

}  // namespace forest
