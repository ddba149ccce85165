// The three kinds of tree as small 3D models, built from two primitives that are easy to
// ray-cast: balls (leaf clumps, branches, cones) and vertical frusta (trunks, a conifer's
// tiers). A model stands on y = 0 with its trunk on the y axis and is about 1 unit tall; the
// scene scales its pictures to each tree's size.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "scripts/forest/canvas.h"

namespace forest {

enum class TreeKind { Conifer, Broadleaf, Birch };
constexpr TreeKind kTreeKinds[] = {TreeKind::Conifer, TreeKind::Broadleaf, TreeKind::Birch};

// Name of a kind's view set in the scene, and the prefix of its pictures' files.
std::string kind_name(TreeKind kind);

// How a surface is shaded: foliage gets a leafy speckle, bark a grain, birch bark its marks.
enum class Surface { Leaves, Bark, BirchBark };

struct Ball {
    clr::Vec3 centre;
    double radius;
    Colour colour;
    Surface surface;
};

// A truncated cone standing upright on the axis through (x, z): radius r0 at y0, r1 at y1.
struct Frustum {
    double x, z;
    double y0, y1;
    double r0, r1;
    Colour colour;
    Surface surface;
};

struct TreeModel {
    std::vector<Ball> balls;
    std::vector<Frustum> frusta;
    double top = 0;         // highest point
    double half_width = 0;  // farthest horizontal reach from the axis
};

// The model of a kind; `seed` varies its clumps (every tree of a kind in a scene shares it).
TreeModel build_tree_model(TreeKind kind, std::uint64_t seed);

}  // namespace forest
