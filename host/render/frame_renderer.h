// Something that renders a frame for a camera key: the OpenCL renderer, or the
// double-precision host reference (--reference). The frame loop does not care which.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "device/device_selection.h"
#include "render/renderer.h"
#include "scene/scene.h"

namespace clr {

class FrameRenderer {
public:
    virtual ~FrameRenderer() = default;
    // `frame` is the animation frame index, which seeds the sample pattern.
    virtual Image render(const CameraKey& key, int frame, FrameTiming* timing) = 0;
    virtual std::string device_name() const = 0;
    virtual double build_ms() const = 0;  // program build time, 0 for the reference
    virtual int cache_hits() const { return 0; }  // programs built from the program cache
    // Keeps the programs built for this run in the program cache for the next (slow the first
    // time: call once the outputs are written).
    virtual void store_built_programs() {}
    // Hands back a finished frame whose storage a later frame may reuse.
    virtual void recycle(Image&& /*image*/) {}
};

// Opens the device chosen by `device_selector` (see select_device), builds the scene's
// program and uploads its buffers, once. Throws DeviceError.
std::unique_ptr<FrameRenderer> make_opencl_frame_renderer(const Scene& scene, const std::string& device_selector,
                                                          const RendererOptions& options = {});
// The same, choosing among `devices` (list_devices(), e.g. listed while the scene loaded).
std::unique_ptr<FrameRenderer> make_opencl_frame_renderer(const Scene& scene, const std::vector<DeviceEntry>& devices,
                                                          const std::string& device_selector,
                                                          const RendererOptions& options);

// `between_rows` runs before each row of a frame and throws to abandon it (a stop request).
std::unique_ptr<FrameRenderer> make_reference_frame_renderer(const Scene& scene,
                                                             std::function<void()> between_rows = {});

}  // namespace clr
