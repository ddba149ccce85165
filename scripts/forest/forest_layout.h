// Where everything of the forest stands: the trees, the clearings, the boulders and the
// camera's path, all drawn from one seed.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "scene/scene.h"
#include "scripts/forest/canvas.h"
#include "scripts/forest/tree_models.h"

namespace forest {

struct ForestOptions {
    int trees = 3000;
    std::uint64_t seed = 1;
    int frames = 240;
    int width = 1280, height = 720;
};

struct TreeInstance {
    TreeKind kind;
    clr::Vec3 base;  // on the ground, y = 0
    double height, width;
};

struct Boulder {
    clr::Vec3 centre;
    double radius;
    Colour colour;
};

struct Clearing {
    double x, z, radius;
};

struct ForestLayout {
    double half_extent = 0;            // trees stand in [-half_extent, half_extent] in x and z
    std::vector<TreeInstance> trees;   // trees[0] is the lone tree in the big clearing
    std::vector<Boulder> boulders;
    std::vector<Clearing> clearings;   // clearings[0] is the big one around the lone tree
    std::vector<clr::CameraKey> camera;
};

// How far a tree keeps from every eye position of the path (beyond half its width).
constexpr double kCameraMargin = 1.5;

// Places options.trees trees (the lone tree included); `width_over_height` gives each kind's
// picture shape, so that a tree's width matches its pictures. Throws std::runtime_error when
// the trees do not fit.
ForestLayout plan_forest(const ForestOptions& options, const std::array<double, 3>& width_over_height);

}  // namespace forest
