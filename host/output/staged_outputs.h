// Outputs that must replace their earlier versions together or not at all: a still's image
// and its --stats report. Each is written completely under its temporary name first; only
// when every write has succeeded are they renamed into place, so a failed write (a full
// disk, an unwritable --stats folder) leaves all earlier files as they were.
#pragma once

#include <memory>
#include <mutex>
#include <vector>

#include "output/atomic_file.h"

namespace clr {

class StagedOutputs {
public:
    // Takes a file that is complete()d (or completes it now; throws OutputError if that fails).
    // Safe to call from the thread that writes frames.
    void add(std::unique_ptr<AtomicFile> file);
    // Renames every staged file into place, in the order added. Throws OutputError.
    void commit_all();

private:
    std::mutex mutex_;
    std::vector<std::unique_ptr<AtomicFile>> files_;  // destroyed uncommitted: temporaries removed
};

}  // namespace clr
