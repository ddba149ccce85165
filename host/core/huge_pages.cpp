#include "core/huge_pages.h"

#include <sys/mman.h>

#include <cstdint>

namespace clr {
namespace {

constexpr std::uintptr_t kHugePage = std::uintptr_t(2) << 20;

}  // namespace

void advise_huge_pages(void* data, std::size_t size) {
    const auto start = reinterpret_cast<std::uintptr_t>(data);
    const std::uintptr_t first = (start + kHugePage - 1) & ~(kHugePage - 1);
    const std::uintptr_t last = (start + size) & ~(kHugePage - 1);
    // Failure (no THP in this kernel, a disabled policy) only leaves the pages small.
    if (last > first) ::madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
}

void reserve_with_huge_pages(std::vector<unsigned char>& buffer, std::size_t size) {
    // reserve() allocates without touching a page, so the advice comes before the first fault.
    if (!buffer.empty() || buffer.capacity() >= size) return;
    buffer.reserve(size);
    if (size >= kHugePage) advise_huge_pages(buffer.data(), size);
}

void resize_with_huge_pages(std::vector<unsigned char>& buffer, std::size_t size) {
    reserve_with_huge_pages(buffer, size);
    buffer.resize(size);
}

}  // namespace clr
