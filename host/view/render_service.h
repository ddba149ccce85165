// The viewer's renderer: one OpenCL device context and one Renderer for the whole session,
// built before the server listens, so that the first frame does not wait for the program. Every
// view (camera, size, samples) renders with the same program and scene buffers
// (Renderer::change_view); frames are rendered one at a time, as the device renders them
// fastest, and each request waits its turn.
#pragma once

#include <chrono>
#include <functional>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>

#include "app/options.h"
#include "core/image.h"
#include "device/device_context.h"
#include "render/renderer.h"
#include "scene/scene.h"
#include "view/view_camera.h"

namespace clr {

class RenderService {
public:
    // Opens the device `options` select (-d, -t), builds the scene's program (--precision,
    // --kernel-dir) and renders a first small frame. Throws DeviceError.
    RenderService(const Scene& scene, const Options& options);

    // The frame `view` sees: byte for byte what a render of the scene with that camera,
    // size and samples gives for that frame. Throws DeviceError, Interrupted after a signal,
    // or FrameAbandoned when `abandoned` (asked before every band of rows, several times a
    // second) says that nobody waits for the frame any more.
    Image render(const ViewCamera& view, std::function<bool()> abandoned = {});
    // Hands back a frame sent to a client: the next frame renders into its storage.
    void recycle(Image&& image);

    // The --explain-pixel text for `pixel` of the frame `view` sees, at most
    // kMostExplanationBytes long. Throws UsageError for a pixel outside the frame,
    // DeviceError from the kernels, and, as render() does, Interrupted after a signal or
    // FrameAbandoned once `abandoned` says that nobody waits for it (asked between the
    // kernels' bands and between the reference's samples, there first after
    // kAbandonmentLookInterval and then at most every interval). Explanations run one at a time.
    std::string explain(const ViewCamera& view, int x, int y, std::function<bool()> abandoned = {});

    const std::string& device_name() const { return device_name_; }
    // Programs taken from the program cache and from the program store (the rest compiled).
    int cache_hits() const { return device_->cache_hits(); }
    int store_hits() const { return device_->store_hits(); }

private:
    Image render_locked(const ViewCamera& view);
    void between_bands() const;

    const Scene& scene_;
    std::mutex mutex_;  // one frame at a time on the device
    std::function<bool()> abandoned_;  // the frame in progress's, under mutex_
    // One explanation at a time: each holds copies of the scene (seen by its camera, relative
    // to the eye, impostors placed) for as long as it runs, outside mutex_.
    std::mutex explain_mutex_;
    std::unique_ptr<DeviceContext> device_;
    std::unique_ptr<Renderer> renderer_;
    std::string device_name_;
};

// A frame stopped between two bands because its client went away.
class FrameAbandoned : public std::runtime_error {
public:
    FrameAbandoned() : std::runtime_error("the client went away before the frame was finished") {}
};

// How often an explanation's reference asks whether its client is still there: a sample
// takes microseconds, the question a system call.
constexpr std::chrono::milliseconds kAbandonmentLookInterval{50};

// An explanation longer than this (many samples, deep mirrors) is cut, with a note.
constexpr std::size_t kMostExplanationBytes = 256 * 1024;

}  // namespace clr
