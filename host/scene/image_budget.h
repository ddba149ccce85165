// How much memory a scene's images may take, all together. Each image alone is limited by its
// header (8192 x 8192), but a scene may name any number of them, and a few small files can
// claim gigabytes once decoded. Every image's decoding cost is read from its header
// (ImageHeader::decoding_bytes) and reserved here BEFORE any image is decoded; images are
// decoded in parallel, so the costs are summed as if all were decoded at once.
#pragma once

#include <cstdint>
#include <string>

namespace clr {

// 2 GiB: four 8-bit 8192 x 8192 PNGs, or two 16-bit ones; a course scene needs a few MiB.
constexpr std::uint64_t kDefaultImageMemoryBytes = std::uint64_t(2) << 30;

// The environment variable that sets the limit, in MiB.
constexpr const char* kImageMemoryVariable = "CLRENDER_IMAGE_MEMORY_MIB";

// The limit from CLRENDER_IMAGE_MEMORY_MIB, else the default. Throws UsageError when the
// variable is not a whole number of MiB from 1 to 2^40.
std::uint64_t image_memory_limit_from_environment();

// The costs of a scene's images, taken in the scene's order so that the image reported is
// the same on every run.
class ImageMemoryBudget {
public:
    explicit ImageMemoryBudget(std::uint64_t limit) : limit_(limit) {}

    // Takes `bytes` from the budget; false (and nothing taken) when they do not fit.
    bool reserve(std::uint64_t bytes);
    std::uint64_t limit() const { return limit_; }
    std::uint64_t used() const { return used_; }

private:
    const std::uint64_t limit_;
    std::uint64_t used_ = 0;
};

}  // namespace clr
