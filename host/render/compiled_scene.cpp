#include "render/compiled_scene.h"

#include <algorithm>
#include <cstdint>
#include <set>
#include <string>

#include "core/errors.h"
#include "core/parallel_for.h"
#include "core/usable_cpus.h"
#include "kinds/kinds.h"
#include "render/coverage_mask.h"
#include "render/device_structs.h"

namespace clr {
namespace {

constexpr std::uint64_t kMaxPackedTexels = 0xFFFFFFFFull;
// Triangles a worker moves to a new eye at a time (compile_frame).
constexpr std::size_t kTrianglesPerTask = 1u << 15;

// Appends each distinct image's texels once, however many billboards and views show it, and
// scans it for transparency once, into its flag and its coverage bits.
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
    append_coverage(image->rgba, first_texel, compiled.coverage);
    compiled.textures.emplace(image, slot);
}

// The texel buffer at its final size before the first image goes in: growing it image by image
// copied the packed texels again at each doubling and faulted in every page of each new block.
void reserve_texels(const Scene& scene, CompiledScene& compiled) {
    std::set<const Image*> images;
    for (const Billboard& billboard : scene.billboards)
        if (!billboard.is_mirror && billboard.image) images.insert(billboard.image.get());
    for (const Impostor& impostor : scene.impostors)
        for (const ImpostorView& view : impostor.views)
            if (view.image) images.insert(view.image.get());
    std::size_t bytes = 0;
    for (const Image* image : images) bytes += image->rgba.size();
    // Past the addressable texels pack_texture() names the image that overflows; reserving
    // that much first would only turn its clear error into running out of memory.
    if (bytes / 4 <= kMaxPackedTexels) compiled.texels.reserve(bytes);  // untouched: huge pages advised
}

const TextureSlot* texture_of(const Billboard& billboard, const CompiledScene& compiled) {
    if (!billboard.image || billboard.is_mirror) return nullptr;  // a mirror ignores its image
    return &compiled.textures.at(billboard.image.get());
}

}  // namespace

std::size_t triangle_device_bytes(const Scene& scene) {
    const std::size_t ties = FeatureSet::of(scene).triangle_ties ? scene.triangles.size() * 6 * sizeof(cl_int) : 0;
    return scene.triangles.size() * sizeof(ClrTriangle) + scene.meshes.size() * sizeof(ClrMeshSurface) +
           scene.corner_normals.size() * 3 * sizeof(cl_float4) + ties;
}

CompiledScene compile_scene(const FrameGeometry& frame, const Vec3& origin) {
    const Scene& scene = frame.scene();
    CompiledScene compiled;
    compiled.features = FeatureSet::of(scene);
    for (const Sphere& sphere : scene.spheres) compiled.spheres.push_back(SphereKind::device(sphere, origin));
    compiled.triangles.reserve(scene.triangles.size());
    for (const Triangle& triangle : scene.triangles)
        compiled.triangles.push_back(TriangleKind::device(scene, triangle, origin));
    compiled.mesh_surfaces.reserve(scene.meshes.size());
    for (const Mesh& mesh : scene.meshes) compiled.mesh_surfaces.push_back(TriangleKind::mesh_surface(mesh));
    compiled.triangle_normals.reserve(scene.corner_normals.size() * 3);
    for (const auto& normals : scene.corner_normals)
        for (const Vec3& normal : normals) compiled.triangle_normals.push_back(to_float4(normal));
    for (const Plane& plane : scene.planes) compiled.planes.push_back(PlaneKind::device(plane, origin));
    compiled.lights.resize(scene.lights.size());
    for (std::size_t i = 0; i < scene.lights.size(); ++i) compiled.lights[i].color = to_float4(scene.lights[i].color);
    for (const Material& material : scene.materials) {
        ClrMaterial device{};
        device.diffuse = to_float4(material.diffuse, static_cast<float>(material.phong_exponent));
        device.specular = to_float4(material.specular);
        device.mirror = to_float4(material.mirror);
        compiled.materials.push_back(device);
    }
    reserve_texels(scene, compiled);
    for (const Billboard& billboard : scene.billboards) {
        if (!billboard.is_mirror) pack_texture(billboard.image.get(), compiled);
        compiled.billboards.push_back(BillboardKind::device(billboard, texture_of(billboard, compiled), origin));
    }
    // Every view, not only those placed for this frame: a later frame may show any of them.
    for (const Impostor& impostor : scene.impostors) {
        for (const ImpostorView& view : impostor.views) pack_texture(view.image.get(), compiled);
    }
    compiled.info.background = to_float4(scene.background);
    compiled.info.max_depth = scene.max_depth;
    compiled.info.lit = scene.lit() ? 1 : 0;
    compiled.info.sphere_count = static_cast<int>(scene.spheres.size());
    compiled.info.triangle_count = static_cast<int>(scene.triangles.size());
    compiled.info.plane_count = static_cast<int>(scene.planes.size());
    compiled.info.light_count = scene.lit_by_lights() ? static_cast<int>(scene.lights.size()) : 0;
    compile_frame(compiled, frame, origin);
    return compiled;
}

void compile_frame(CompiledScene& compiled, const FrameGeometry& frame, const Vec3& origin) {
    const Scene& scene = frame.scene();
    for (std::size_t i = 0; i < scene.spheres.size(); ++i)
        SphereKind::move(compiled.spheres[i], scene.spheres[i], origin);
    for (std::size_t i = 0; i < scene.billboards.size(); ++i)
        BillboardKind::move(compiled.billboards[i], scene.billboards[i], origin);
    // A moving camera re-expresses every triangle each frame: a million took 35-44 ms on one
    // core. On every usable one, unless another loop has the worker threads (the screen tiles'
    // binning, which runs beside this for smaller meshes): the same structs either way.
    const std::size_t triangle_tasks = (scene.triangles.size() + kTrianglesPerTask - 1) / kTrianglesPerTask;
    parallel_for(triangle_tasks, static_cast<std::size_t>(usable_cpu_count()), [&](std::size_t task) {
        const std::size_t end = std::min(scene.triangles.size(), (task + 1) * kTrianglesPerTask);
        for (std::size_t i = task * kTrianglesPerTask; i < end; ++i)
            TriangleKind::move(compiled.triangles[i], scene.triangles[i], origin);
    });
    for (std::size_t i = 0; i < scene.planes.size(); ++i) PlaneKind::move(compiled.planes[i], scene.planes[i], origin);
    for (std::size_t i = 0; i < scene.lights.size(); ++i)
        compiled.lights[i].position = to_float4(scene.lights[i].position - origin);
    compiled.billboards.resize(frame.billboard_count());
    const std::size_t first = frame.first_impostor();
    compiled.impostor_textures.resize(frame.billboard_count() - first, {nullptr, nullptr});
    for (std::size_t i = first; i < frame.billboard_count(); ++i) {
        const Billboard& billboard = frame.billboard(i);
        auto& [image, texture] = compiled.impostor_textures[i - first];
        if (image != billboard.image.get()) {
            image = billboard.image.get();
            texture = texture_of(billboard, compiled);
        }
        // Placed relative to the key's eye: with that eye as `origin` (as the renderer has it)
        // the corners go to float as they were placed, exactly.
        compiled.billboards[i] = BillboardKind::device(billboard, texture, origin - frame.billboard_origin(i));
    }
    compiled.info.sun = to_float4(scene.sun_location - origin);
    compiled.info.billboard_count = static_cast<int>(compiled.billboards.size());
}

}  // namespace clr
