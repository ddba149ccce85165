// One frame of a clrender scene written in POV-Ray 3.7's scene description language, so that
// POV-Ray renders the same picture with the same work (docs/benchmarks.md, Against POV-Ray):
// the frame's camera rays exactly, the spheres, the billboards as textured parallelograms with
// their image files, the meshes as mesh2, the background, the sun and the mirrors, each shaded as clrender shades
// it as far as POV-Ray's own model allows.
#pragma once

#include <string>

#include "scene/scene.h"

namespace clr::bench {

// The scene text of frame `frame` (0 for a still) of `scene`, a scene loaded with its images
// decoded (each billboard's image names the file it came from). Throws UsageError for a frame
// outside the animation and SceneError for an image that POV-Ray cannot be pointed at (a
// placeholder, a path with characters a POV-Ray string cannot hold).
std::string povray_scene_text(const Scene& scene, int frame);

// POV-Ray's max_trace_level for `scene`: the mirror depth plus one level for each billboard
// that may pass a ray through a transparent texel (POV-Ray counts those as traces, clrender
// does not), within POV-Ray's limit of 256.
int povray_trace_levels(const Scene& scene);

}  // namespace clr::bench
