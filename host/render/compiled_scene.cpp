#include "render/compiled_scene.h"

#include <map>

#include "render/device_structs.h"

namespace clr {
namespace {

ClrSphere compile_sphere(const Sphere& sphere, const Vec3& origin) {
    ClrSphere out{};
    out.center_radius = to_float4(sphere.center - origin, static_cast<float>(sphere.radius));
    out.color = to_float4(sphere.ambient);
    out.flags = sphere.is_mirror ? CLR_SURFACE_MIRROR : 0u;
    return out;
}

// Texels of each distinct image, appended once however many billboards show it.
class TexelPacker {
public:
    explicit TexelPacker(std::vector<std::uint8_t>& texels) : texels_(texels) {}

    std::uint32_t offset_of(const Image* image) {
        auto found = offsets_.find(image);
        if (found != offsets_.end()) return found->second;
        auto offset = static_cast<std::uint32_t>(texels_.size() / 4);
        texels_.insert(texels_.end(), image->rgba.begin(), image->rgba.end());
        offsets_.emplace(image, offset);
        return offset;
    }

private:
    std::vector<std::uint8_t>& texels_;
    std::map<const Image*, std::uint32_t> offsets_;
};

}  // namespace

ClrBillboard compile_billboard(const Billboard& billboard, const Vec3& origin) {
    // P = UL + a*edge_a + b*edge_b. With m = edge_a x edge_b, the dual vectors
    // (edge_b x m)/|m|^2 and (m x edge_a)/|m|^2 pick a and b out of P - UL by one dot product
    // each, for any parallelogram, and are computed here in double once per billboard.
    Vec3 edge_a = billboard.upper_right - billboard.upper_left;
    Vec3 edge_b = billboard.lower_left - billboard.upper_left;
    Vec3 m = cross(edge_a, edge_b);
    double m2 = dot(m, m);

    ClrBillboard out{};
    out.corner = to_float4(billboard.upper_left - origin);
    out.normal = to_float4(normalize(cross(edge_b, edge_a)));  // front: (LL-UL) x (UR-UL)
    out.dual_a = to_float4(cross(edge_b, m) / m2);
    out.dual_b = to_float4(cross(m, edge_a) / m2);
    out.color = to_float4(billboard.ambient);
    out.flags = billboard.is_mirror ? CLR_SURFACE_MIRROR : 0u;
    if (billboard.image && !billboard.is_mirror) {  // a mirror ignores its image
        out.flags |= CLR_SURFACE_TEXTURED;
        out.texture_width = billboard.image->width;
        out.texture_height = billboard.image->height;
        if (billboard.image->has_transparency()) out.flags |= CLR_SURFACE_HOLES;  // only these need alpha tests
    }
    return out;
}

void move_origin(CompiledScene& compiled, const Scene& scene, const Vec3& origin) {
    for (std::size_t i = 0; i < scene.spheres.size(); ++i)
        compiled.spheres[i].center_radius =
            to_float4(scene.spheres[i].center - origin, static_cast<float>(scene.spheres[i].radius));
    for (std::size_t i = 0; i < scene.billboards.size(); ++i)
        compiled.billboards[i].corner = to_float4(scene.billboards[i].upper_left - origin);
    compiled.info.sun = to_float4(scene.sun_location - origin);
}

CompiledScene compile_scene(const Scene& scene, const Vec3& origin) {
    CompiledScene compiled;
    compiled.features = FeatureSet::of(scene);
    for (const Sphere& sphere : scene.spheres) compiled.spheres.push_back(compile_sphere(sphere, origin));
    TexelPacker packer(compiled.texels);
    for (const Billboard& billboard : scene.billboards) {
        ClrBillboard out = compile_billboard(billboard, origin);
        if (out.flags & CLR_SURFACE_TEXTURED) out.texel_offset = packer.offset_of(billboard.image.get());
        compiled.billboards.push_back(out);
    }
    compiled.info.background = to_float4(scene.background);
    compiled.info.sun = to_float4(scene.sun_location - origin);
    compiled.info.sphere_count = static_cast<int>(scene.spheres.size());
    compiled.info.billboard_count = static_cast<int>(scene.billboards.size());
    compiled.info.max_depth = scene.max_depth;
    compiled.info.lit = scene.lit() ? 1 : 0;
    return compiled;
}

}  // namespace clr
