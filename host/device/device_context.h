// One OpenCL device ready for work: its context and an in-order, profiling-enabled queue
// (profiling gives the kernel times of the timing report), and program builds on it.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "device/device_selection.h"
#include "device/opencl.h"
#include "device/program_cache.h"
#include "device/program_store.h"

namespace clr {

class DeviceContext {
public:
    // Throws DeviceError when the device cannot be opened. `store`: binaries built ahead of
    // need (device/program_store.h), tried when the program cache misses.
    explicit DeviceContext(const DeviceEntry& device, ProgramStore store = ProgramStore());
    // Puts the cache entries this context built programs from back under their names (a rename:
    // safe at exit, unlike asking the driver for binaries).
    ~DeviceContext();
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
    // The program from the program cache or the store, as build_program takes it, or nothing:
    // never compiles.
    std::optional<cl::Program> prebuilt_program(const std::string& source, const std::string& options) const;
    // Stores the binaries of the programs built from source in the program cache (best effort),
    // and puts back the entries this context built programs from (see ~DeviceContext).
    // Asking PoCL for a binary compiles every kernel of the program, which takes longer than a
    // frame (docs/benchmarks.md, Figures behind design choices), so the frame loop calls this
    // once its outputs are written. Never from a destructor: at exit, static
    // destruction may already have torn down the compiler inside the driver.
    void store_built_programs();
    int cache_hits() const { return cache_hits_; }  // builds served by the program cache
    int store_hits() const { return store_hits_; }  // builds served by the program store

private:
    // The cache key of a program; nothing when neither the cache nor the store is on, or no key
    // can be made.
    std::optional<ProgramCache::Key> key_of(const ProgramCache& cache, const std::string& source,
                                            const std::string& options) const;
    std::optional<cl::Program> prebuilt_program(const ProgramCache& cache, const std::optional<ProgramCache::Key>& key,
                                                const std::string& options) const;
    // The program built from the cache's binary for `key`; nothing on a miss or when the driver
    // refuses the binary (the entry is then removed).
    std::optional<cl::Program> build_from_cache(const ProgramCache& cache, const ProgramCache::Key& key,
                                                const std::string& options) const;

    // Gives the entries held aside since their programs were built back to the cache.
    void give_back_borrowed() const;

    DeviceEntry entry_;
    cl::Context context_;
    cl::CommandQueue queue_;
    mutable int cache_hits_ = 0;
    ProgramStore store_;
    mutable int store_hits_ = 0;
    struct PendingEntry {
        std::string cache_folder;
        ProgramCache::Key key;
        cl::Program program;
    };
    mutable std::vector<PendingEntry> to_store_;
    // Program cache entries held aside (ProgramCache::borrow) while their programs are in use: a
    // run that crashes in the driver leaves them aside, so the next run does not crash on them.
    struct Borrowed {
        std::string cache_folder;
        ProgramCache::Key key;
        std::string aside;
    };
    mutable std::vector<Borrowed> borrowed_;
};

}  // namespace clr
