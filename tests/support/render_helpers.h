// Renders a scene's first camera key with the kernels or with the reference.
#pragma once

#include "render/renderer.h"
#include "scene/scene.h"

namespace clr::testing {

Image render_with_kernels(const Scene& scene, const RendererOptions& options = {});
Image render_with_reference(const Scene& scene);

}  // namespace clr::testing
