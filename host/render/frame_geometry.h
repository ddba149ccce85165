// What one frame shows, in double: the scene's spheres and billboards in scene coordinates, and
// its impostors placed as billboards for the frame's camera key (impostor_placement.h),
// relative to that key's eye (billboard_origin() says which holds for a billboard). It is
// the one source of everything the device sees of a frame's geometry, derived in one
// direction: the device structs (compile_scene), the BVH (build_bvh) and the screen tiles
// (bin_screen_tiles), so the three always describe the same objects in the same order.
#pragma once

#include <cstddef>
#include <vector>

#include "scene/scene.h"

namespace clr {

class FrameGeometry {
public:
    // `scene` must outlive this object. Its impostors show once placed for a camera key.
    explicit FrameGeometry(const Scene& scene) : scene_(&scene) {}

    // Places the impostors for a camera at `key`; nothing else moves from frame to frame.
    void place_impostors(const CameraKey& key);
    // The eye the impostors were last placed for: their corners are relative to it.
    const Vec3& impostor_origin() const { return impostor_origin_; }

    const Scene& scene() const { return *scene_; }
    const std::vector<Sphere>& spheres() const { return scene_->spheres; }
    const std::vector<Triangle>& triangles() const { return scene_->triangles; }

    // Billboard i as the kernels index it: the scene's own billboards first, then its impostors
    // as placed, in the scene's order.
    std::size_t billboard_count() const { return scene_->billboards.size() + placed_impostors_.size(); }
    const Billboard& billboard(std::size_t i) const {
        std::size_t own = scene_->billboards.size();
        return i < own ? scene_->billboards[i] : placed_impostors_[i - own];
    }
    std::size_t first_impostor() const { return scene_->billboards.size(); }  // index of the first placed impostor
    // The point that billboard i's corners are relative to: (0, 0, 0) for the scene's own,
    // impostor_origin() for the placed impostors. Relative to another origin O, its corners are
    // corner - (O - billboard_origin(i)): exact for an impostor when O is the eye it was placed for.
    Vec3 billboard_origin(std::size_t i) const { return i < first_impostor() ? Vec3{} : impostor_origin_; }

    std::size_t object_count() const { return spheres().size() + billboard_count() + triangles().size(); }

private:
    const Scene* scene_;
    std::vector<Billboard> placed_impostors_;  // scene_->impostors placed for the last key
    Vec3 impostor_origin_;                     // that key's eye
};

}  // namespace clr
