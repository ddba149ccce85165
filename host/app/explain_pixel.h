// --explain-pixel X,Y: how one pixel is computed, step by step, in the lecture's notation,
// from the double reference's own code path, beside the bytes the OpenCL kernels give it
// (docs/explain-pixel.md).
#pragma once

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

// Writes the explanation of options.explain_pixel to `out`. Throws UsageError for a pixel
// outside the image or --frames naming other than one frame; DeviceError from the kernels.
void explain_pixel(const Options& options, const Scene& scene, const KernelRendererFactory& kernel_renderer,
                   std::ostream& out);

// The same for pixel `pixel` of frame `frame` (which seeds the samples) seen from `key`, with the
// scene's up vector, field of view, size and sampling (`clrender view` explains the camera the
// page shows).
void explain_pixel_of_camera(const Options::PixelPosition& pixel, const Scene& scene, const CameraKey& key, int frame,
                             const KernelRendererFactory& kernel_renderer, std::ostream& out);

}  // namespace clr
