// Camera path: how many frames an animation has and where the camera is in each. Expected
// positions are worked out by hand in the comments, or by an independent formula (the
// uniform Catmull-Rom matrix form, which the centripetal spline equals when all keys are
// evenly spaced).
#include "scene/camera_path.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace clr {
namespace {

Scene scene_with_path(const std::vector<CameraKey>& keys, Interpolation interpolation = Interpolation::Linear) {
    Scene scene;
    scene.camera_path = keys;
    scene.animation.interpolation = interpolation;
    return scene;
}

// Keys moving the eye through `eyes` while looking at the origin.
Scene scene_with_eyes(const std::vector<Vec3>& eyes, Interpolation interpolation = Interpolation::Linear) {
    std::vector<CameraKey> keys;
    for (const Vec3& eye : eyes) keys.push_back({eye, {0, 0, 0}});
    return scene_with_path(keys, interpolation);
}

void expect_near(const Vec3& actual, const Vec3& expected, double tolerance, const std::string& what) {
    EXPECT_NEAR(actual.x, expected.x, tolerance) << what;
    EXPECT_NEAR(actual.y, expected.y, tolerance) << what;
    EXPECT_NEAR(actual.z, expected.z, tolerance) << what;
}

// The uniform Catmull-Rom segment from p1 to p2 in its textbook matrix form.
Vec3 uniform_catmull_rom(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3, double u) {
    return 0.5 * (2.0 * p1 + (p2 - p0) * u + (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3) * (u * u) +
                  (3.0 * p1 - p0 - 3.0 * p2 + p3) * (u * u * u));
}

TEST(CameraPath, StillHasOneFrame) {
    Scene scene = scene_with_eyes({{1, 2, 3}});
    scene.animation.frame_count = 50;  // ignored: a still is one picture
    EXPECT_EQ(animation_frame_count(scene), 1);
    const CameraKey camera = camera_at_frame(scene, 0);
    EXPECT_EQ(camera.eye, Vec3(1, 2, 3));
    EXPECT_EQ(camera.lookat, Vec3(0, 0, 0));
}

TEST(CameraPath, TwoKeysDefaultToElevenFrames) {
    EXPECT_EQ(animation_frame_count(scene_with_eyes({{0, 0, 0}, {10, 0, 0}})), 11);
}

TEST(CameraPath, ThreeKeysDefaultToTwentyOneFrames) {
    EXPECT_EQ(animation_frame_count(scene_with_eyes({{0, 0, 0}, {10, 0, 0}, {10, 10, 0}})), 21);
}

TEST(CameraPath, FramesPerSegmentSetsTheCount) {
    Scene scene = scene_with_eyes({{0, 0, 0}, {10, 0, 0}, {10, 10, 0}});
    scene.animation.frames_per_segment = 4;
    EXPECT_EQ(animation_frame_count(scene), 9);  // 2 segments * 4 + the last key
}

TEST(CameraPath, FrameCountOverridesFramesPerSegment) {
    Scene scene = scene_with_eyes({{0, 0, 0}, {10, 0, 0}, {10, 10, 0}});
    scene.animation.frame_count = 5;
    EXPECT_EQ(animation_frame_count(scene), 5);
    // s = frame * 2 / 4 keys: 0, 0.5, 1, 1.5, 2.
    EXPECT_EQ(camera_at_frame(scene, 0).eye, Vec3(0, 0, 0));
    EXPECT_EQ(camera_at_frame(scene, 1).eye, Vec3(5, 0, 0));
    EXPECT_EQ(camera_at_frame(scene, 2).eye, Vec3(10, 0, 0));
    EXPECT_EQ(camera_at_frame(scene, 3).eye, Vec3(10, 5, 0));
    EXPECT_EQ(camera_at_frame(scene, 4).eye, Vec3(10, 10, 0));
}

TEST(CameraPath, LinearFrameKOfElevenIsAtXEqualsK) {
    const Scene scene = scene_with_eyes({{0, 0, 0}, {10, 0, 0}});
    for (int k = 0; k < 11; ++k) EXPECT_EQ(camera_at_frame(scene, k).eye, Vec3(k, 0, 0)) << "frame " << k;
}

TEST(CameraPath, LinearInterpolatesLookatSeparately) {
    // Eye from (0,0,10) to (20,0,10), look-at from (0,0,0) to (0,-10,0): frame 3 of 11 is
    // 3/10 of the way along each.
    const Scene scene = scene_with_path({{{0, 0, 10}, {0, 0, 0}}, {{20, 0, 10}, {0, -10, 0}}});
    const CameraKey camera = camera_at_frame(scene, 3);
    EXPECT_EQ(camera.eye, Vec3(6, 0, 10));
    EXPECT_EQ(camera.lookat, Vec3(0, -3, 0));
}

TEST(CameraPath, FixedLookatStaysExactlyPut) {
    const Vec3 lookat(0.1, 0.2, 0.3);
    for (Interpolation interpolation : {Interpolation::Linear, Interpolation::CatmullRom}) {
        const Scene scene = scene_with_path({{{0, 0, 1}, lookat}, {{1, 0, 1}, lookat}, {{1, 1, 1}, lookat}}, interpolation);
        for (int frame = 0; frame < animation_frame_count(scene); ++frame)
            EXPECT_EQ(camera_at_frame(scene, frame).lookat, lookat) << "frame " << frame;
    }
}

// Awkward coordinates (not representable in binary) so that any arithmetic on the way to a
// key frame would show up as a difference in the last bits.
TEST(CameraPath, FramesOnKeysAreExactlyTheKeys) {
    const std::vector<CameraKey> keys = {{{0.1, 1.0 / 3, -7.7}, {0.3, 0.6, 0.9}},
                                         {{2.2, -1.1, 1e-3}, {0.7, 0.1, 1.3}},
                                         {{5.5, 4.4, 3.3}, {-0.2, 0.4, 0.8}},
                                         {{-1.9, 0.05, 2.7}, {1.1, 2.2, 3.3}}};
    for (Interpolation interpolation : {Interpolation::Linear, Interpolation::CatmullRom}) {
        Scene scene = scene_with_path(keys, interpolation);
        scene.animation.frames_per_segment = 7;
        for (std::size_t i = 0; i < keys.size(); ++i) {
            const CameraKey camera = camera_at_frame(scene, static_cast<int>(i) * 7);
            EXPECT_EQ(camera.eye, keys[i].eye) << "key " << i;
            EXPECT_EQ(camera.lookat, keys[i].lookat) << "key " << i;
        }
        // With 7 frames over 3 segments, s = frame / 2: frames 0, 2, 4, 6 are keys.
        scene.animation.frame_count = 7;
        for (std::size_t i = 0; i < keys.size(); ++i)
            EXPECT_EQ(camera_at_frame(scene, static_cast<int>(i) * 2).eye, keys[i].eye) << "key " << i;
        // An odd count that no key but the ends lands on: the ends are still exact.
        scene.animation.frame_count = 100;
        EXPECT_EQ(camera_at_frame(scene, 0).eye, keys.front().eye);
        EXPECT_EQ(camera_at_frame(scene, 99).eye, keys.back().eye);
        EXPECT_EQ(camera_at_frame(scene, 99).lookat, keys.back().lookat);
    }
}

TEST(CameraPath, FramesOutsideTheAnimationAreRejected) {
    const Scene scene = scene_with_eyes({{0, 0, 0}, {10, 0, 0}});
    EXPECT_THROW(camera_at_frame(scene, -1), std::out_of_range);
    EXPECT_THROW(camera_at_frame(scene, 11), std::out_of_range);
    EXPECT_THROW(camera_at_frame(Scene{}, 0), std::invalid_argument);
}

TEST(CameraPath, CatmullRomOnCollinearEvenlySpacedKeysIsLinear) {
    const std::vector<Vec3> eyes = {{1, 2, 3}, {3, 3, 2}, {5, 4, 1}, {7, 5, 0}};
    Scene linear = scene_with_eyes(eyes, Interpolation::Linear);
    Scene smooth = scene_with_eyes(eyes, Interpolation::CatmullRom);
    for (int frame = 0; frame < animation_frame_count(linear); ++frame)
        expect_near(camera_at_frame(smooth, frame).eye, camera_at_frame(linear, frame).eye, 1e-12,
                    "frame " + std::to_string(frame));
}

// The unit square (0,0) (1,0) (1,1) (0,1) has every key, and the mirrored phantoms (-1,0) and
// (-1,1), one unit from its neighbour, so the centripetal knots are evenly spaced and the
// spline is the uniform one. By hand, with the matrix form at u = 1/2:
//   first segment, points (-1,0) (0,0) (1,0) (1,1): x = 0.5 * (1 + 0.25 - 0.125) = 0.5625,
//                                                   y = 0.5 * (-0.25 + 0.125) = -0.0625;
//   middle segment, points (0,0) (1,0) (1,1) (0,1): x = 0.5 * (2 + 0.5 - 0.25) = 1.125,
//                                                   y = 0.5 * (0.5 + 0.75 - 0.25) = 0.5.
TEST(CameraPath, CatmullRomOnTheUnitSquareMatchesHandValues) {
    Scene scene = scene_with_eyes({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, Interpolation::CatmullRom);
    scene.animation.frames_per_segment = 2;  // frames 1, 3, 5 are segment midpoints
    expect_near(camera_at_frame(scene, 1).eye, {0.5625, -0.0625, 0}, 1e-12, "first segment");
    expect_near(camera_at_frame(scene, 3).eye, {1.125, 0.5, 0}, 1e-12, "middle segment");
    expect_near(camera_at_frame(scene, 5).eye, {0.5625, 1.0625, 0}, 1e-12, "last segment (mirror image)");
}

TEST(CameraPath, CatmullRomWithEvenSpacingMatchesTheUniformFormula) {
    // A bent path of unit steps: evenly spaced, so centripetal = uniform.
    const std::vector<Vec3> eyes = {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {1, 1, 1}};
    Scene scene = scene_with_eyes(eyes, Interpolation::CatmullRom);
    scene.animation.frames_per_segment = 8;
    const Vec3 before = 2.0 * eyes[0] - eyes[1];
    const Vec3 after = 2.0 * eyes[3] - eyes[2];
    const std::vector<Vec3> padded = {before, eyes[0], eyes[1], eyes[2], eyes[3], after};
    for (int frame = 0; frame < animation_frame_count(scene); ++frame) {
        const int segment = frame / 8;
        const double u = (frame % 8) / 8.0;
        const Vec3 expected =
            segment == 3 ? eyes[3]
                         : uniform_catmull_rom(padded[segment], padded[segment + 1], padded[segment + 2], padded[segment + 3], u);
        expect_near(camera_at_frame(scene, frame).eye, expected, 1e-12, "frame " + std::to_string(frame));
    }
}

TEST(CameraPath, CatmullRomIsSmoothThroughTheKeys) {
    const std::vector<Vec3> eyes = {{0, 0, 0}, {4, 1, 0}, {5, 5, 2}, {1, 6, 3}, {-2, 2, 2}};
    Scene scene = scene_with_eyes(eyes, Interpolation::CatmullRom);
    scene.animation.frames_per_segment = 2000;
    const int count = animation_frame_count(scene);
    // Continuous: consecutive frames are close (the longest segment is about 5.5 long).
    for (int frame = 1; frame < count; ++frame)
        ASSERT_LT(length(camera_at_frame(scene, frame).eye - camera_at_frame(scene, frame - 1).eye), 0.01) << frame;
    // No kink at an inner key: the direction of motion just before and just after agree.
    for (int key = 1; key + 1 < static_cast<int>(eyes.size()); ++key) {
        const int frame = key * 2000;
        const Vec3 incoming = normalize(camera_at_frame(scene, frame).eye - camera_at_frame(scene, frame - 1).eye);
        const Vec3 outgoing = normalize(camera_at_frame(scene, frame + 1).eye - camera_at_frame(scene, frame).eye);
        EXPECT_GT(dot(incoming, outgoing), 0.999) << "key " << key;
    }
}

// Centripetal parameterisation does not overshoot: on unevenly spaced collinear keys the
// camera moves monotonically forward, never past a key and back (the uniform spline would).
TEST(CameraPath, CatmullRomDoesNotOvershootUnevenKeys) {
    Scene scene = scene_with_eyes({{0, 0, 0}, {1, 0, 0}, {1.2, 0, 0}, {20, 0, 0}}, Interpolation::CatmullRom);
    scene.animation.frames_per_segment = 200;
    double previous_x = -1;
    for (int frame = 0; frame < animation_frame_count(scene); ++frame) {
        const Vec3 eye = camera_at_frame(scene, frame).eye;
        EXPECT_GE(eye.x, previous_x) << "frame " << frame;
        EXPECT_EQ(eye.y, 0);
        previous_x = eye.x;
    }
}

TEST(CameraPath, CoincidentKeysHoldTheCameraStill) {
    const std::vector<Vec3> eyes = {{1, 1, 1}, {1, 1, 1}, {3, 1, 1}, {3, 1, 1}};
    for (Interpolation interpolation : {Interpolation::Linear, Interpolation::CatmullRom}) {
        const Scene scene = scene_with_eyes(eyes, interpolation);
        for (int frame = 0; frame <= 10; ++frame) EXPECT_EQ(camera_at_frame(scene, frame).eye, eyes[0]) << frame;
        for (int frame = 11; frame < 20; ++frame) {
            const Vec3 eye = camera_at_frame(scene, frame).eye;
            EXPECT_TRUE(std::isfinite(eye.x) && eye.x > 1 && eye.x < 3) << "frame " << frame << " x " << eye.x;
        }
        for (int frame = 20; frame <= 30; ++frame) EXPECT_EQ(camera_at_frame(scene, frame).eye, eyes[3]) << frame;
    }
}

}  // namespace
}  // namespace clr
