#include "view/render_service.h"

#include <sstream>

#include "app/explain_pixel.h"
#include "core/interruption.h"
#include "device/device_selection.h"
#include "device/program_store.h"

namespace clr {
namespace {

// The kernels' bytes for the explained pixel, from the viewer's own renderer: the whole frame
// is rendered and the pixel cut out of it, which gives the bytes a 1x1 crop would (crops are
// byte for byte the full frame's, docs/command-line.md, Crop).
class PixelOfFrame : public FrameRenderer {
public:
    PixelOfFrame(std::function<Image()> render_frame, std::string device, int x, int y)
        : render_frame_(std::move(render_frame)), device_(std::move(device)), x_(x), y_(y) {}
    Image render(const CameraKey&, int, FrameTiming*) override {
        const Image frame = render_frame_();
        Image pixel;
        pixel.width = pixel.height = 1;
        for (int channel = 0; channel < 4; ++channel) pixel.rgba.push_back(frame.at(x_, y_, channel));
        return pixel;
    }
    std::string device_name() const override { return device_; }
    double build_ms() const override { return 0; }

private:
    std::function<Image()> render_frame_;
    std::string device_;
    int x_, y_;
};

}  // namespace

RenderService::RenderService(const Scene& scene, const Options& options) : scene_(scene) {
    DeviceEntry entry = select_device(list_devices(), options.device);
    if (options.threads) entry = select_compute_units(entry, *options.threads);
    // The program store, as a render's: a fresh install's first view compiles nothing.
    device_ = std::make_unique<DeviceContext>(entry, ProgramStore::from_environment());
    device_name_ = entry.device_name;
    RendererOptions renderer_options;
    renderer_options.kernel_dir = options.kernel_dir;
    renderer_options.double_precision = options.double_precision;
    // A scene whose own program is not prebuilt (meshes, planes, lights, clipping) is served by
    // the store's general program at once rather than after a compile of seconds: the same
    // pixels, a little slower per frame (docs/architecture.md, Program store).
    renderer_options.general_stand_in = true;
    // A signal stops a long frame within a band, so the server stops promptly; a client that
    // goes away stops its frame too, so that the next client's frame is not kept waiting.
    renderer_options.between_bands = [this] { between_bands(); };
    renderer_ = std::make_unique<Renderer>(*device_, scene_, renderer_options);
    renderer_->warm_up();
    // The next start builds from the program cache (asking the driver for the binary takes
    // longer than a frame: done here, before the server listens, not while it serves).
    device_->store_built_programs();
}

Image RenderService::render_locked(const ViewCamera& view) {
    renderer_->change_view(view.up, view.fov_degrees, view.width, view.height, view.sampling);
    return renderer_->render(view.key, view.frame);
}

void RenderService::between_bands() const {
    throw_if_interrupted();
    if (abandoned_ && abandoned_()) throw FrameAbandoned();
}

Image RenderService::render(const ViewCamera& view, std::function<bool()> abandoned) {
    std::lock_guard<std::mutex> lock(mutex_);
    abandoned_ = std::move(abandoned);
    struct Forget {
        std::function<bool()>& abandoned;
        ~Forget() { abandoned = nullptr; }
    } forget{abandoned_};
    return render_locked(view);
}

void RenderService::recycle(Image&& image) {
    std::lock_guard<std::mutex> lock(mutex_);
    renderer_->recycle(std::move(image));
}

std::string RenderService::explain(const ViewCamera& view, int x, int y, std::function<bool()> abandoned) {
    // Taken before the copies: explanations asked at once would each hold theirs.
    std::lock_guard<std::mutex> one_at_a_time(explain_mutex_);
    const Scene seen = scene_seen_by(scene_, view);
    KernelRendererFactory kernels = [this, &view, &abandoned, x, y] {
        return std::make_unique<PixelOfFrame>([this, &view, &abandoned] { return render(view, abandoned); }, device_name_,
                                              x, y);
    };
    // The reference's samples stop as a frame's bands do: many samples among deep mirrors take
    // minutes, which neither a signal nor a client that left should wait for. The first look
    // comes after a first stretch of work, as a frame's comes after its first band: a client
    // that half-closed (nc -N) looks gone, and a small explanation is answered to it as a small
    // frame is, where it got 503 before.
    auto next_look = std::chrono::steady_clock::now() + kAbandonmentLookInterval;
    const BeforeEachSample between_samples = [&abandoned, &next_look] {
        throw_if_interrupted();
        if (!abandoned || std::chrono::steady_clock::now() < next_look) return;
        next_look = std::chrono::steady_clock::now() + kAbandonmentLookInterval;
        if (abandoned()) throw FrameAbandoned();
    };
    std::ostringstream text;
    explain_pixel_of_camera(Options::PixelPosition{x, y}, seen, view.key, view.frame, kernels, text, between_samples);
    std::string explanation = text.str();
    if (explanation.size() > kMostExplanationBytes) {
        explanation.resize(kMostExplanationBytes);
        explanation += "\n[... cut at " + std::to_string(kMostExplanationBytes / 1024) +
                       " KiB; clrender --explain-pixel prints it all]\n";
    }
    return explanation;
}

}  // namespace clr
