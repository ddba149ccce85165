// The camera's flight: in low over the forest, once around the tree that stands alone in the
// big clearing, then up over it and on towards the mountains.
#pragma once

#include <vector>

#include "scene/scene.h"

namespace forest {

// How far the orbit keeps from the lone tree's trunk, and how high: far enough for the whole
// tree, from its base to its top, to fit in the picture.
constexpr double kOrbitRadius = 12.5;
constexpr double kOrbitEyeHeight = 4.0;

// The keys of the path, the lone tree standing at the origin.
std::vector<clr::CameraKey> flight_keys();

// The eye at `samples` evenly spread frames of the path, interpolated as clrender will
// (centripetal Catmull-Rom): the positions the forest must keep clear of.
std::vector<clr::Vec3> sample_eyes(const std::vector<clr::CameraKey>& keys, int samples);

}  // namespace forest
