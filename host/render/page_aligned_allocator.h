// Storage for buffers that an OpenCL device uses in place (CL_MEM_USE_HOST_PTR): the texel
// buffer. A device may only use host memory without copying it where the pointer meets its
// CL_DEVICE_MEM_BASE_ADDR_ALIGN (PoCL: 128 bytes); malloc's large blocks start 16 bytes into a
// page. Page alignment meets every device's alignment that clrender has met (the spec's
// largest data type, long16, is 128 bytes), and blocks of 2 MiB or more start on a huge-page
// boundary and are advised so (core/huge_pages.h): one fault per 2 MiB as they fill.
#pragma once

#include <cstddef>
#include <cstdlib>
#include <new>
#include <vector>

#include "core/huge_pages.h"

namespace clr {

inline constexpr std::size_t kPageBytes = 4096;
inline constexpr std::size_t kHugePageBytes = std::size_t(2) << 20;

template <typename T>
struct PageAlignedAllocator {
    using value_type = T;

    PageAlignedAllocator() = default;
    template <typename U>
    PageAlignedAllocator(const PageAlignedAllocator<U>&) {}

    T* allocate(std::size_t count) {
        const std::size_t bytes = count * sizeof(T);
        const std::size_t alignment = bytes >= kHugePageBytes ? kHugePageBytes : kPageBytes;
        // aligned_alloc wants a multiple of the alignment.
        void* data = std::aligned_alloc(alignment, (bytes + alignment - 1) / alignment * alignment);
        if (!data) throw std::bad_alloc();
        if (alignment == kHugePageBytes) advise_huge_pages(data, bytes);
        return static_cast<T*>(data);
    }
    void deallocate(T* data, std::size_t) { std::free(data); }

    template <typename U>
    bool operator==(const PageAlignedAllocator<U>&) const { return true; }
    template <typename U>
    bool operator!=(const PageAlignedAllocator<U>&) const { return false; }
};

template <typename T>
using PageAlignedVector = std::vector<T, PageAlignedAllocator<T>>;

}  // namespace clr
