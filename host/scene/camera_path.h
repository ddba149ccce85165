// Turns a scene's camera keys into one camera per animation frame (docs/scene-format.md,
// Camera and camera path; the settings are in docs/scene-format.md, Extensions). The frames
// are spread at constant parameter speed: every segment between two keys gets the same share
// of frames, whatever its length.
#pragma once

#include "scene/scene.h"

namespace clr {

// Frames the scene renders: 1 for a still; for N >= 2 keys, scene.animation.frame_count when
// it is set (> 0), else (N - 1) * frames_per_segment + 1, so that the last key gets a frame
// of its own (11 frames for 2 keys with the default 10 per segment).
int animation_frame_count(const Scene& scene);

// The camera of frame `frame`, in [0, animation_frame_count(scene)). Frames that land on a key
// (the first and last frames always do) return that key exactly. Throws std::out_of_range
// for a frame outside the animation and std::invalid_argument for a scene without keys.
CameraKey camera_at_frame(const Scene& scene, int frame);

}  // namespace clr
