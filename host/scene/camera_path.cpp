// Choices made here, and why:
// - Constant parameter speed: frame f sits at path parameter s = f * (N - 1) / (count - 1),
//   measured in keys. Segment index and the fraction within it come from integer division,
//   so frames that land on a key reproduce it bit for bit, with no floating-point drift.
// - Eye and look-at are interpolated independently, each along its own curve.
// - The smooth option is the centripetal Catmull-Rom spline (alpha = 0.5), evaluated with
//   the Barry-Goldman pyramid. Unlike the uniform variant it neither overshoots between
//   unevenly spaced keys nor forms cusps or loops within a segment, so the camera never
//   swings past a key and back. Its knot spacing uses the 3D distance between keys; the
//   evaluation itself is per component. Within each segment the knot parameter advances
//   evenly with the frames, so the direction of motion is continuous at the keys while the
//   speed may change there (as it does for the linear path).
#include "scene/camera_path.h"

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace clr {
namespace {

// Where a frame falls: `numerator / denominator` of the way from key `segment` to key
// `segment + 1`, with 0 <= numerator < denominator. The last frame is segment N - 1 at 0.
struct PathPosition {
    std::size_t segment = 0;
    long long numerator = 0;
    long long denominator = 1;
};

PathPosition position_of_frame(std::size_t key_count, int frame, int frame_count) {
    PathPosition position;
    if (frame_count < 2) return position;  // a single frame shows the first key
    const long long scaled = static_cast<long long>(frame) * static_cast<long long>(key_count - 1);
    position.denominator = frame_count - 1;
    position.segment = static_cast<std::size_t>(scaled / position.denominator);
    position.numerator = scaled % position.denominator;
    return position;
}

// a + (b - a) * numerator / denominator, multiplying before dividing so that a whole-number
// answer such as 10 * 3 / 10 comes out exact.
Vec3 lerp_exact(const Vec3& a, const Vec3& b, long long numerator, long long denominator) {
    return a + (b - a) * static_cast<double>(numerator) / static_cast<double>(denominator);
}

// The point at knot parameter t on the line that is at `a` at knot ta and at `b` at knot tb.
Vec3 lerp_between_knots(const Vec3& a, double ta, const Vec3& b, double tb, double t) {
    return (a * (tb - t) + b * (t - ta)) / (tb - ta);
}

// Centripetal knot spacing: the square root of the distance between consecutive points.
double knot_interval(const Vec3& from, const Vec3& to) { return std::sqrt(length(to - from)); }

// The centripetal Catmull-Rom segment from p1 (u = 0) to p2 (u = 1), with neighbours p0 and
// p3 shaping the tangents. Requires p0 != p1, p1 != p2 and p2 != p3 (no zero knot interval).
Vec3 centripetal_catmull_rom(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3, double u) {
    const double t0 = 0;
    const double t1 = t0 + knot_interval(p0, p1);
    const double t2 = t1 + knot_interval(p1, p2);
    const double t3 = t2 + knot_interval(p2, p3);
    const double t = t1 + u * (t2 - t1);

    const Vec3 a1 = lerp_between_knots(p0, t0, p1, t1, t);
    const Vec3 a2 = lerp_between_knots(p1, t1, p2, t2, t);
    const Vec3 a3 = lerp_between_knots(p2, t2, p3, t3, t);
    const Vec3 b1 = lerp_between_knots(a1, t0, a2, t2, t);
    const Vec3 b2 = lerp_between_knots(a2, t1, a3, t3, t);
    return lerp_between_knots(b1, t1, b2, t2, t);
}

// One coordinate curve of the path (the eyes, or the look-at points), read in place from the
// keys: camera_at_frame() runs once per frame, and copying a path of a million keys for
// each frame would make a long animation quadratic.
struct PathPoints {
    const std::vector<CameraKey>& keys;
    Vec3 CameraKey::*member;

    const Vec3& operator[](std::size_t i) const { return keys[i].*member; }
    std::size_t size() const { return keys.size(); }
};

// The neighbour before key i. Past the first key, and where the neighbour coincides with the
// key (its knot interval would be zero), a phantom point mirrors the next key through key i,
// which makes the curve leave key i heading straight at the next key.
Vec3 previous_neighbour(const PathPoints& points, std::size_t i) {
    const Vec3 mirrored = 2.0 * points[i] - points[i + 1];
    if (i == 0 || points[i - 1] == points[i]) return mirrored;
    return points[i - 1];
}

// The neighbour after key i + 1, mirrored in the same way at the end of the path.
Vec3 next_neighbour(const PathPoints& points, std::size_t i) {
    const Vec3 mirrored = 2.0 * points[i + 1] - points[i];
    if (i + 2 >= points.size() || points[i + 2] == points[i + 1]) return mirrored;
    return points[i + 2];
}

Vec3 point_on_path(const PathPoints& points, const PathPosition& at, Interpolation interpolation) {
    const std::size_t i = at.segment;
    if (at.numerator == 0) return points[i];  // exactly on a key
    const Vec3& from = points[i];
    const Vec3& to = points[i + 1];
    // Coinciding keys make a segment where the camera rests; the spline's knot interval would
    // be zero there, and the linear answer (standing still) is the right one anyway.
    if (interpolation == Interpolation::Linear || from == to) {
        return lerp_exact(from, to, at.numerator, at.denominator);
    }
    const double u = static_cast<double>(at.numerator) / static_cast<double>(at.denominator);
    return centripetal_catmull_rom(previous_neighbour(points, i), from, to, next_neighbour(points, i), u);
}

}  // namespace

int animation_frame_count(const Scene& scene) {
    const std::size_t keys = scene.camera_path.size();
    if (keys < 2) return 1;
    if (scene.animation.frame_count > 0) return scene.animation.frame_count;
    // The scene loader refuses longer animations with the scene's location; a Scene built
    // in code gets this check, so that the count can never wrap around.
    const long long per_segment = scene.animation.frames_per_segment;
    if (per_segment < 1 || static_cast<long long>(keys - 1) > (kMaxAnimationFrames - 1) / per_segment) {
        throw std::length_error("animation of " + std::to_string(keys) + " camera keys at " + std::to_string(per_segment) +
                                " frames per segment has more than " + std::to_string(kMaxAnimationFrames) + " frames");
    }
    return static_cast<int>((keys - 1) * per_segment + 1);
}

CameraKey camera_at_frame(const Scene& scene, int frame) {
    const std::vector<CameraKey>& keys = scene.camera_path;
    if (keys.empty()) throw std::invalid_argument("camera_at_frame: the scene has no camera keys");
    const int frame_count = animation_frame_count(scene);
    if (frame < 0 || frame >= frame_count) {
        throw std::out_of_range("camera_at_frame: frame " + std::to_string(frame) + " is outside 0-" +
                                std::to_string(frame_count - 1));
    }
    if (keys.size() == 1) return keys.front();

    const PathPoints eyes{keys, &CameraKey::eye}, lookats{keys, &CameraKey::lookat};
    const PathPosition at = position_of_frame(keys.size(), frame, frame_count);
    const Interpolation interpolation = scene.animation.interpolation;
    return {point_on_path(eyes, at, interpolation), point_on_path(lookats, at, interpolation)};
}

}  // namespace clr
