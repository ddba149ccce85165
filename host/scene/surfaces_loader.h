// The fall 2019 format (docs/scene-format.md, The fall 2019 format): `surfaces` (spheres,
// planes, triangles and OBJ meshes with Blinn-Phong materials) and `lights` (point lights).
// Read into the same scene model as the course's later formats: spheres join Scene::spheres,
// planes Scene::planes, triangles and meshes Scene::meshes.
#pragma once

#include <vector>

#include "scene/json_reader.h"
#include "scene/mesh_loader.h"
#include "scene/scene.h"

namespace clr {

// Most point lights a scene may have: each costs a shadow ray per lit pixel, and a
// thousand-light scene is a mistake that would render for hours rather than an intent.
constexpr std::size_t kMaxLights = 256;
// Most planes a scene may have: a plane has no bounds, so every ray tests every plane.
constexpr std::size_t kMaxPlanes = 256;

// Reads `surfaces` and `lights` when the file has them; returns the `mesh` surfaces, whose
// files load_meshes() reads once the whole scene is valid (a `triangle` is added at once).
// `lights` and `SunLocation` are two lighting models: a scene with both is refused (at /lights).
std::vector<PendingMesh> read_surfaces_and_lights(ObjectReader& file, Scene& scene);

}  // namespace clr
