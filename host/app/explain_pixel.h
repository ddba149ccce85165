// --explain-pixel X,Y: how one pixel is computed, step by step, in the lecture's notation,
// from the double reference's own code path, beside the bytes the OpenCL kernels give it
// (docs/explain-pixel.md).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <ostream>

#include "app/frame_renderer.h"
#include "app/options.h"
#include "scene/scene.h"

namespace clr {

// Makes the renderer whose bytes are shown beside the reference's (the OpenCL kernels); null
// when only the reference is wanted (--reference).
using KernelRendererFactory = std::function<std::unique_ptr<FrameRenderer>()>;  // renders the pixel alone (a 1x1 crop)

// The most bytes of steps (samples, rays, tests) an explanation prints; the result follows
// whatever was left out. Many samples with deep mirrors among many objects took hundreds of MB.
constexpr std::uint64_t kExplanationStepsLimit = std::uint64_t(16) << 20;

// Writes the explanation of options.explain_pixel to `out` as it is computed, after the kernels
// have rendered the pixel (a device failure leaves nothing written). Throws UsageError for a
// pixel outside the image or --frames naming other than one frame; DeviceError from the
// kernels; OutputError when `out` does not take every byte.
void explain_pixel(const Options& options, const Scene& scene, const KernelRendererFactory& kernel_renderer,
                   std::ostream& out);

// Called before each of the reference's samples; it may throw to stop the explanation (the
// viewer stops one at a signal, or when its client has gone: many samples take minutes).
using BeforeEachSample = std::function<void()>;

// The same for pixel `pixel` of frame `frame` (which seeds the samples) seen from `key`, with the
// scene's up vector, field of view, size and sampling (`clrender view` explains the camera the
// page shows).
void explain_pixel_of_camera(const Options::PixelPosition& pixel, const Scene& scene, const CameraKey& key, int frame,
                             const KernelRendererFactory& kernel_renderer, std::ostream& out,
                             const BeforeEachSample& before_each_sample = {});

}  // namespace clr
