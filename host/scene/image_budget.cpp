#include "scene/image_budget.h"

#include <cstdlib>
#include <string>

#include "core/errors.h"

namespace clr {

std::uint64_t image_memory_limit_from_environment() {
    const char* text = std::getenv(kImageMemoryVariable);
    if (!text || !*text) return kDefaultImageMemoryBytes;
    constexpr std::uint64_t kMostMebibytes = std::uint64_t(1) << 40;  // far past any machine, far below overflow
    const std::string value = text;
    std::uint64_t mebibytes = 0;
    const bool digits = value.size() <= 13 && value.find_first_not_of("0123456789") == std::string::npos;
    if (digits) {
        for (char digit : value) mebibytes = mebibytes * 10 + static_cast<std::uint64_t>(digit - '0');
    }
    const bool valid = digits && mebibytes >= 1 && mebibytes <= kMostMebibytes;
    if (!valid) {
        throw UsageError(std::string(kImageMemoryVariable) + "='" + value +
                         "': expected the memory for decoded images in MiB, a whole number from 1 to " +
                         std::to_string(kMostMebibytes));
    }
    return mebibytes << 20;
}

bool ImageMemoryBudget::reserve(std::uint64_t bytes) {
    if (bytes > limit_ - used_) return false;  // used_ <= limit_ always: no overflow
    used_ += bytes;
    return true;
}

}  // namespace clr
