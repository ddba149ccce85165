// The scene's `obj` objects: Wavefront OBJ meshes placed in the scene (docs/scene-format.md,
// Meshes). Reading a scene takes two steps, as for images: the `obj` values are checked with
// the rest of the scene (read_mesh_objects), and the files are read only once the whole scene
// is valid (load_meshes), each into Scene::triangles in scene coordinates.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "scene/json_reader.h"
#include "scene/scene.h"

namespace clr {

// Most triangles all of a scene's meshes may hold together: the renderer keeps about 250
// bytes a triangle on the host and the device (scene model, device struct, normals, BVH).
constexpr std::size_t kMaxSceneTriangles = std::size_t(1) << 24;

// What a placed triangle takes to load and render, as measured (docs/robustness.md, Memory):
// the peak of a still of terrains of 1M and 2M triangles grew by 590-620 MB a million, the
// OBJ's text included, and a lit one by 70 MB a million more for its neighbours on shared
// edges (scene/triangle_ties.h); a margin on top for corner normals.
constexpr std::uint64_t kPlacedTriangleBytes = 780;

// A mesh whose file is still to be read: its settings, and its "filename" value.
struct PendingMesh {
    Mesh mesh;
    Node filename;
    Node node;  // the `obj` object, for messages about the whole mesh
    bool ambient_given = false;
};

// The keys that place a mesh's file, as an `obj` object and a fall 2019 `mesh` surface give
// them: "filename" (required), "position", "scale". The caller reads the others.
PendingMesh read_mesh_placement(ObjectReader& fields, const Node& node);

// Adds one triangle with `corners` as a mesh of its own (a fall 2019 `triangle` surface);
// refused at `node` when it has no area.
void add_triangle(Scene& scene, Mesh mesh, const std::array<Vec3, 3>& corners, const Node& node);

// Checks the scene's "obj" value (one object or a list of them) and its keys.
std::vector<PendingMesh> read_mesh_objects(ObjectReader& file);

// Reads each mesh's OBJ (relative to the scene's folder) into `scene`'s meshes, triangles and
// corner normals. A file that cannot be read is the scene's error at its "filename", or, with
// `placeholders`, a warning and a unit cube in its place. A file whose parse, or a scene whose
// triangles at kPlacedTriangleBytes each, would take more than `memory_budget` bytes ends the
// run with exit 6 (kExitOutOfMemory) at the "filename" that brings it there.
void load_meshes(Scene& scene, const std::vector<PendingMesh>& pending, bool placeholders, std::uint64_t memory_budget);

}  // namespace clr
