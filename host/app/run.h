// The program once its options are parsed: load, render, write. Returns the exit code;
// errors are thrown as clr::Error and mapped to exit codes by main().
#pragma once

#include "app/options.h"
#include "core/image.h"
#include "scene/scene.h"

namespace clr {

int run(const Options& options);

// The parts of a run that other commands share (clrender compare): the scene as a run loads
// it (its warnings printed, --strict applied), and one frame rendered as a run renders it,
// on the device (or the reference) the options choose. Throw as run() does.
Scene load_scene_for_run(const Options& options);
Image render_one_frame(const Options& options, const Scene& scene, int frame);

}  // namespace clr
