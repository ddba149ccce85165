// Renders a scene's first camera key with the kernels or with the reference, and compares the two.
#pragma once

#include <string>

#include "render/renderer.h"
#include "scene/scene.h"

namespace clr::testing {

Image render_with_kernels(const Scene& scene, const RendererOptions& options = {});
Image render_with_reference(const Scene& scene);

// Expects the kernels' image of `scene` (with `options`) to match the reference's: at most
// `differing_fraction` of the pixels off by more than the tolerance, and each of those on an
// edge (support/image_compare.h). `what` names the case in a failure.
void expect_kernels_match_reference(const Scene& scene, const std::string& what, const RendererOptions& options = {},
                                    double differing_fraction = 0.002);

// Expects every way the kernels trace primary rays (screen tiles, 16-ray packets through the
// BVH, one ray a work-item, and in double) to give the reference's image of `scene` to the
// pixel: for scenes whose pixel centres lie on edges, where only a shared rule makes them agree.
void expect_every_kernel_path_matches_reference(const Scene& scene, const std::string& what);

// Expects the general program that stands in for the scene's own in a still
// (FeatureSet::general, RendererOptions::general_stand_in) to render the scene's image byte for
// byte, in float and in double precision, with screen tiles.
void expect_general_program_renders_the_same(const Scene& scene);

}  // namespace clr::testing
