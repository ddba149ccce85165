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

}  // namespace clr::testing
