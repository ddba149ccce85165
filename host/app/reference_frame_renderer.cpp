#include "app/reference_frame_renderer.h"

#include "core/stopwatch.h"
#include "reference/reference.h"

namespace clr {
namespace {

class ReferenceFrameRenderer : public FrameRenderer {
public:
    ReferenceFrameRenderer(const Scene& scene, std::function<void()> between_rows, std::optional<PixelRect> crop,
                           std::function<void(double)> rows_done, bool linear_frames)
        : scene_(scene), between_rows_(std::move(between_rows)), crop_(crop), rows_done_(std::move(rows_done)),
          linear_frames_(linear_frames) {}

    Image render(const CameraKey& key, int frame, FrameTiming* timing) override {
        const Stopwatch frame_time;
        const int rows = crop_ ? crop_->height() : scene_.height;
        int rows_started = 0;
        // The reference calls this before each row: the call before row r reports r rows done.
        auto before_row = [&] {
            if (rows_started > 0 && rows_done_) rows_done_(static_cast<double>(rows_started) / rows);
            ++rows_started;
            if (between_rows_) between_rows_();
        };
        const reference::CameraFrame camera = reference::camera_of(scene_, key);
        Image image = linear_frames_ ? reference::render_linear(scene_, camera, frame, before_row, crop_)
                                     : reference::render(scene_, camera, frame, before_row, crop_);
        if (rows_done_) rows_done_(1.0);
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
    std::optional<PixelRect> crop_;
    std::function<void(double)> rows_done_;
    bool linear_frames_;
};

}  // namespace

std::unique_ptr<FrameRenderer> make_reference_frame_renderer(const Scene& scene, std::function<void()> between_rows,
                                                             std::optional<PixelRect> crop,
                                                             std::function<void(double)> rows_done,
                                                             bool linear_frames) {
    return std::make_unique<ReferenceFrameRenderer>(scene, std::move(between_rows), crop, std::move(rows_done),
                                                    linear_frames);
}

}  // namespace clr
