#include "render/feature_set.h"

#include <map>

namespace clr {

FeatureSet FeatureSet::all() {
    FeatureSet features;
    features.spheres = features.billboards = features.textures = true;
    features.alpha = features.sun = features.mirrors = true;
    features.bvh = true;
    return features;
}

FeatureSet FeatureSet::of(const Scene& scene) {
    FeatureSet features;
    features.spheres = !scene.spheres.empty();
    features.billboards = !scene.billboards.empty();
    features.sun = scene.lit() && features.spheres;  // only spheres are lit
    for (const Sphere& sphere : scene.spheres) features.mirrors |= sphere.is_mirror;
    for (const Billboard& billboard : scene.billboards) {
        features.mirrors |= billboard.is_mirror;
        bool shows_image = billboard.image && !billboard.is_mirror;
        features.textures |= shows_image;
        features.alpha |= shows_image && billboard.image->has_transparency();
    }
    // Primary rays are culled by screen tiles; shadow and mirror rays test every object
    // unless a BVH is compiled in, which pays from a few dozen objects on.
    features.bvh = (features.sun || features.mirrors) && scene.spheres.size() + scene.billboards.size() > kBvhMinObjects;
    return features;
}

std::string FeatureSet::build_options() const {
    // std::map keeps the macros sorted by name.
    const std::map<std::string, bool> macros = {
        {"CLR_FEATURE_ALPHA", alpha},         {"CLR_FEATURE_BILLBOARDS", billboards},
        {"CLR_FEATURE_BVH", bvh},             {"CLR_FEATURE_DOUBLE", double_precision},
        {"CLR_FEATURE_MIRRORS", mirrors},     {"CLR_FEATURE_SPHERES", spheres},
        {"CLR_FEATURE_SUN", sun},             {"CLR_FEATURE_TEXTURES", textures},
    };
    std::string options;
    for (const auto& [name, on] : macros) options += (options.empty() ? "" : " ") + ("-D" + name + "=" + (on ? "1" : "0"));
    return options;
}

}  // namespace clr
