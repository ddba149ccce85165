// The feature sets of the programs built ahead of need (the program store,
// device/program_store.h): every set a scene of spheres and billboards can have (FeatureSet::of's
// rules leave 38 of the 2^7 combinations of those features), and the four general programs that
// stand in for every other set (meshes, planes, lights, near/far) in a still
// (FeatureSet::general: with and without mirrors and lights, with and without clipping).
#pragma once

#include <vector>

#include "render/feature_set.h"

namespace clr {

// Every FeatureSet that FeatureSet::of can give a scene (textures need billboards, alpha needs
// textures, sun needs spheres, mirrors need spheres or billboards, a BVH needs sun or mirrors),
// with `double_precision` and `float_output` as given; each once.
std::vector<FeatureSet> scene_feature_sets(bool double_precision, bool float_output);

// scene_feature_sets() and then FeatureSet::general() with mirrors and lights, without and with
// clipping, then without mirrors and lights, without and with clipping.
std::vector<FeatureSet> store_feature_sets(bool double_precision, bool float_output);

}  // namespace clr
