#include "scripts/forest/camera_flight.h"

#include <cmath>

#include "scene/camera_path.h"

namespace forest {

using clr::CameraKey;
using clr::Vec3;

namespace {

constexpr double kDegrees = 3.14159265358979323846 / 180;
const Vec3 kLoneTreeMiddle{0, 4.65, 0};

// A point on a circle around the lone tree: angle 0 is +z, 90 degrees is +x.
Vec3 around_tree(double angle_degrees, double radius, double height) {
    return {radius * std::sin(angle_degrees * kDegrees), height, radius * std::cos(angle_degrees * kDegrees)};
}

// In over the tree tops from the forest's near corner, descending into the clearing; the
// keys are about 17 m apart so the speed stays even. The camera keeps the lone tree in view.
void add_approach(std::vector<CameraKey>& keys) {
    const Vec3 eyes[] = {{-80, 24, 118}, {-70, 23, 106}, {-60, 21, 94}, {-50, 19, 80},
                         {-40, 16, 64},  {-31, 12, 48},  {-23, 8, 33},  {-15, 4.5, 20}};
    for (const Vec3& eye : eyes) keys.push_back({eye, kLoneTreeMiddle});
}

// Once around at close range, so that the tree's eight views take turns; the eye bobs a
// little so the orbit does not look mechanical.
void add_orbit(std::vector<CameraKey>& keys, double start_angle) {
    for (int step = 0; step <= 8; ++step) {
        const double height = kOrbitEyeHeight + 0.5 * std::sin(step * 0.8);
        keys.push_back({around_tree(start_angle + 45.0 * step, kOrbitRadius, height), kLoneTreeMiddle});
    }
}

// Spiral up and out, then away over the tree tops towards the mountains in the -z distance,
// looking ahead and a little down.
void add_departure(std::vector<CameraKey>& keys, double start_angle) {
    keys.push_back({around_tree(start_angle + 405, kOrbitRadius + 2.5, 7), kLoneTreeMiddle});
    keys.push_back({around_tree(start_angle + 450, kOrbitRadius + 5.5, 11), {4, 6, -4}});
    const Vec3 eyes[] = {{20, 14, -4}, {28, 18, -19}, {35, 21, -35}, {41, 23, -52}, {47, 25, -69}, {52, 26, -86}};
    const Vec3 heading = clr::normalize(Vec3(0.34, 0, -0.94));
    for (const Vec3& eye : eyes) keys.push_back({eye, eye + heading * 60 + Vec3(0, -14, 0)});
}

}  // namespace

std::vector<CameraKey> flight_keys() {
    std::vector<CameraKey> keys;
    add_approach(keys);
    const Vec3 entry = keys.back().eye;
    const double start_angle = std::atan2(entry.x, entry.z) / kDegrees;
    add_orbit(keys, start_angle);
    add_departure(keys, start_angle);
    return keys;
}

std::vector<Vec3> sample_eyes(const std::vector<CameraKey>& keys, int samples) {
    clr::Scene scene;
    scene.camera_path = keys;
    scene.animation.frame_count = samples;
    scene.animation.interpolation = clr::Interpolation::CatmullRom;
    std::vector<Vec3> eyes;
    for (int frame = 0; frame < samples; ++frame) eyes.push_back(clr::camera_at_frame(scene, frame).eye);
    return eyes;
}

}  // namespace forest
