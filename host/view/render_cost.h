// What one viewer request may cost: its pixels times its samples per pixel. A frame the query
// asks for is rendered in full under the render lock (a client that goes away does not stop it),
// so without a bound one GET (size=8192x8192&spp=4096) would hold the device for hours and
// every other client with it.
#pragma once

#include "scene/scene.h"
#include "view/view_camera.h"
#include "view/view_parameters.h"

namespace clr {

// A 1920x1080 frame at 32 samples per pixel: a few seconds of a desktop CPU on the course's scenes.
constexpr long long kViewerMostSamples = 1920LL * 1080 * 32;

// The most samples a request may render for `scene`: kViewerMostSamples, or the scene's own
// frame at its own samples per pixel (after --size and --spp) where that is more, since the
// page asks for that frame (the still view) and the user chose it.
long long most_view_samples(const Scene& scene);

// Throws ParameterError naming "spp" when the query gave spp=, "size" otherwise, when `view`
// costs more than most_view_samples(scene).
void check_render_cost(const Scene& scene, const ViewCamera& view, const ViewQuery& query);

}  // namespace clr
