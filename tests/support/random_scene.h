// Seeded random scenes and rays for property tests. Every test that uses them prints its
// seed on failure, so a failure can be replayed.
#pragma once

#include <cstdint>
#include <random>
#include <vector>

#include "reference/reference.h"
#include "scene/scene.h"
#include "shared/clr_types.h"

namespace clr::testing {

// A scene of `spheres` spheres and `billboards` billboards inside a box of half-size 10:
// random radii, parallelograms of every shape, half of the billboards textured with an
// image that has transparent texels.
Scene make_random_scene(std::uint32_t seed, int spheres, int billboards);

// make_random_scene(77, 8, 8) seen from (3, 5, 30) at 90x61 (a multiple neither of the 16-pixel
// screen tiles nor of small band heights), spp 4, lit by a sun, two spheres and a billboard
// mirrors: every code path a band or a crop could change the result of.
Scene make_sunlit_mirror_scene();

// `count` rays: half aimed at random points of the scene's objects (so most hit
// something), half in random directions, from origins in and around the scene.
std::vector<reference::Ray> make_random_rays(const Scene& scene, std::uint32_t seed, int count);

// The ray in float, as the kernels take it, and back in double, so that the reference
// traces exactly the ray the kernel traced.
ClrRay to_device_ray(const reference::Ray& ray);
reference::Ray from_device_ray(const ClrRay& ray);

}  // namespace clr::testing
