#include "app/reference_frame_renderer.h"

#include "core/stopwatch.h"
#include "reference/reference.h"

namespace clr {
namespace {

class ReferenceFrameRenderer : public FrameRenderer {
public:
    ReferenceFrameRenderer(const Scene& scene, std::function<void()> between_rows, bool linear_frames)
        : scene_(scene), between_rows_(std::move(between_rows)), linear_frames_(linear_frames) {}

    Image render(const CameraKey& key, int frame, FrameTiming* timing) override {
        const Stopwatch frame_time;
        const reference::CameraFrame camera = reference::camera_of(scene_, key);
        Image image = linear_frames_ ? reference::render_linear(scene_, camera, frame, between_rows_)
                                     : reference::render(scene_, camera, frame, between_rows_);
        if (timing) {
            timing->total_ms = frame_time.elapsed_ms();
            timing->kernel_ms = timing->total_ms;  // all of it is "kernel" work, on the host
        }
        return image;
    }
    std::string device_name() const override { return "host reference (double precision)"; }
    double build_ms() const override { return 0; }

private:
    const Scene& scene_;
    std::function<void()> between_rows_;
    bool linear_frames_;
};

}  // namespace

std::unique_ptr<FrameRenderer> make_reference_frame_renderer(const Scene& scene, std::function<void()> between_rows,
                                                             bool linear_frames) {
    return std::make_unique<ReferenceFrameRenderer>(scene, std::move(between_rows), linear_frames);
}

}  // namespace clr
