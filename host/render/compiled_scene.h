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

CompiledScene compile_scene(const Scene& scene);

// The device form of one billboard; texel_offset is filled in by compile_scene.
ClrBillboard compile_billboard(const Billboard& billboard);

}  // namespace clr
