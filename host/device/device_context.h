// One OpenCL device ready for work: its context and an in-order, profiling-enabled queue
// (profiling gives the kernel times of the timing report), and program builds on it.
#pragma once

#include <string>
#include <vector>

#include "device/device_selection.h"
#include "device/opencl.h"

namespace clr {

class DeviceContext {
public:
    // Throws DeviceError when the device cannot be opened.
    explicit DeviceContext(const DeviceEntry& device);
    DeviceContext(const DeviceContext&) = delete;
    DeviceContext& operator=(const DeviceContext&) = delete;

    const DeviceEntry& entry() const { return entry_; }
    const cl::Device& device() const { return entry_.device; }
    const cl::Context& context() const { return context_; }
    cl::CommandQueue& queue() { return queue_; }

    // Builds `source` with `options`. A failure throws DeviceError carrying the build
    // options and the compiler's log.
    // Builds from the program cache's binary when it has one (device/program_cache.h); the
    // binary of a build from source goes there on store_built_programs().
    cl::Program build_program(const std::string& source, const std::string& options) const;
    // Stores the binaries of the programs built from source in the program cache (best effort).
    // Asking PoCL for a binary compiles every kernel of the program (0.8 s cold), so the frame
    // loop calls this once its outputs are written. Never from a destructor: at exit, static
    // destruction may already have torn down the compiler inside the driver.
    void store_built_programs();
    int cache_hits() const { return cache_hits_; }  // builds served by the program cache

private:
    DeviceEntry entry_;
    cl::Context context_;
    cl::CommandQueue queue_;
    mutable int cache_hits_ = 0;
    struct PendingEntry {
        std::string folder, key;
        cl::Program program;
    };
    mutable std::vector<PendingEntry> to_store_;
};

}  // namespace clr
