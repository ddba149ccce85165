// The frame loop's renderer for --reference: the double-precision host reference
// (reference/reference.h), frame by frame like the OpenCL renderer.
#pragma once

#include <functional>
#include <memory>

#include "app/frame_renderer.h"

namespace clr {

// `between_rows` runs before each row of a frame and throws to abandon it (a stop request).
// `linear_frames`: frames also carry their linear colours (Image::linear).
std::unique_ptr<FrameRenderer> make_reference_frame_renderer(const Scene& scene,
                                                             std::function<void()> between_rows = {},
                                                             bool linear_frames = false);

}  // namespace clr
