#include "render/feature_combinations.h"

namespace clr {

std::vector<FeatureSet> scene_feature_sets(bool double_precision, bool float_output) {
    std::vector<FeatureSet> sets;
    for (int bits = 0; bits < (1 << 7); ++bits) {
        FeatureSet features;
        features.spheres = bits & 1;
        features.billboards = bits & 2;
        features.textures = bits & 4;
        features.alpha = bits & 8;
        features.sun = bits & 16;
        features.mirrors = bits & 32;
        features.bvh = bits & 64;
        features.double_precision = double_precision;
        features.float_output = float_output;
        if (features.textures && !features.billboards) continue;
        if (features.alpha && !features.textures) continue;
        if (features.sun && !features.spheres) continue;
        if (features.mirrors && !features.spheres && !features.billboards) continue;
        if (features.bvh && !features.sun && !features.mirrors) continue;
        sets.push_back(features);
    }
    return sets;
}

std::vector<FeatureSet> store_feature_sets(bool double_precision, bool float_output) {
    std::vector<FeatureSet> sets = scene_feature_sets(double_precision, float_output);
    FeatureSet specialised;
    specialised.double_precision = double_precision;
    specialised.float_output = float_output;
    for (bool mirrors : {true, false}) {
        specialised.mirrors = mirrors;
        for (bool clip : {false, true}) {
            specialised.clip = clip;
            sets.push_back(FeatureSet::general(specialised));
        }
    }
    return sets;
}

}  // namespace clr
