// The benchmark's scenes, generated in code from fixed seeds so that every run on every
// machine measures the same pictures.
//
// Every object shows a colour of its own that encodes its id (flat colour for spheres, the
// opaque texels of a billboard's private image), and shading is flat, so the image clrender
// renders is also a map of which object each pixel sees. That map is compared with the
// Embree peer's hit ids without any extra kernel: the comparison checks the very image that
// was timed.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace clr::bench {

struct BenchSceneSpec {
    std::string name;  // as printed and as given to --scenes
    int spheres = 0;
    int billboards = 0;
    int impostors = 0;  // upright, camera-facing, three views each (numbered after the billboards)
    // A displaced terrain of about this many triangles (one mesh), seen from above, lit by the
    // sun, with the spheres above it casting shadows: the "triangles" scenes.
    int terrain_triangles = 0;
    // The course's objects with a smooth ball of about this many triangles among them (a UV
    // sphere, less its poles' collapsed triangles), lit by the sun: "course + mesh".
    int ball_triangles = 0;
    bool unlit = false;  // a terrain scene in flat shading: its primary rays alone
    // `instances` copies of one smooth ball of about `instance_triangles` triangles, placed as
    // the same file placed again is (one tree shape, refitted: render/scene_bvh.h), in a 10-wide
    // grid on the ground, lit by the sun: "100x100k triangles".
    int instances = 0;
    int instance_triangles = 0;

    int objects() const { return spheres + billboards + impostors; }
    std::int64_t triangles() const {
        return std::int64_t{terrain_triangles} + ball_triangles + std::int64_t{instances} * instance_triangles;
    }
    bool terrain() const { return terrain_triangles > 0; }
    bool lit() const { return (terrain() || ball_triangles > 0 || instances > 0) && !unlit; }
};

// course, 16+16, 256+256, 4096+4096, 100k spheres, 10k impostors, 70k triangles,
// 70k triangles flat, 1M triangles, course + mesh, 100x100k triangles, in that order.
const std::vector<BenchSceneSpec>& bench_scene_specs();

// The spec named `name`; throws std::invalid_argument listing the names when none matches.
const BenchSceneSpec& find_bench_scene(const std::string& name);

// The scene of `spec` seen at width x height: black background, no mirrors, one still camera.
// Flat shading, with the camera at the origin looking down -z, except for the terrain scenes
// (spec.terrain()), whose camera looks down on the terrain and whose sun lights it (unless
// spec.unlit), and for "course + mesh", lit by the sun. The object
// layout depends on the aspect ratio only through the field of view, and not at all on
// anything but the arguments.
Scene make_bench_scene(const BenchSceneSpec& spec, int width, int height);

// Object ids as both peers report them: 0 is the background, 1 + i sphere i, and
// 1 + sphere_count + j billboard j (impostors count as billboards, after the others), and
// 1 + sphere_count + billboard_count + m every triangle of mesh m.
constexpr std::uint32_t kBackgroundId = 0;
inline std::uint32_t sphere_id(int index) { return 1u + static_cast<std::uint32_t>(index); }
inline std::uint32_t billboard_id(int sphere_count, int index) {
    return 1u + static_cast<std::uint32_t>(sphere_count) + static_cast<std::uint32_t>(index);
}

inline std::uint32_t mesh_id(int sphere_count, int billboard_count, int index) {
    return 1u + static_cast<std::uint32_t>(sphere_count) + static_cast<std::uint32_t>(billboard_count) +
           static_cast<std::uint32_t>(index);
}

// The colour that shows object `id` (ids below 2^24): its three display bytes are a
// scrambled 24-bit code of the id, so neighbouring ids get visibly different colours.
// The background id 0 is black.
Color id_color(std::uint32_t id);

// The id whose id_color() renders as these display bytes.
std::uint32_t id_of_bytes(std::uint8_t r, std::uint8_t g, std::uint8_t b);

// In a lit scene, whose colours no longer encode ids, two images' pixels may differ by this
// many display steps (of 255) in a channel without counting as differing: the two sides'
// normals and n.l are the same float operations, but their barycentric coordinates are not
// (Embree's u, v against the kernels' own).
constexpr int kLitTolerance = 2;

// The id of every pixel of a rendered image, rows from the top.
std::vector<std::uint32_t> object_ids(const Image& image);

}  // namespace clr::bench
