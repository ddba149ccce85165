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

// `count` rays: half aimed at random points of the scene's objects (so most hit
// something), half in random directions, from origins in and around the scene.
std::vector<reference::Ray> make_random_rays(const Scene& scene, std::uint32_t seed, int count);

// The ray in float, as the kernels take it, and back in double, so that the reference
// traces exactly the ray the kernel traced.
ClrRay to_device_ray(const reference::Ray& ray);
reference::Ray from_device_ray(const ClrRay& ray);

}  // namespace clr::testing
