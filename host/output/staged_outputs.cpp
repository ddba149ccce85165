#include "output/staged_outputs.h"

#include <utility>

namespace clr {

void StagedOutputs::add(std::unique_ptr<AtomicFile> file) {
    file->complete();
    std::lock_guard<std::mutex> lock(mutex_);
    files_.push_back(std::move(file));
}

void StagedOutputs::commit_all() {
    std::lock_guard<std::mutex> lock(mutex_);
    for (std::unique_ptr<AtomicFile>& file : files_) file->commit();
    files_.clear();
}

}  // namespace clr
