#include "bench/clrender_side.h"


#include "bench/bench_stats.h"
#include "core/stopwatch.h"
#include "render/device_camera.h"

namespace clr::bench {
namespace {

// The same view at 64x36: the same kernel and work-group size at almost no cost.
ClrCamera thumbnail_of(const Scene& scene) {
    const CameraKey& key = scene.camera_path.front();
    return make_device_camera(key.eye, key.lookat, scene.up, scene.fov_degrees, 64, 36);
}

}  // namespace

ClrenderSide::ClrenderSide(DeviceContext& device, const Scene& scene, const ClrCamera& camera)
    : camera_(camera), key_(scene.camera_path.front()), faces_camera_(!scene.impostors.empty()) {
    const Stopwatch stopwatch;
    renderer_.emplace(device, scene);
    setup_ms_ = stopwatch.elapsed_ms();
    renderer_->render_frame(thumbnail_of(scene));
}

ClrenderFrame ClrenderSide::render_frame() {
    FrameTiming timing;
    renderer_->recycle(std::move(image_));  // as an interactive viewer reuses its framebuffer
    const Stopwatch stopwatch;
    // With impostors the frame's time includes placing them for the eye (and uploading them),
    // which every frame of a moving camera pays; the scene's size is the benchmark's.
    image_ = faces_camera_ ? renderer_->render_view(key_, &timing) : renderer_->render_frame(camera_, &timing);
    return {timing.kernel_ms, stopwatch.elapsed_ms()};
}

}  // namespace clr::bench
