// What the frame loop (run.cpp) needs of a renderer: a frame for a camera key, and a few facts
// for the report. Two adapters implement it, each in its own file here in app/: the OpenCL
// renderer (opencl_frame_renderer.h) and the double-precision host reference
// (reference_frame_renderer.h, --reference). The interface and its adapters live in app/
// because only the frame loop needs them: render/ and reference/ stay independent of each
// other and of the command line's choice between them.
#pragma once

#include <string>

#include "core/image.h"
#include "render/frame_timing.h"
#include "scene/scene.h"

namespace clr {

class FrameRenderer {
public:
    virtual ~FrameRenderer() = default;
    // `frame` is the animation frame index, which seeds the sample pattern.
    virtual Image render(const CameraKey& key, int frame, FrameTiming* timing) = 0;
    virtual std::string device_name() const = 0;
    virtual double build_ms() const = 0;  // program build time, 0 for the reference
    // The OpenCL device's compute units in use (-t); 0 for the reference, which has none.
    virtual int compute_units() const { return 0; }
    virtual int cache_hits() const { return 0; }  // programs built from the program cache
    virtual int store_hits() const { return 0; }  // programs built from the program store
    // How primary rays are traced (render/primary_ray_path.h: "screen tiles", "BVH packets",
    // "per pixel"); empty for the reference, which traces each pixel's rays through every object.
    virtual std::string primary_rays() const { return {}; }
    // Keeps the programs built for this run in the program cache for the next (slow the first
    // time: call once the outputs are written).
    virtual void store_built_programs() {}
    // Hands back a finished frame whose storage a later frame may reuse.
    virtual void recycle(Image&& /*image*/) {}
};

}  // namespace clr
