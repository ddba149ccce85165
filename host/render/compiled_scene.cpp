#include "render/compiled_scene.h"

#include <cstdint>
#include <string>

#include "core/errors.h"

#include "render/device_structs.h"
#include "render/impostor_placement.h"

namespace clr {
namespace {

constexpr std::uint64_t kMaxPackedTexels = 0xFFFFFFFFull;

ClrSphere compile_sphere(const Sphere& sphere, const Vec3& origin) {
    ClrSphere out{};
    out.center_radius = to_float4(sphere.center - origin, static_cast<float>(sphere.radius));
    out.color = to_float4(sphere.ambient);
    out.flags = sphere.is_mirror ? CLR_SURFACE_MIRROR : 0u;
    return out;
}

// Appends each distinct image's texels once, however many billboards and views show it, and
// scans it for transparency once.
void pack_texture(const Image* image, CompiledScene& compiled) {
    if (!image || compiled.textures.count(image)) return;
    // The kernels address texels with 32-bit offsets (ClrBillboard.texel_offset, and uint
    // arithmetic in kernels/common/texture.cl): every texel of every image must have an index
    // below 2^32, or the image would silently show another image's texels.
    const std::uint64_t first_texel = compiled.texels.size() / 4;
    const std::uint64_t texel_count = static_cast<std::uint64_t>(image->width) * static_cast<std::uint64_t>(image->height);
    if (first_texel + texel_count > kMaxPackedTexels) {
        throw SceneError(image->path, "", "the scene's images hold more than " + std::to_string(kMaxPackedTexels) +
                                              " texels together, more than one texture buffer can address");
    }
    TextureSlot slot;
    slot.offset = static_cast<std::uint32_t>(compiled.texels.size() / 4);
    slot.width = image->width;
    slot.height = image->height;
    slot.holes = image->has_transparency();
    compiled.texels.insert(compiled.texels.end(), image->rgba.begin(), image->rgba.end());
    compiled.textures.emplace(image, slot);
}

const TextureSlot* texture_of(const Billboard& billboard, const CompiledScene& compiled) {
    if (!billboard.image || billboard.is_mirror) return nullptr;  // a mirror ignores its image
    return &compiled.textures.at(billboard.image.get());
}

}  // namespace

ClrBillboard compile_billboard(const Billboard& billboard, const TextureSlot* texture, const Vec3& origin) {
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
    if (texture) {
        out.flags |= CLR_SURFACE_TEXTURED;
        out.texel_offset = texture->offset;
        out.texture_width = texture->width;
        out.texture_height = texture->height;
        if (texture->holes) out.flags |= CLR_SURFACE_HOLES;  // only these need alpha tests
    }
    return out;
}

void place_impostors(CompiledScene& compiled, const Scene& scene, const CameraKey& key, const Vec3& origin) {
    place_impostors(scene, PlacementCamera(key, scene.up), 0, compiled.placed_impostors);
    std::size_t first = scene.billboards.size();
    compiled.billboards.resize(first + compiled.placed_impostors.size());
    for (std::size_t i = 0; i < compiled.placed_impostors.size(); ++i) {
        const Billboard& billboard = compiled.placed_impostors[i];
        compiled.billboards[first + i] = compile_billboard(billboard, texture_of(billboard, compiled), origin);
    }
}

void move_origin(CompiledScene& compiled, const Scene& scene, const Vec3& origin) {
    for (std::size_t i = 0; i < scene.spheres.size(); ++i)
        compiled.spheres[i].center_radius =
            to_float4(scene.spheres[i].center - origin, static_cast<float>(scene.spheres[i].radius));
    for (std::size_t i = 0; i < scene.billboards.size(); ++i)
        compiled.billboards[i].corner = to_float4(scene.billboards[i].upper_left - origin);
    for (std::size_t i = 0; i < compiled.placed_impostors.size(); ++i)
        compiled.billboards[scene.billboards.size() + i].corner = to_float4(compiled.placed_impostors[i].upper_left - origin);
    compiled.info.sun = to_float4(scene.sun_location - origin);
}

CompiledScene compile_scene(const Scene& scene, const Vec3& origin) {
    CompiledScene compiled;
    compiled.features = FeatureSet::of(scene);
    for (const Sphere& sphere : scene.spheres) compiled.spheres.push_back(compile_sphere(sphere, origin));
    for (const Billboard& billboard : scene.billboards) {
        if (!billboard.is_mirror) pack_texture(billboard.image.get(), compiled);
        compiled.billboards.push_back(compile_billboard(billboard, texture_of(billboard, compiled), origin));
    }
    for (const Impostor& impostor : scene.impostors) {
        for (const ImpostorView& view : impostor.views) pack_texture(view.image.get(), compiled);
    }
    if (!scene.impostors.empty() && !scene.camera_path.empty()) place_impostors(compiled, scene, scene.camera_path.front(), origin);
    compiled.info.background = to_float4(scene.background);
    compiled.info.sun = to_float4(scene.sun_location - origin);
    compiled.info.sphere_count = static_cast<int>(scene.spheres.size());
    compiled.info.billboard_count = static_cast<int>(compiled.billboards.size());
    compiled.info.max_depth = scene.max_depth;
    compiled.info.lit = scene.lit() ? 1 : 0;
    return compiled;
}

Scene placed_scene(const Scene& scene, const CompiledScene& compiled) {
    Scene placed = scene;
    placed.impostors.clear();
    placed.billboards.insert(placed.billboards.end(), compiled.placed_impostors.begin(), compiled.placed_impostors.end());
    return placed;
}

}  // namespace clr
