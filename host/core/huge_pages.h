// Large buffers that are filled right after they are allocated (decoded images read back from
// the image cache, texture buffers). The kernel gives fresh memory a 4 KiB page at a time, and
// on a warm start faulting those pages in was the largest single cost of the whole process
// (docs/benchmarks.md, Against POV-Ray); asking for transparent huge pages makes it one fault
// per 2 MiB. Only advice: where the kernel has none to give, the buffer is the same, in 4 KiB pages.
#pragma once

#include <cstddef>
#include <vector>

namespace clr {

// Asks for huge pages over the whole 2 MiB-aligned part of [data, data + size).
void advise_huge_pages(void* data, std::size_t size);

// `buffer` (empty) given room for `size` bytes, its storage advised; nothing touched yet.
void reserve_with_huge_pages(std::vector<unsigned char>& buffer, std::size_t size);

// `buffer` (empty) resized to `size` value-initialized bytes, its storage advised first.
void resize_with_huge_pages(std::vector<unsigned char>& buffer, std::size_t size);

}  // namespace clr
