// The frame loop's renderer on an OpenCL device (render/renderer.h).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/frame_renderer.h"
#include "device/device_selection.h"
#include "render/renderer.h"

namespace clr {

// Opens the device chosen by `device_selector` among `devices` (see select_device; list_devices()
// runs while the scene loads), builds the scene's program and uploads its buffers, once.
// With `threads` (-t), the device is limited to that many compute units (select_compute_units()).
// Throws DeviceError.
std::unique_ptr<FrameRenderer> make_opencl_frame_renderer(const Scene& scene, const std::vector<DeviceEntry>& devices,
                                                          const std::string& device_selector,
                                                          const RendererOptions& options,
                                                          std::optional<int> threads = std::nullopt);

}  // namespace clr
