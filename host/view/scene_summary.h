// GET /scene.json: what the page needs to know of the scene to start with: its camera, size,
// samples, and its camera path, one entry per key.
#pragma once

#include <string>

#include "scene/scene.h"

namespace clr {

// {"camera": {"eye", "lookat", "up", "fov"}, "size": [w, h], "spp": n, "frames": count,
//  "fps": f, "path": [{"eye", "lookat", "up", "fov"} per key], "name": "scene.json"}
std::string scene_summary_json(const Scene& scene);

}  // namespace clr
