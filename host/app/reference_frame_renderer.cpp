#include "app/reference_frame_renderer.h"

#include <chrono>

#include "reference/reference.h"

namespace clr {
namespace {

class ReferenceFrameRenderer : public FrameRenderer {
public:
    ReferenceFrameRenderer(const Scene& scene, std::function<void()> between_rows)
        : scene_(scene), between_rows_(std::move(between_rows)) {}

    Image render(const CameraKey& key, int frame, FrameTiming* timing) override {
        auto start = std::chrono::steady_clock::now();
        Image image = reference::render(scene_, reference::camera_of(scene_, key), frame, between_rows_);
        if (timing) {
            timing->total_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
            timing->kernel_ms = timing->total_ms;  // all of it is "kernel" work, on the host
        }
        return image;
    }
    std::string device_name() const override { return "host reference (double precision)"; }
    double build_ms() const override { return 0; }

private:
    const Scene& scene_;
    std::function<void()> between_rows_;
};

}  // namespace

std::unique_ptr<FrameRenderer> make_reference_frame_renderer(const Scene& scene, std::function<void()> between_rows) {
    return std::make_unique<ReferenceFrameRenderer>(scene, std::move(between_rows));
}

}  // namespace clr
