// `clrender compare SCENE IMAGE [-o heat.png] [--tolerance N]` (docs/command-line.md,
// Comparing with an image): renders the scene as a run would and compares the render with
// IMAGE, as pbrt's `imgtool diff` compares two images, for a student checking a render of
// their own against clrender's.
#pragma once

#include "app/compare_options.h"

namespace clr {

// Returns 0 when no pixel differs by more than the tolerance, kExitImagesDiffer (7) when some
// do; throws clr::Error for everything else (IMAGE missing, damaged or of another size: exit 2,
// naming it; a heat map that cannot be written or would replace an input: exit 4).
int run_compare(const CompareRequest& request);

}  // namespace clr
