#include "render/frame_geometry.h"

#include "render/impostor_placement.h"

namespace clr {

void FrameGeometry::place_impostors(const CameraKey& key) {
    clr::place_impostors(*scene_, PlacementCamera(key, scene_->up), placed_impostors_);
    impostor_origin_ = key.eye;
}

}  // namespace clr
