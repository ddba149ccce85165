// --join: the final image of a still (or of one frame) from tiles that separate processes
// rendered with --crop, byte for byte what one process renders (docs/command-line.md, Joining
// tiles). Nothing renders and no OpenCL device is needed. Each tile must be a PNG that clrender
// wrote for exactly this render (its description, Crop aside, equal to the one this run
// writes), of its Crop's size, inside the frame; together the tiles cover every pixel once.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "app/options.h"
#include "app/output_plan.h"
#include "core/image.h"
#include "output/atomic_file.h"
#include "scene/scene.h"

namespace clr {

// Throws UsageError when the run would not write one image that tiles can make: several
// frames (plan.frames is chosen; nothing else of the plan is needed), an -o frame pattern, an
// EXR (tiles hold display bytes, not linear colours).
void check_join_request(const Options& options, const OutputPlan& plan);

// Reads, checks and pastes the tiles of options.join into frame `frame` of the scene; with
// options.alpha the tiles and the image have an alpha channel. Throws SceneError (exit 2)
// naming the tile at fault, or "--join" for pixels that no tile covers; Interrupted between
// tiles.
Image join_tiles(const Options& options, const Scene& scene, int frame);

// join_tiles for the run's one image, written (complete, not yet renamed: staged_outputs.h)
// with the PNG description a render of it writes.
std::unique_ptr<AtomicFile> write_joined_image(const Options& options, const Scene& scene, const OutputPlan& plan);

}  // namespace clr
