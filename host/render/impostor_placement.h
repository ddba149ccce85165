// Impostors become ordinary billboards for each frame: turned to face that frame's eye and
// showing the view taken from closest to it (docs/scene-format.md, Impostors). The kernels
// then see nothing but billboards.
#pragma once

#include <vector>

#include "scene/scene.h"

namespace clr {

// The camera quantities that placement depends on, all in scene coordinates.
struct PlacementCamera {
    Vec3 eye;
    Vec3 up;        // unit(scene up): the axis that upright impostors turn about
    Vec3 backward;  // w = unit(eye - lookat)
    Vec3 right;     // u = unit(up x w)

    PlacementCamera(const CameraKey& key, const Vec3& scene_up);
};

// Index of the view shown to `camera`: the highest score unit(eye - centre) . direction,
// the first of equal scores; -1 when the impostor has no views (a flat colour).
int choose_view(const Impostor& impostor, const PlacementCamera& camera);

// The billboard `impostor` is for one frame: front normal towards the eye, image upright. Its
// corners are relative to the camera's eye (corner - eye), computed from the centre less the
// eye in double: exact near the eye wherever the scene lies, as the device geometry is (in
// scene coordinates, corners near 1e15 would round to 1/8).
Billboard place_impostor(const Impostor& impostor, const PlacementCamera& camera);
// The same, written over `placed` (the same impostor's billboard of an earlier frame, or a
// default one): its image is only reassigned when the view shown changes.
void place_impostor(const Impostor& impostor, const PlacementCamera& camera, Billboard& placed);

// The scene's impostors placed for `camera`, in order, into `placed` (whose storage is reused
// from frame to frame), relative to the camera's eye.
void place_impostors(const Scene& scene, const PlacementCamera& camera, std::vector<Billboard>& placed);

}  // namespace clr
