// What a rendered frame shows, for the text chunks of its PNG (docs/command-line.md, PNG
// metadata): enough to tell which scene, frame and camera an image came from, and to render
// it again.
#pragma once

#include <optional>

#include "core/pixel_rect.h"
#include "output/image_writer.h"
#include "scene/scene.h"

namespace clr {

// Software, Scene (the file name, without its folder), Size, Samples per pixel, Seed, Frame,
// Eye, Lookat, Up, Field of view: frame `frame`'s camera. Nothing that changes from run to
// run (no time, no folder), so that an image's bytes stay reproducible. With a crop, Crop
// ("x0,x1,y0,y1") follows Size, which stays the whole frame's: the image is that rectangle.
ImageText describe_frame(const Scene& scene, int frame, const std::optional<PixelRect>& crop = std::nullopt);

}  // namespace clr
