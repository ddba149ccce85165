#include "app/opencl_frame_renderer.h"

#include "device/device_context.h"
#include "device/program_store.h"

namespace clr {
namespace {

class OpenClFrameRenderer : public FrameRenderer {
public:
    OpenClFrameRenderer(const Scene& scene, const DeviceEntry& entry, const RendererOptions& options)
        : device_(entry, ProgramStore::from_environment()), renderer_(device_, scene, options) {}

    Image render(const CameraKey& key, int frame, FrameTiming* timing) override {
        return renderer_.render(key, frame, timing);
    }
    std::string device_name() const override { return device_.entry().device_name; }
    double build_ms() const override { return renderer_.build_ms(); }
    int compute_units() const override { return clr::compute_units(device_.entry()); }
    int cache_hits() const override { return device_.cache_hits(); }
    int store_hits() const override { return device_.store_hits(); }
    std::string primary_rays() const override { return primary_rays_name(renderer_.primary_rays()); }
    void store_built_programs() override { device_.store_built_programs(); }
    void recycle(Image&& image) override { renderer_.recycle(std::move(image)); }

private:
    DeviceContext device_;
    Renderer renderer_;
};

}  // namespace

std::unique_ptr<FrameRenderer> make_opencl_frame_renderer(const Scene& scene, const std::vector<DeviceEntry>& devices,
                                                          const std::string& device_selector,
                                                          const RendererOptions& options,
                                                          std::optional<int> threads) {
    DeviceEntry device = select_device(devices, device_selector);
    if (threads) device = select_compute_units(device, *threads);
    return std::make_unique<OpenClFrameRenderer>(scene, device, options);
}

}  // namespace clr
