#include "render/frame_renderer.h"

#include <chrono>

#include "reference/reference.h"
#include "render/device_camera.h"

namespace clr {
namespace {

class OpenClFrameRenderer : public FrameRenderer {
public:
    OpenClFrameRenderer(const Scene& scene, const DeviceEntry& entry, const RendererOptions& options)
        : scene_(scene), device_(entry), renderer_(device_, scene, options) {}

    Image render(const CameraKey& key, int frame, FrameTiming* timing) override {
        return renderer_.render_view(key, timing, frame);
    }
    std::string device_name() const override { return device_.entry().device_name; }
    double build_ms() const override { return renderer_.build_ms(); }
    int cache_hits() const override { return device_.cache_hits(); }
    void store_built_programs() override { device_.store_built_programs(); }
    void recycle(Image&& image) override { renderer_.recycle(std::move(image)); }

private:
    const Scene& scene_;
    DeviceContext device_;
    Renderer renderer_;
};

class ReferenceFrameRenderer : public FrameRenderer {
public:
    ReferenceFrameRenderer(const Scene& scene, std::function<void()> between_rows)
        : scene_(scene), between_rows_(std::move(between_rows)) {}

    Image render(const CameraKey& key, int frame, FrameTiming* timing) override {
        auto start = std::chrono::steady_clock::now();
        Image image = reference::render(
            scene_, reference::make_camera(key.eye, key.lookat, scene_.up, scene_.fov_degrees, scene_.width, scene_.height),
            frame, between_rows_);
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

std::unique_ptr<FrameRenderer> make_opencl_frame_renderer(const Scene& scene, const std::string& device_selector,
                                                          const RendererOptions& options) {
    return make_opencl_frame_renderer(scene, list_devices(), device_selector, options);
}

std::unique_ptr<FrameRenderer> make_opencl_frame_renderer(const Scene& scene, const std::vector<DeviceEntry>& devices,
                                                          const std::string& device_selector,
                                                          const RendererOptions& options) {
    return std::make_unique<OpenClFrameRenderer>(scene, select_device(devices, device_selector), options);
}

std::unique_ptr<FrameRenderer> make_reference_frame_renderer(const Scene& scene, std::function<void()> between_rows) {
    return std::make_unique<ReferenceFrameRenderer>(scene, std::move(between_rows));
}

}  // namespace clr
