// Every feature set a scene can have, for building programs ahead of need (the program store,
// device/program_store.h): FeatureSet::of's rules leave 38 of the 2^7 combinations of scene
// features.
#pragma once

#include <vector>

#include "render/feature_set.h"

namespace clr {

// Every FeatureSet that FeatureSet::of can give a scene (textures need billboards, alpha needs
// textures, sun needs spheres, mirrors need spheres or billboards, a BVH needs sun or mirrors),
// with `double_precision` and `float_output` as given; each once.
std::vector<FeatureSet> scene_feature_sets(bool double_precision, bool float_output);

}  // namespace clr
