// The frame loop's renderer for --reference: the double-precision host reference
// (reference/reference.h), frame by frame like the OpenCL renderer.
#pragma once

#include <functional>
#include <memory>
#include <optional>

#include "app/frame_renderer.h"
#include "core/pixel_rect.h"

namespace clr {

// `between_rows` runs before each row of a frame and throws to abandon it (a stop request);
// `rows_done` gets the fraction (0..1] of the frame's rows rendered, after each row (progress).
// With `crop`, each frame is only those pixels (docs/command-line.md, Crop).
// `linear_frames`: frames also carry their linear colours (Image::linear).
std::unique_ptr<FrameRenderer> make_reference_frame_renderer(const Scene& scene,
                                                             std::function<void()> between_rows = {},
                                                             std::optional<PixelRect> crop = std::nullopt,
                                                             std::function<void(double)> rows_done = {},
                                                             bool linear_frames = false);

}  // namespace clr
