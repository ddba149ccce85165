#include "render/feature_set.h"

#include <map>
#include <set>

#include "kinds/kinds.h"

namespace clr {
namespace {

// Whether two `triangle` surfaces of the scene differ in flat colour: each mesh has one, so only
// those, which share corners as one mesh (Mesh::surface_triangle), can show two at an edge.
bool surface_triangle_colors_differ(const Scene& scene) {
    const Mesh* first = nullptr;
    for (const Mesh& mesh : scene.meshes) {
        if (!mesh.surface_triangle) continue;
        if (!first)
            first = &mesh;
        else if (!(mesh.ambient.x == first->ambient.x && mesh.ambient.y == first->ambient.y &&
                   mesh.ambient.z == first->ambient.z))
            return true;
    }
    return false;
}

}  // namespace

FeatureSet FeatureSet::all() {
    FeatureSet features;
    features.spheres = features.billboards = features.triangles = features.planes = features.textures = true;
    features.triangle_ties = true;
    features.lights = features.clip = true;
    features.alpha = features.sun = features.mirrors = true;
    features.bvh = true;
    return features;
}

FeatureSet FeatureSet::general(const FeatureSet& specialised) {
    FeatureSet features = all();
    features.clip = specialised.clip;
    if (!specialised.mirrors && !specialised.lights) features.mirrors = features.lights = false;
    features.double_precision = specialised.double_precision;
    features.float_output = specialised.float_output;
    return features;
}

std::size_t FeatureSet::bvh_objects(const Scene& scene) {
    return scene.spheres.size() + scene.billboards.size() + scene.impostors.size() + scene.triangles.size();
}

FeatureSet FeatureSet::of(const Scene& scene) {
    FeatureSet features;
    features.spheres = !scene.spheres.empty();
    features.billboards = !scene.billboards.empty();
    features.triangles = !scene.triangles.empty();
    features.planes = !scene.planes.empty();
    features.lights = scene.lit_by_lights() && has_lit_objects(scene);
    features.clip = scene.clips();
    features.sun = scene.lit() && has_lit_objects(scene);  // the kinds the sun lights (kinds/kinds.h)
    for (const Sphere& sphere : scene.spheres) features.mirrors |= sphere.is_mirror;
    for (const Mesh& mesh : scene.meshes) features.mirrors |= mesh.is_mirror && mesh.triangle_count > 0;
    features.billboards |= !scene.impostors.empty();  // each impostor is a billboard in every frame
    std::set<const Image*> shown;  // each image once: thousands of impostors share a few
    for (const Billboard& billboard : scene.billboards) {
        features.mirrors |= billboard.is_mirror;
        if (billboard.image && !billboard.is_mirror) shown.insert(billboard.image.get());
    }
    for (const Impostor& impostor : scene.impostors) {
        for (const ImpostorView& view : impostor.views) shown.insert(view.image.get());
    }
    shown.erase(nullptr);
    features.textures = !shown.empty();
    for (const Image* image : shown) features.alpha |= image->has_transparency();
    // Primary rays are culled by screen tiles; shadow and mirror rays test every object
    // unless a BVH is compiled in, which pays from a few dozen objects on.
    features.bvh = (features.sun || features.lights || features.mirrors) && bvh_objects(scene) > kBvhMinObjects;
    features.triangle_ties = features.triangles && scene.has_triangle_ties &&
                             (features.sun || features.lights || features.mirrors || surface_triangle_colors_differ(scene));
    return features;
}

std::string FeatureSet::build_options() const {
    // std::map keeps the macros sorted by name.
    const std::map<std::string, bool> macros = {
        {"CLR_FEATURE_ALPHA", alpha},         {"CLR_FEATURE_BILLBOARDS", billboards},
        {"CLR_FEATURE_BVH", bvh},             {"CLR_FEATURE_CLIP", clip},             {"CLR_FEATURE_DOUBLE", double_precision},
        {"CLR_FEATURE_FLOAT_OUTPUT", float_output},
        {"CLR_FEATURE_LIGHTS", lights},       {"CLR_FEATURE_MIRRORS", mirrors},
        {"CLR_FEATURE_PLANES", planes},       {"CLR_FEATURE_SPHERES", spheres},
        {"CLR_FEATURE_SUN", sun},             {"CLR_FEATURE_TEXTURES", textures},
        {"CLR_FEATURE_TRIANGLES", triangles}, {"CLR_FEATURE_TRIANGLE_TIES", triangle_ties},
    };
    std::string options;
    for (const auto& [name, on] : macros) options += (options.empty() ? "" : " ") + ("-D" + name + "=" + (on ? "1" : "0"));
    return options;
}

}  // namespace clr
