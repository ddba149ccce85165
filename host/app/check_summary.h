// What --check prints: a one-screen summary of a valid scene, read without an OpenCL device
// and with its images checked from their headers only (docs/command-line.md, Checking a scene).
#pragma once

#include <string>

#include "scene/scene.h"

namespace clr {

// The summary, one "name: value" line each: file, size, frames, objects, images, the kernel
// features a render would compile in, warnings. `double_precision`: --precision double.
std::string check_summary(const Scene& scene, bool double_precision);

}  // namespace clr
