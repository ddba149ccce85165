#include "bench/clrender_side.h"

#include <chrono>

#include "bench/bench_stats.h"

namespace clr::bench {

ClrenderSide::ClrenderSide(DeviceContext& device, const Scene& scene) : key_(scene.camera_path.front()) {
    auto start = std::chrono::steady_clock::now();
    renderer_.emplace(device, scene);
    setup_ms_ = ms_since(start);
    renderer_->warm_up();
}

ClrenderFrame ClrenderSide::render_frame() {
    FrameTiming timing;
    renderer_->recycle(std::move(image_));  // as an interactive viewer reuses its framebuffer
    auto start = std::chrono::steady_clock::now();
    // Every frame pays what a moving camera's frame pays: moving the geometry to the eye (free
    // when it stays) and, with impostors, placing them and uploading them.
    image_ = renderer_->render(key_, 0, &timing);
    return {timing.kernel_ms, ms_since(start)};
}

}  // namespace clr::bench
