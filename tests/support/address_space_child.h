// Runs a check in a forked child with bounded resources: a reader that holds far more memory
// than it should fails the check (std::bad_alloc) instead of exhausting the machine, and one
// that waits for ever is ended instead of hanging the test.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>

namespace clr::testing {

struct ChildBounds {
    // How far the child's address space may grow beyond what it holds when forked; none: no
    // bound. AddressSanitizer's process already holds terabytes of address space for its shadow
    // memory and its allocator maps more as it goes: tests give none under it.
    std::optional<std::uint64_t> address_space_to_spare;
    unsigned seconds = 0;  // SIGALRM after this long; 0: no bound
};

// Whether `check` returned true in a child within `bounds`; false where the child ended
// otherwise (a signal, an exception, a bound that could not be set).
bool passes_in_bounded_child(const ChildBounds& bounds, const std::function<bool()>& check);

}  // namespace clr::testing
