// The clrender side of the benchmark: the scene rendered by clr::Renderer, exactly as the
// clrender command renders a still, one timed frame at a time.
#pragma once

#include <optional>

#include "device/device_context.h"
#include "render/renderer.h"
#include "scene/scene.h"

namespace clr::bench {

struct ClrenderFrame {
    double kernel_ms = 0;  // device time of the frame's kernels (OpenCL profiling)
    double wall_ms = 0;    // wall time of Renderer::render(): the frame's host work, enqueue to image in host memory
};

class ClrenderSide {
public:
    // Builds the program, uploads the scene (both timed as setup) and renders a thumbnail of
    // the view (Renderer::warm_up), so that PoCL's compile for the work-group size on first use
    // is out of the way.
    // `per_pixel`: primary rays one work-item a pixel through the BVH, or in screen tiles of
    // 16-ray packets; unset, as the device prefers (RendererOptions::per_pixel).
    // `packets_walk_bvh`: packets through the BVH, or through screen-tile lists; unset, as
    // the scene prefers (RendererOptions::packets_walk_bvh).
    // `kernel_dir`: read the kernels from this folder instead of the embedded copies (empty:
    // embedded), so that two versions of a kernel can be timed by one binary.
    ClrenderSide(DeviceContext& device, const Scene& scene, std::optional<bool> per_pixel = std::nullopt,
                 std::optional<bool> packets_walk_bvh = std::nullopt, const std::string& kernel_dir = "");

    double setup_ms() const { return setup_ms_; }
    ClrenderFrame render_frame();
    const Image& image() const { return image_; }  // the last frame

private:
    CameraKey key_;
    double setup_ms_ = 0;
    std::optional<Renderer> renderer_;  // constructed in the constructor's body, to time it
    Image image_;
};

}  // namespace clr::bench
