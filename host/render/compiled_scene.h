// The seam between the scene model and the device: a Scene flattened into the shared
// structs of kernels/shared/clr_types.h, the texel buffer and the feature set.
#pragma once

#include <cstdint>
#include <vector>

#include "render/feature_set.h"
#include "scene/scene.h"
#include "shared/clr_types.h"

namespace clr {

struct CompiledScene {
    std::vector<ClrSphere> spheres;
    std::vector<ClrBillboard> billboards;
    std::vector<std::uint8_t> texels;  // RGBA bytes of every shown image, one after another
    ClrSceneInfo info{};
    FeatureSet features;
};

// Positions are stored relative to `origin`: with the frame's eye as origin, float32 keeps
// full precision near the camera however far from (0, 0, 0) the scene lies (a scene at 1e5
// would otherwise lose 1/128 of a unit to rounding).
CompiledScene compile_scene(const Scene& scene, const Vec3& origin = {});

// Re-expresses the positions in `compiled` (made from `scene`) relative to `origin`, leaving
// everything else (texels, flags, features) as it is: what each frame of an animation needs,
// without repacking images.
void move_origin(CompiledScene& compiled, const Scene& scene, const Vec3& origin);

// The device form of one billboard, relative to `origin`; texel_offset is filled in by
// compile_scene.
ClrBillboard compile_billboard(const Billboard& billboard, const Vec3& origin = {});

}  // namespace clr
