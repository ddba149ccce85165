// Runs a check in a forked child whose address space may grow by only so many bytes: a reader
// that holds far more memory than it should fails the check (std::bad_alloc) instead of
// exhausting the machine. Not under AddressSanitizer, whose allocator reserves address space of
// its own (the callers skip their tests there).
#pragma once

#include <cstdint>
#include <functional>

namespace clr::testing {

// Whether `check` returned true in a child whose address space may grow by `spare` bytes beyond
// what it holds when forked; false where the limit cannot be set, or the child ends otherwise.
bool passes_with_address_space_to_spare(std::uint64_t spare, const std::function<bool()>& check);

}  // namespace clr::testing
