// Pictures of a tree model from several horizontal directions, made by a small orthographic
// ray-caster: the views of an impostor's view set.
#pragma once

#include <vector>

#include "scripts/forest/canvas.h"
#include "scripts/forest/tree_models.h"

namespace forest {

constexpr int kViewCount = 8;  // every 45 degrees around the tree

// The horizontal unit direction from the tree towards the camera of view `index`
// (0: +z, then turning towards +x).
clr::Vec3 view_direction(int index);

struct TreePictures {
    TreeKind kind;
    std::vector<Canvas> views;          // views[i] seen from view_direction(i)
    double width_over_height = 0.5;     // of every picture; the impostor keeps it
};

// The model seen from far away along `direction` (horizontal): the picture's top row is up and
// its right column towards up x direction, as an eye at +direction sees it. Texels are opaque
// where the tree is and fully transparent elsewhere; the bottom row is the ground under the
// trunk. Lit from `towards_light` (unit), with soft self-shadowing of the foliage.
Canvas render_tree_view(const TreeModel& model, const clr::Vec3& direction, const clr::Vec3& towards_light,
                        int picture_width, int picture_height);

// All views of a kind at `picture_height` texels tall; the width follows the model's shape.
TreePictures render_tree_pictures(TreeKind kind, const TreeModel& model, const clr::Vec3& towards_light,
                                  int picture_height);

}  // namespace forest
