// The pictures around the trees: the forest floor under them, the coarser ground that runs
// out to the horizon, and the mountain range in the distance.
#pragma once

#include "scripts/forest/canvas.h"
#include "scripts/forest/forest_layout.h"

namespace forest {

// Grass, moss and dirt over [-half_size, half_size] in x and z, darker under each tree (its
// litter and shade) and brighter in the clearings. Column 0 is x = -half_size, row 0 is
// z = -half_size, as the ground billboard maps it.
Canvas draw_forest_floor(const ForestLayout& layout, double half_size, int texels, std::uint32_t seed,
                         const clr::Vec3& towards_sun);

// The ground from the forest's edge to the horizon: broad patches of meadow and distant
// woods that fade into haze at the edges.
Canvas draw_far_ground(int texels, std::uint32_t seed);

// A snowy range with a wooded foothill ridge in front: opaque below the crest, transparent
// above it so the sky shows. `ground_row` is the row at ground level; below it the foothills
// go on, to hide the far ground's edge.
Canvas draw_mountains(int width, int height, int ground_row, std::uint32_t seed);

}  // namespace forest
