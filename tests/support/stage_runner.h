// Runs one kernel stage alone on the test device, for a scene, so each stage can be compared
// with the host reference by itself.
#pragma once

#include <vector>

#include "render/renderer.h"
#include "shared/clr_types.h"

namespace clr::testing {

struct ShadeOutput {
    std::vector<cl_float4> colors;  // (rgb, 1) when the path ends, (0,0,0,0) when it bounces
    std::vector<ClrRay> next_rays;  // the reflected ray when it bounces
};

class StageRunner {
public:
    explicit StageRunner(const Scene& scene, const RendererOptions& options = {});

    std::vector<ClrRay> raygen(const ClrCamera& camera);
    std::vector<ClrHit> intersect(const std::vector<ClrRay>& rays);
    ShadeOutput shade(const std::vector<ClrRay>& rays, const std::vector<ClrHit>& hits, int reflections);

    Renderer& renderer() { return renderer_; }

private:
    Renderer renderer_;      // the scene's buffers and features
    cl::Program program_;    // the stage kernels (kernels/programs/test_stages.cl)
};

}  // namespace clr::testing
