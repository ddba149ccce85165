// --plan (docs/command-line.md, Planning a run): what a run will do, as JSON, for a program that
// splits the run (scripts/slurm-render.sh): the frames, the image size, every file the run reads,
// writes or reads back, and how the work can be split. Printed only after every check a render
// makes without a device has passed.
#pragma once

#include <string>

#include "app/options.h"
#include "app/output_plan.h"
#include "scene/scene.h"

namespace clr {

// The plan as one JSON object and a line break. Paths are as the command line gives them (or
// as clrender names them by default): relative ones are relative to the working folder.
std::string plan_json(const Options& options, const Scene& scene, const OutputPlan& plan);

}  // namespace clr
