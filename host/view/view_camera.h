// The camera a viewer request asks for, resolved against the scene: what the query leaves out
// is the scene's (its first camera key, or the key of frame=N of its path; its up vector, field
// of view, size and samples per pixel). The values are checked by the scene loader itself, on a
// scene made of just them, so that a request is refused exactly where
// `clrender SCENE -D eye=[..] -D lookat=[..] -D up=[..] -D fov_angle=.. --size WxH --spp N`
// would be, with the same limits and messages.
#pragma once

#include "scene/scene.h"
#include "view/view_parameters.h"

namespace clr {

struct ViewCamera {
    CameraKey key;
    Vec3 up;
    double fov_degrees = 60;
    int width = 0, height = 0;
    SamplingSettings sampling;
    int frame = 0;  // the animation frame whose sample pattern (seed) the frame uses
};

// Throws ParameterError naming the query parameter at fault ("eye", "up", "fov", "size",
// "spp", "frame").
ViewCamera resolve_view_camera(const Scene& scene, const ViewQuery& query);

// `scene` seen by `view`: a still with the view's single camera key and settings; everything
// else as it is (for the pixel explainer, which reads the camera from a scene).
Scene scene_seen_by(const Scene& scene, const ViewCamera& view);

}  // namespace clr
