#include "render/screen_tiles.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "render/frustum_clip.h"

namespace clr {
namespace {

// The pixel rectangle an object may cover, in (fractional) pixel coordinates, or the
// whole screen when the object reaches behind the eye (its projection is then unbounded), or
// nothing when it lies wholly behind the eye.
struct PixelBounds {
    double col_min = std::numeric_limits<double>::infinity(), col_max = -col_min;
    double row_min = col_min, row_max = -col_min;
    bool whole_screen = false;
    bool in_front = false;  // some point is not clearly behind the eye
};

class Projector {
public:
    explicit Projector(const FrameCamera& camera)
        : eye_(camera.eye_in_scene()), forward_(camera.forward), right_(camera.right), up_(camera.up),
          width_(camera.width), height_(camera.height) {}

    // Widens `bounds` by the projection of `point`. A point less than a small fraction of the
    // scene's distance in front of the eye counts as behind it. An object whose points are all
    // clearly behind the eye plane (by more than float rounding could move them) is never met:
    // every primary ray travels forwards, so every hit has a positive depth, and so would any
    // point of the object's convex hull that a ray could reach.
    void add(const Vec3& point, PixelBounds& bounds) const {
        Vec3 rel = point - eye_;
        double depth = dot(rel, forward_);
        if (!(depth < -1e-6 * length(rel))) bounds.in_front = true;
        if (!(depth > 1e-7 * length(rel))) {
            bounds.whole_screen = true;
            return;
        }
        // Inverse of the kernels' camera_ray: screen coordinates sx, sy in [-1, 1] across
        // the image, then pixel coordinates of which pixel centres are the integers.
        double sx = dot(rel, right_) / (dot(right_, right_) * depth);
        double sy = dot(rel, up_) / (dot(up_, up_) * depth);
        widen(bounds, (sx + 1) * width_ / 2 - 0.5, (1 - sy) * height_ / 2 - 0.5);
    }

    // Widens `bounds` by the projection of the part of convex polygon `corners` that rays can
    // reach: the part inside the view frustum, widened by kClipMarginPixels on every side and
    // with its apex moved back by a small fraction of the polygon's distance, more than float
    // rounding of the kernels' positions could move it. A polygon that comes that close to
    // the eye covers the whole screen. For objects that reach behind the eye plane.
    void add_clipped(const std::vector<Vec3>& corners, PixelBounds& bounds) const {
        std::vector<ViewPoint> polygon;
        double distance = 0;
        for (const Vec3& corner : corners) {
            Vec3 rel = corner - eye_;
            polygon.push_back({dot(rel, right_) / dot(right_, right_), dot(rel, up_) / dot(up_, up_), dot(rel, forward_)});
            distance = std::max(distance, length(rel));
        }
        const ClipFrustum frustum{2.0 * kClipMarginPixels / width_, 2.0 * kClipMarginPixels / height_,
                                  kNearEyeFraction * distance};
        for (const ViewPoint& p : clip_to_frustum(polygon, frustum)) {
            bounds.in_front = true;
            if (!(p.z > frustum.apex_back)) {
                bounds.whole_screen = true;
                return;
            }
            widen(bounds, (p.x / p.z + 1) * width_ / 2 - 0.5, (1 - p.y / p.z) * height_ / 2 - 0.5);
        }
    }

    const Vec3& eye() const { return eye_; }

private:
    // Clipping keeps what lies within this many pixels outside the screen: far more than the
    // kernels' float rays can stray from the exact ones.
    static constexpr double kClipMarginPixels = 4;
    // A polygon that passes within this fraction of its distance from the eye counts as
    // touching it (float positions are exact to about 6e-8 of their distance).
    static constexpr double kNearEyeFraction = 1e-5;

    static void widen(PixelBounds& bounds, double col, double row) {
        bounds.col_min = std::min(bounds.col_min, col);
        bounds.col_max = std::max(bounds.col_max, col);
        bounds.row_min = std::min(bounds.row_min, row);
        bounds.row_max = std::max(bounds.row_max, row);
    }

    Vec3 eye_, forward_, right_, up_;
    int width_, height_;
};

struct Candidate {
    std::uint32_t item;
    double nearest;
    PixelBounds bounds;
};

// Whether an object reaches behind the eye plane: then its corners' projection says nothing,
// and its bounds are those of its part inside the view frustum.
bool reaches_behind_eye(const PixelBounds& bounds) { return bounds.whole_screen && bounds.in_front; }

// A sphere lies inside its axis-aligned box, whose projection bounds the sphere's. Reaching
// behind the eye, the box's faces are clipped: a ray from outside the box enters through one.
Candidate sphere_candidate(const Sphere& sphere, std::uint32_t index, const Projector& projector) {
    Candidate candidate{index, std::max(0.0, length(sphere.center - projector.eye()) - sphere.radius), {}};
    auto corner = [&](int bits) {
        return sphere.center + Vec3{bits & 1 ? sphere.radius : -sphere.radius, bits & 2 ? sphere.radius : -sphere.radius,
                                    bits & 4 ? sphere.radius : -sphere.radius};
    };
    for (int bits = 0; bits < 8; ++bits) projector.add(corner(bits), candidate.bounds);
    if (!reaches_behind_eye(candidate.bounds)) return candidate;
    candidate.bounds = {};
    for (int axis = 0; axis < 3; ++axis) {
        const int u = 1 << ((axis + 1) % 3), v = 1 << ((axis + 2) % 3);
        for (int side : {0, 1 << axis})
            projector.add_clipped({corner(side), corner(side | u), corner(side | u | v), corner(side | v)}, candidate.bounds);
    }
    return candidate;
}

// A parallelogram projects inside the hull of its corners; no hit is nearer than its plane.
Candidate billboard_candidate(const Billboard& billboard, std::uint32_t index, const Projector& projector) {
    Vec3 edge_a = billboard.upper_right - billboard.upper_left;
    Vec3 edge_b = billboard.lower_left - billboard.upper_left;
    Vec3 normal = normalize(cross(edge_a, edge_b));
    double plane_distance = std::fabs(dot(projector.eye() - billboard.upper_left, normal));
    Candidate candidate{index | CLR_TILE_BILLBOARD, plane_distance, {}};
    const std::vector<Vec3> corners = {billboard.upper_left, billboard.upper_right, billboard.upper_right + edge_b,
                                       billboard.lower_left};
    for (const Vec3& corner : corners) projector.add(corner, candidate.bounds);
    if (reaches_behind_eye(candidate.bounds)) {
        candidate.bounds = {};
        projector.add_clipped(corners, candidate.bounds);
    }
    return candidate;
}

// Pixel rows first..last, packed as the kernels read them (ScreenTiles::rows).
std::uint32_t pack_rows(int first, int last) { return static_cast<std::uint32_t>(first) << 16 | static_cast<std::uint32_t>(last); }

// The tiles a candidate may cover, and its pixel rows, widened by one pixel so that rounding
// in the kernels' float rays can never put a pixel outside its object's tiles or rows.
bool tile_range(const Candidate& candidate, const ScreenTiles& tiles, int width, int height, std::array<int, 4>& range,
                std::uint32_t& rows) {
    const PixelBounds& b = candidate.bounds;
    if (!b.in_front) return false;  // wholly behind the eye: trees behind the camera in a forest
    if (b.whole_screen) {
        range = {0, tiles.tiles_x - 1, 0, tiles.tiles_y - 1};
        rows = pack_rows(0, height - 1);
        return true;
    }
    double col_min = std::floor(b.col_min) - 1, col_max = std::ceil(b.col_max) + 1;
    double row_min = std::floor(b.row_min) - 1, row_max = std::ceil(b.row_max) + 1;
    if (col_max < 0 || row_max < 0 || col_min > width - 1 || row_min > height - 1) return false;
    auto pixel_of = [](double pixel, int count) { return static_cast<int>(std::clamp(pixel, 0.0, double(count) - 1)); };
    range = {pixel_of(col_min, width) / kClrTileSize, pixel_of(col_max, width) / kClrTileSize,
             pixel_of(row_min, height) / kClrTileSize, pixel_of(row_max, height) / kClrTileSize};
    rows = pack_rows(pixel_of(row_min, height), pixel_of(row_max, height));
    return true;
}

}  // namespace

ScreenTiles bin_screen_tiles(const FrameGeometry& frame, const FrameCamera& camera) {
    Projector projector(camera);
    std::vector<Candidate> candidates;
    candidates.reserve(frame.object_count());
    for (std::size_t i = 0; i < frame.spheres().size(); ++i)
        candidates.push_back(sphere_candidate(frame.spheres()[i], static_cast<std::uint32_t>(i), projector));
    for (std::size_t i = 0; i < frame.billboard_count(); ++i)
        candidates.push_back(billboard_candidate(frame.billboard(i), static_cast<std::uint32_t>(i), projector));
    // Nearest first, ties by item, so every tile's list is in a deterministic near-to-far order.
    std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
        return a.nearest != b.nearest ? a.nearest < b.nearest : a.item < b.item;
    });

    ScreenTiles tiles;
    tiles.tiles_x = (camera.width + kClrTileSize - 1) / kClrTileSize;
    tiles.tiles_y = (camera.height + kClrTileSize - 1) / kClrTileSize;
    // Two passes over flat arrays (count per tile, then fill in candidate order), without a
    // list per tile: a frame bins anew, and a vector per tile (thousands at 1080p) would be
    // allocated and freed every frame (docs/benchmarks.md).
    struct Placed {
        std::uint32_t item;
        float bound;
        std::array<int, 4> range;
        std::uint32_t rows;
    };
    std::vector<Placed> placed;
    placed.reserve(candidates.size());
    std::vector<std::uint32_t> counts(static_cast<std::size_t>(tiles.tiles_x) * tiles.tiles_y + 1, 0);
    for (const Candidate& candidate : candidates) {
        std::array<int, 4> range;
        std::uint32_t rows;
        if (!tile_range(candidate, tiles, camera.width, camera.height, range, rows)) continue;
        // Stored slightly low: a float32 hit distance may fall a few ulps short of the true
        // one, and the kernel must never skip an object that its float ray does hit first.
        placed.push_back({candidate.item, static_cast<float>(candidate.nearest * (1 - 1e-5)), range, rows});
        for (int ty = range[2]; ty <= range[3]; ++ty)
            for (int tx = range[0]; tx <= range[1]; ++tx) ++counts[ty * tiles.tiles_x + tx];
    }
    tiles.offsets.resize(counts.size());
    std::uint32_t total = 0;
    for (std::size_t t = 0; t < counts.size(); ++t) {
        tiles.offsets[t] = total;
        total += counts[t];
    }
    tiles.items.resize(total);
    tiles.nearest.resize(total);
    tiles.rows.resize(total);
    std::vector<std::uint32_t> next(tiles.offsets.begin(), tiles.offsets.end() - 1);
    for (const Placed& p : placed)
        for (int ty = p.range[2]; ty <= p.range[3]; ++ty)
            for (int tx = p.range[0]; tx <= p.range[1]; ++tx) {
                std::uint32_t slot = next[ty * tiles.tiles_x + tx]++;
                tiles.items[slot] = p.item;
                tiles.nearest[slot] = p.bound;
                tiles.rows[slot] = p.rows;
            }
    return tiles;
}

}  // namespace clr
