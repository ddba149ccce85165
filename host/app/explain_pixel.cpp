#include "app/explain_pixel.h"

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/bounded_text.h"
#include "app/frame_selection.h"
#include "app/pixel_narrator.h"
#include "core/errors.h"
#include "core/interruption.h"
#include "core/printable_text.h"
#include "reference/eye_relative.h"
#include "reference/impostors.h"
#include "reference/reference.h"
#include "scene/camera_path.h"

namespace clr {
namespace {

// The frame --frames names, 0 when it is left out: an explanation is of one frame.
int explained_frame(const Options& options, const Scene& scene) {
    if (options.frames.empty()) return 0;
    const std::vector<int> frames = parse_frame_list(options.frames, animation_frame_count(scene));
    if (frames.size() != 1)
        throw UsageError("--explain-pixel explains one frame; --frames '" + options.frames + "' names " +
                         std::to_string(frames.size()));
    return frames.front();
}

void check_inside(const Options::PixelPosition& pixel, const Scene& scene) {
    if (pixel.x < scene.width && pixel.y < scene.height) return;
    throw UsageError("--explain-pixel " + std::to_string(pixel.x) + "," + std::to_string(pixel.y) +
                     " is outside the " + std::to_string(scene.width) + "x" + std::to_string(scene.height) +
                     " image (X from 0 to " + std::to_string(scene.width - 1) + ", Y from 0 to " +
                     std::to_string(scene.height - 1) + ")");
}

void describe_camera(const Scene& scene, const CameraKey& key, const reference::CameraFrame& camera, std::ostream& out) {
    out << "\n== Camera (docs/scene-format.md, Conventions: Camera) ==\n";
    out << "Eye = " << explain_vector(key.eye) << ", LookAt = " << explain_vector(key.lookat)
        << ", Up = " << explain_vector(scene.up) << ", field of view " << explain_number(scene.fov_degrees)
        << " degrees\n";
    out << "w = unit(Eye - LookAt) = " << explain_vector(camera.w) << "\n";
    out << "u = unit(Up x w) = " << explain_vector(camera.u) << "\n";
    out << "v = w x u = " << explain_vector(camera.v) << "\n";
    out << "image plane at distance D = 1: half width hw = " << explain_number(camera.half_width)
        << ", half height hh = " << explain_number(camera.half_height) << " (tan(fov/2) across the larger side)\n";
}

std::string bytes_text(const std::uint8_t bytes[3]) {
    return std::to_string(bytes[0]) + " " + std::to_string(bytes[1]) + " " + std::to_string(bytes[2]);
}

// The kernels' bytes for the pixel and the device that gave them.
struct KernelPixel {
    std::uint8_t bytes[3] = {0, 0, 0};
    std::string device;
};

// From a renderer that renders just that pixel (a 1x1 crop of the frame) as a plain run renders
// it; nothing with --reference.
std::optional<KernelPixel> render_kernel_pixel(const KernelRendererFactory& kernel_renderer, const CameraKey& key,
                                               int frame) {
    if (!kernel_renderer) return std::nullopt;
    std::unique_ptr<FrameRenderer> renderer = kernel_renderer();
    const Image image = renderer->render(key, frame, nullptr);
    if (image.width != 1 || image.height != 1)
        throw std::logic_error("the kernels' image of one pixel is " + std::to_string(image.width) + "x" +
                               std::to_string(image.height));  // a bug: exit 5
    KernelPixel pixel;
    for (int channel = 0; channel < 3; ++channel) pixel.bytes[channel] = image.at(0, 0, channel);
    pixel.device = renderer->device_name();
    return pixel;
}

void describe_kernel_bytes(const std::optional<KernelPixel>& kernel, const std::uint8_t reference_bytes[3],
                           std::ostream& out) {
    if (!kernel) {
        out << "OpenCL kernels: not run (--reference)\n";
        return;
    }
    const bool same = kernel->bytes[0] == reference_bytes[0] && kernel->bytes[1] == reference_bytes[1] &&
                      kernel->bytes[2] == reference_bytes[2];
    out << "bytes the OpenCL kernels write (" << printable(kernel->device) << "): " << bytes_text(kernel->bytes)
        << (same ? " (the same)" : " (they differ: float rounding near an edge, see docs/explain-pixel.md)") << "\n";
}

std::string mebibytes(std::uint64_t bytes) { return std::to_string(bytes >> 20) + " MiB"; }

// The narrator, which gives its caller a word before each sample: the one step of the
// reference that an explanation repeats without bound.
class NarratorAskingBeforeSamples : public PixelNarrator {
public:
    NarratorAskingBeforeSamples(const BeforeEachSample& before_each_sample, const Scene& placed, int own_billboards,
                                const reference::CameraFrame& camera, const Vec3& eye, int col, int row,
                                std::ostream& out)
        : PixelNarrator(placed, own_billboards, camera, eye, col, row, out), before_each_sample_(before_each_sample) {}

    void sample_started(int sample, int samples, double ox, double oy, const Vec3& witness_direction,
                        const reference::Ray& ray) override {
        if (before_each_sample_) before_each_sample_();
        PixelNarrator::sample_started(sample, samples, ox, oy, witness_direction, ray);
    }

private:
    const BeforeEachSample& before_each_sample_;
};

}  // namespace

void explain_pixel(const Options& options, const Scene& scene, const KernelRendererFactory& kernel_renderer,
                   std::ostream& out) {
    check_inside(*options.explain_pixel, scene);
    const int frame = explained_frame(options, scene);
    // Ctrl-C ends a long explanation (many samples) between two samples, as a render between bands.
    explain_pixel_of_camera(*options.explain_pixel, scene, camera_at_frame(scene, frame), frame, kernel_renderer, out,
                            throw_if_interrupted);
}

void explain_pixel_of_camera(const Options::PixelPosition& pixel, const Scene& scene, const CameraKey& key, int frame,
                             const KernelRendererFactory& kernel_renderer, std::ostream& out,
                             const BeforeEachSample& before_each_sample) {
    check_inside(pixel, scene);
    const reference::CameraFrame camera = reference::camera_of(scene, key);
    // The reference traces relative to the eye, with impostors placed as billboards for this
    // camera, as render() does.
    const reference::EyeRelative relative = reference::relative_to_eye(scene, camera);
    const Scene placed = reference::with_impostors_placed(relative.scene, relative.camera);

    // The kernels first: a device failure then leaves no half explanation, although the steps
    // go out as the reference computes them.
    const std::optional<KernelPixel> kernel = render_kernel_pixel(kernel_renderer, key, frame);
    BoundedTextBuffer steps_buffer(out, kExplanationStepsLimit);
    std::ostream steps(&steps_buffer);

    steps << "Pixel X,Y = " << pixel.x << "," << pixel.y << " (column j = " << pixel.x << ", row i = " << pixel.y
          << " from the top) of frame " << frame << " of " << scene.path << ": " << scene.width << "x" << scene.height
          << ", " << scene.sampling.samples_per_pixel << " sample(s) per pixel, "
          << (scene.lit() ? "lit by the sun" : "unlit (ambient colours)") << ", MaxDepth " << scene.max_depth << "\n";
    steps << "Numbers from the double-precision reference (%.9g). It computes positions relative to the eye,\n"
             "as the kernels do; they are shown in scene coordinates (Eye + the relative position).\n";
    describe_camera(scene, key, camera, steps);

    NarratorAskingBeforeSamples narrator(before_each_sample, placed, static_cast<int>(scene.billboards.size()),
                                         relative.camera, relative.eye, pixel.x, pixel.y, steps);
    const Color colour = reference::pixel_colour(placed, relative.camera, frame, pixel.x, pixel.y, &narrator);
    const std::uint8_t bytes[3] = {reference::to_byte(colour.x), reference::to_byte(colour.y),
                                   reference::to_byte(colour.z)};

    if (steps_buffer.cut())
        out << "\n... " << steps_buffer.omitted() << " more bytes of steps left out: an explanation prints at most "
            << mebibytes(kExplanationStepsLimit) << " of them (docs/explain-pixel.md); the result counts every sample\n";
    out << "\n== Result ==\n";
    out << "pixel colour = mean of " << scene.sampling.samples_per_pixel
        << " sample(s) = " << explain_vector(colour) << "\n";
    out << "bytes the reference writes, round(clamp(c, 0, 1) * 255): " << bytes_text(bytes) << "\n";
    describe_kernel_bytes(kernel, bytes, out);
    out.flush();
    if (steps_buffer.target_failed() || !out)
        throw OutputError("standard output: cannot write the explanation (disk full or pipe closed?)");
}

}  // namespace clr
