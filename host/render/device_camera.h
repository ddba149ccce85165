// The camera of one frame as the kernels see it (ClrCamera), computed in double from the
// SPEC's convention and rounded to float once.
#pragma once

#include "core/vec3.h"
#include "shared/clr_types.h"

namespace clr {

// eye, lookat and up as in the scene; fov_degrees spans the larger image dimension.
ClrCamera make_device_camera(const Vec3& eye, const Vec3& lookat, const Vec3& up, double fov_degrees, int width,
                             int height);

}  // namespace clr
