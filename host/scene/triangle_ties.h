#pragma once
// Which triangle a ray through a shared mesh edge or vertex is shaded as (docs/scene-format.md,
// Meshes, "Shared edges and vertices"). The kernels (kernels/kinds/triangle.cl,
// triangle_settled_index()) and the reference (reference/shade.cpp) settle such a hit on the
// lowest-numbered triangle there, so float, double and the reference agree whichever side of
// the edge their rounding took; this file finds, for each triangle, the neighbours that rule
// needs.

#include <array>
#include <cstdint>
#include <vector>

#include "scene/scene.h"

namespace clr {

// Fills Scene::triangle_ties: for each triangle, [k] (k = 0..2) the lowest-numbered other
// triangle sharing its edge opposite corner k, [3 + k] the lowest-numbered other triangle
// around its corner k, its own index where none does. Triangles share a corner where the
// corners' positions are exactly equal (+0 and -0 alike), among the triangles of one mesh
// placement, or among all the `triangle` surfaces of a scene (Mesh::surface_triangle). A
// placement of the same file and scale as an earlier one reuses that one's neighbours, shifted,
// after checking each shared position.
// Meshes already tied when they were placed (Mesh::tied, tie_placed_mesh()) keep theirs.
void compute_triangle_ties(Scene& scene);

// The ties of the triangles Scene::triangles[first_triangle, + corners.size()) of one mesh
// placement, whose corners are `positions`[corners[t][k]] (a model's vertices once placed:
// numbering them is cheaper than numbering every corner).
void tie_placed_mesh(Scene& scene, std::size_t first_triangle, const std::vector<Vec3>& positions,
                     const std::vector<std::array<std::uint32_t, 3>>& corners);

}  // namespace clr
