// Whether a camera can render: it needs a view direction (eye != lookat) and a roll (up not
// parallel to the view). The scene loader checks every key of a path, and every frame
// between keys: two keys can each be fine while the interpolated eye passes through the
// interpolated look-at point, or the view turns parallel to up, between them; that frame
// would render blank (NaN directions) with no error.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "scene/json_reader.h"
#include "scene/scene.h"

namespace clr {

// Up is "parallel" to the view direction when the sine of the angle between them is below
// this. Both are unit vectors first, so the test does not depend on the scene's scale.
constexpr double kParallelSine = 1e-9;

// What is wrong with `camera` under `up`, as a message ending in its consequence, with
// `where` (" at camera key 2") after the facts; nullopt when it renders.
std::optional<std::string> camera_problem(const CameraKey& camera, const Vec3& up, const std::string& where);

// Fails at the location of the key that starts the segment (`key_locations[k]` for key k)
// when a frame strictly between two keys has a camera_problem(). Needs the scene's
// animation settings read; O(1) per frame.
void check_frames_between_keys(const Scene& scene, const std::vector<std::string>& key_locations,
                               const Diagnostics& diagnostics);

}  // namespace clr
