#include "bench/clrender_side.h"

#include "bench/bench_stats.h"
#include "core/stopwatch.h"

namespace clr::bench {

ClrenderSide::ClrenderSide(DeviceContext& device, const Scene& scene, std::optional<bool> per_pixel,
                           std::optional<bool> packets_walk_bvh, const std::string& kernel_dir)
    : key_(scene.camera_path.front()) {
    RendererOptions options;
    options.per_pixel = per_pixel;
    options.packets_walk_bvh = packets_walk_bvh;
    options.kernel_dir = kernel_dir;
    const Stopwatch stopwatch;
    renderer_.emplace(device, scene, options);
    setup_ms_ = stopwatch.elapsed_ms();
    renderer_->warm_up();
}

ClrenderFrame ClrenderSide::render_frame() {
    FrameTiming timing;
    renderer_->recycle(std::move(image_));  // as an interactive viewer reuses its framebuffer
    const Stopwatch stopwatch;
    // Every frame pays what a moving camera's frame pays: moving the geometry to the eye (free
    // when it stays) and, with impostors, placing them and uploading them.
    image_ = renderer_->render(key_, 0, &timing);
    return {timing.kernel_ms, stopwatch.elapsed_ms()};
}

}  // namespace clr::bench
