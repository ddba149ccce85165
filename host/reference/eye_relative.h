// The reference traces a frame relative to its eye, as the kernels do (docs/architecture.md,
// Numerics): every position less the eye, taken in double. Near the eye, where the picture is
// decided, those differences are exact (two doubles within a factor of two of each other
// subtract exactly), so a hit point, a billboard's (alpha, beta) and a texel come out the same
// wherever the scene lies; in absolute coordinates a scene near 1e15, where doubles are 1/8
// apart, would put hit points up to 1/16 off and pick the wrong texels.
#pragma once

#include "reference/reference.h"

namespace clr::reference {

struct EyeRelative {
    Scene scene;          // positions less the eye: spheres, billboards, impostors, sun, camera keys
    CameraFrame camera;   // the same camera with its eye at (0, 0, 0)
    Vec3 eye;             // the eye in scene coordinates: add it back to show a position
};

EyeRelative relative_to_eye(const Scene& scene, const CameraFrame& camera);

}  // namespace clr::reference
