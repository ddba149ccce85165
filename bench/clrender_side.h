// The clrender side of the benchmark: the scene rendered by clr::Renderer, exactly as the
// clrender command renders a still, one timed frame at a time.
#pragma once

#include <optional>

#include "device/device_context.h"
#include "render/renderer.h"
#include "scene/scene.h"
#include "shared/clr_types.h"

namespace clr::bench {

struct ClrenderFrame {
    double kernel_ms = 0;  // device time of the frame's kernels (OpenCL profiling)
    double wall_ms = 0;    // wall time of render_frame(): enqueue to image in host memory
};

class ClrenderSide {
public:
    // Builds the program, uploads the scene (both timed as setup) and renders a thumbnail of
    // the view, so that PoCL's compile for the work-group size on first use is out of the way.
    ClrenderSide(DeviceContext& device, const Scene& scene, const ClrCamera& camera);

    double setup_ms() const { return setup_ms_; }
    ClrenderFrame render_frame();
    const Image& image() const { return image_; }  // the last frame

private:
    ClrCamera camera_;
    CameraKey key_;
    bool faces_camera_ = false;  // has impostors: each frame places them, as an animation must
    double setup_ms_ = 0;
    std::optional<Renderer> renderer_;  // constructed in the constructor's body, to time it
    Image image_;
};

}  // namespace clr::bench
