// Conversions from the host's double-precision values to the shared device structs.
#pragma once

#include "core/vec3.h"
#include "shared/clr_types.h"

namespace clr {

inline clr_float4 to_float4(const Vec3& v, float w = 0.0f) {
    clr_float4 out;
    out.s[0] = static_cast<float>(v.x);
    out.s[1] = static_cast<float>(v.y);
    out.s[2] = static_cast<float>(v.z);
    out.s[3] = w;
    return out;
}

}  // namespace clr
