// What in the process's surroundings keeps the OpenCL driver from working, said as such: PoCL
// reports an address-space limit (ulimit -v), too few file descriptors (ulimit -n) or a kernel
// cache folder it cannot write as "no device", a failed build, or a crash, and a user told to
// install a driver that is installed cannot act on that (docs/robustness.md, The OpenCL
// driver under limits).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "core/errors.h"

namespace clr {

// The address-space limit (RLIMIT_AS, `ulimit -v`) in bytes; nothing when there is none.
std::optional<std::uint64_t> address_space_limit();

// The address space the process has mapped now (VmSize), in bytes; 0 when unknown.
std::uint64_t address_space_in_use();

// The address space a cold build of the kernels takes beyond what the process has mapped
// before it (PoCL loads LLVM, compiles, links with ld and loads the result; measured with
// docs/robustness.md's command, with room to spare).
constexpr std::uint64_t kAddressSpaceForABuild = std::uint64_t(512) << 20;

// Throws an out-of-memory Error (exit 6) when an address-space limit leaves less than
// kAddressSpaceForABuild: short of memory, PoCL's compiler hangs on a lock of its own or
// crashes instead of failing, so clrender refuses before it starts one.
void check_room_for_a_build();

// PoCL's own kernel cache folder: $POCL_CACHE_DIR, else $XDG_CACHE_HOME/pocl, else
// $HOME/.cache/pocl; "" when none is set.
std::string pocl_cache_folder();

// Why the driver may have found no device or failed: the first that applies of an address-space
// limit (an out-of-memory error, exit 6), too few free file descriptors, PoCL's cache folder
// not writable (exit 3); nothing when none does. `what_failed` starts the message ("no OpenCL
// device started").
std::optional<Error> driver_trouble(const std::string& what_failed);

// Raises a soft descriptor limit below 1024 towards that, as far as the hard limit allows (a low
// soft `ulimit -Sn` makes PoCL's linker fail), and, when an address-space or descriptor limit is set, turns a
// crash (PoCL aborts or faults when an allocation or open fails) into that limit's error line and
// exit code instead of a signal death. Called once, before the driver loads.
void prepare_for_driver_limits();

}  // namespace clr
