// The mountains all around the forest: a ring of upright pictures, each a piece of one
// panorama of a range drawn as seen from the forest's centre. Neighbours overlap, and both show
// the same peaks where they meet, so the skyline runs on from one picture into the next.
#pragma once

#include <cstdint>
#include <vector>

#include "scripts/forest/canvas.h"

namespace forest {

struct MountainRing {
    int count = 16;              // pictures, evenly spread around the horizon
    double distance = 1500;      // from the forest's centre to the middle of each picture
    // Seen from the centre, a picture spans +-half_angle degrees; within +-full_half_angle the
    // range stands at full height, and beyond it sinks to the ground, so that the picture's end
    // lies low behind its neighbour and never shows as a cut. Both exceed 180 / count, so that
    // each neighbour's full part still covers the seam when the eye is away from the centre.
    double half_angle = 18, full_half_angle = 14.5;
    double above_ground = 400, below_ground = 50;  // metres: the peaks, and a skirt under the horizon
    int texels_wide = 704, texels_high = 352;  // about a texel per pixel of a 1280-wide frame
};

// Width of each picture in metres.
double picture_width(const MountainRing& ring);

// Picture i stands towards (sin a, 0, -cos a) from the centre, a = i * 360 / count degrees:
// picture 0 is straight ahead at the end of the flight, and a grows to the right (+x).
clr::Vec3 picture_direction(const MountainRing& ring, int index);

// The ring's pictures, opaque below the skyline and transparent above it; row
// texels_high * above_ground / (above_ground + below_ground) is the ground line. Lit from
// `towards_sun`, brought low so that ridges and valleys stand out.
std::vector<Canvas> draw_mountain_ring(const MountainRing& ring, std::uint32_t seed, const clr::Vec3& towards_sun);

}  // namespace forest
