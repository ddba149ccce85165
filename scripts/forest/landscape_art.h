// The pictures of the ground: the forest floor under the trees, and the coarser country that
// runs out to the mountains.
#pragma once

#include "scripts/forest/canvas.h"
#include "scripts/forest/forest_layout.h"

namespace forest {

// Grass, moss and dirt over [-half_size, half_size] in x and z, darker under each tree (its
// litter and shade) and brighter in the clearings. Column 0 is x = -half_size, row 0 is
// z = -half_size, as the ground billboard maps it.
Canvas draw_forest_floor(const ForestLayout& layout, double half_size, int texels, std::uint32_t seed,
                         const clr::Vec3& towards_sun);

// The colour of the air far away, which everything distant fades into.
constexpr Colour kHaze{0.66, 0.76, 0.86};

// How much of kHaze veils what lies `distance` metres from the forest's centre: none at the
// forest, about a quarter at the mountains' foot, half on the far peaks.
double haze_amount(double distance);

// The open country around the forest at (x, z), before haze: woods (crowns lit on top, gaps
// dark between them) and meadows. `detail` in [0, 1] scales the finest variation, which far
// away would only flicker, one texel shown per pixel.
Colour lowland_colour(double x, double z, double detail, std::uint32_t seed);

// The country from the forest's edge to the mountains, over [-half_size, half_size] in x and z
// (laid out like the forest floor): woods and meadows that fade into haze with distance.
Canvas draw_country(double half_size, int texels, std::uint32_t seed);

}  // namespace forest
