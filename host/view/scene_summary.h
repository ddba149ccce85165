// GET /scene.json: what the page needs to know of the scene to start with: its camera, size,
// samples, and its camera path, one entry per key; and GET /camera.json, one frame's camera.
#pragma once

#include <string>

#include "scene/scene.h"

namespace clr {

// A file name as the page shows it: escaped by printable() (core/printable_text.h), as on the
// terminal, so that a bidirectional override, an invisible or a control character, or invalid
// UTF-8 in the name is seen as \xNN rather than reordering or hiding what the reader sees.
// Escaped here, where the names leave the server, rather than in the page: one escaper for
// every message, the page's text the same as the terminal's.
std::string shown_name(const std::string& name);

// {"camera": {"eye", "lookat", "up", "fov"}, "size": [w, h], "spp": n, "frames": count,
//  "fps": f, "path": [{"eye", "lookat", "up", "fov"} per key], "name": "scene.json"}
std::string scene_summary_json(const Scene& scene);

// GET /camera.json?frame=N: {"frame": N, "eye", "lookat", "up", "fov"}, the camera of frame N
// of the scene's animation placed by camera_at_frame(), as a batch render of that frame places
// it (a Catmull-Rom path too). The page records this camera at a path frame rather than
// placing the frame itself. `frame` must be one of the animation's frames.
std::string frame_camera_json(const Scene& scene, int frame);

}  // namespace clr
