// The camera of one frame, computed once on the host from its camera key, from which both the
// kernels' ClrCamera and the screen tiles' projection are derived: the tiles then bound
// exactly the float rays the kernels trace (docs/scene-format.md, Conventions: Camera).
#pragma once

#include <limits>

#include "core/vec3.h"
#include "scene/scene.h"
#include "shared/clr_types.h"

namespace clr {

struct FrameCamera {
    // The scene point at device coordinates (0, 0, 0): device positions are differences taken
    // in double from it and rounded to float once (compile_scene).
    Vec3 origin;
    // Relative to `origin`, each component already rounded to float (held in doubles), so that
    // the host works with exactly the values the kernels get.
    Vec3 eye;
    Vec3 forward;  // -w, unit length
    Vec3 right;    // u scaled to half the image plane's width at distance 1
    Vec3 up;       // v scaled to half its height
    int width = 0;
    int height = 0;
    int samples = 1;          // 1: the pixel centre
    unsigned frame_seed = 0;  // with `samples` > 1, fixes the sample pattern (clr_samples.h)
    // The depths along `forward` that primary rays see (Scene::clip_near, clip_far).
    double clip_near = 0;
    double clip_far = std::numeric_limits<double>::infinity();

    Vec3 eye_in_scene() const { return eye + origin; }
    ClrCamera device() const;  // the kernels' form: the same values as floats, exactly
};

// eye, lookat and up in scene coordinates; fov_degrees spans the larger image dimension. One
// sample per pixel (its centre).
FrameCamera make_frame_camera(const Vec3& eye, const Vec3& lookat, const Vec3& up, double fov_degrees, int width,
                              int height, const Vec3& origin = {});

// Animation frame `frame` seen from `key`, with the scene's up vector, field of view, size and
// sampling. Its origin is the key's eye, so float precision near the camera does not depend on
// where the scene lies.
FrameCamera frame_camera(const Scene& scene, const CameraKey& key, int frame);

}  // namespace clr
