// Fills a program store (device/program_store.h) ahead of need: the binaries of the program
// the command line renders with (render_packets) for a list of feature sets, as a run would
// build them on `device`, so that a first run finds them instead of compiling.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "device/device_selection.h"
#include "render/feature_set.h"

namespace clr {

struct ProgramStoreBuild {
    int built = 0;    // compiled and written now
    int kept = 0;     // already there and good
    int failed = 0;   // the driver could not build or hand back the binary
    int removed = 0;  // entries no longer wanted (older kernels, another device)
};

// Makes `folder` (created when missing) hold exactly the entries for `feature_sets` on
// `device`: builds the missing ones, keeps good ones, removes other entries of ours
// (`<64 hex>.clbin`). Failures are counted and reported on `log`, never thrown: a store
// missing some programs only means slower first runs.
ProgramStoreBuild build_program_store(const std::string& folder, const DeviceEntry& device,
                                      const std::vector<FeatureSet>& feature_sets, std::ostream& log);

// Removes every entry of ours from `folder` (no device: an empty store); the count removed.
int empty_program_store(const std::string& folder);

}  // namespace clr
