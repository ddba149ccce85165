// What a rendered frame shows, for the text chunks of its PNG (docs/command-line.md, PNG
// metadata): enough to tell which scene, frame and camera an image came from, and to render
// it again.
#pragma once

#include <optional>

#include "app/options.h"
#include "output/image_writer.h"
#include "scene/scene.h"

namespace clr {

// Software, Scene (the file name, without its folder), Scene digest (scene/scene_digest.h),
// Size, Samples per pixel, Seed, Frame, Eye, Lookat, Up, Field of view: frame `frame`'s
// camera. Nothing that changes from run to run (no time, no folder), so that an image's bytes
// stay reproducible. With a crop (options.crop), Crop ("x0,x1,y0,y1") follows Size, which
// stays the whole frame's: the image is that rectangle. Pixels not computed by the default
// float kernels say so after Seed (Precision: double; Renderer: host reference), so that
// --resume, --join and --assemble never take a file of another arithmetic for this run's;
// default images carry neither key.
ImageText describe_frame(const Scene& scene, int frame, const Options& options);

}  // namespace clr
