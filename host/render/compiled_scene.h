// The seam between the scene model and the device: a Scene flattened into the shared
// structs of kernels/shared/clr_types.h, the texel buffer and the feature set.
#pragma once

#include <cstdint>
#include <map>
#include <vector>

#include "render/feature_set.h"
#include "scene/scene.h"
#include "shared/clr_types.h"

namespace clr {

// Where one image's texels sit in the texel buffer, and what the kernels need to know of it.
struct TextureSlot {
    std::uint32_t offset = 0;  // first texel
    int width = 0, height = 0;
    bool holes = false;  // some alpha below 255: rays must test it
};

struct CompiledScene {
    std::vector<ClrSphere> spheres;
    // The scene's billboards, then its impostors as placed for the current camera.
    std::vector<ClrBillboard> billboards;
    std::vector<std::uint8_t> texels;  // RGBA bytes of every image a billboard or view may show
    std::map<const Image*, TextureSlot> textures;  // each image's place in `texels`
    ClrSceneInfo info{};
    FeatureSet features;
    std::vector<Billboard> placed_impostors;  // in scene coordinates: billboards[scene's count + i]
};

// Positions are stored relative to `origin`: with the frame's eye as origin, float32 keeps
// full precision near the camera however far from (0, 0, 0) the scene lies (a scene at 1e5
// would otherwise lose 1/128 of a unit to rounding). Impostors are placed for the scene's
// first camera key; place_impostors() moves them to another.
CompiledScene compile_scene(const Scene& scene, const Vec3& origin = {});

// Places the scene's impostors for a camera at `key` (impostor_placement.h) and recompiles
// their billboards relative to `origin`.
void place_impostors(CompiledScene& compiled, const Scene& scene, const CameraKey& key, const Vec3& origin);

// Re-expresses the positions in `compiled` (made from `scene`) relative to `origin`, leaving
// everything else (texels, flags, features) as it is: what each frame of an animation needs,
// without repacking images.
void move_origin(CompiledScene& compiled, const Scene& scene, const Vec3& origin);

// The device form of one billboard, relative to `origin`, showing the image at `texture`
// (null: its flat colour).
ClrBillboard compile_billboard(const Billboard& billboard, const TextureSlot* texture, const Vec3& origin = {});

// `scene` with its impostors turned into billboards placed for `compiled`'s current camera
// (after the scene's own billboards, in order), for the host-side structures that see
// billboards only: screen tiles and the BVH.
Scene placed_scene(const Scene& scene, const CompiledScene& compiled);

}  // namespace clr
