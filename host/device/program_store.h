// A read-only store of program binaries built ahead of need: at build time
// (clrender_build_program_store, cmake/build_program_store.cmake) for the feature combinations
// a command line can ask for, installed under share/clrender/programs. A fresh install's first
// run then builds its program from a binary (milliseconds) instead of from source (seconds on
// PoCL: docs/benchmarks.md, Start-up).
//
// Entries are the program cache's, byte for byte (device/program_cache.h, core/cache_entry.h):
// keyed on the SHA-256 of the device, driver, platform, build options and whole source, so a
// store built for another device or driver, or for other kernels, simply misses; checked in full
// before the driver sees a byte. Unlike the cache, a run never writes, evicts or removes
// anything here: it is part of the install, not the user's. A damaged entry is ignored (a miss).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "device/opencl.h"
#include "device/program_cache.h"

namespace clr {

class ProgramStore {
public:
    // "" (the default): no store.
    explicit ProgramStore(std::string folder = "") : folder_(std::move(folder)) {}

    // $CLRENDER_PROGRAM_STORE when set ("off" or empty: no store), else the first folder of
    // folders_beside() that exists, for the running executable (/proc/self/exe).
    static ProgramStore from_environment();
    // Where an install keeps the store for `executable`: <bin>/../share/clrender/programs (an
    // installed binary), then <bin>/share/clrender/programs (the binary in its build tree).
    static std::vector<std::string> folders_beside(const std::string& executable);

    bool enabled() const { return !folder_.empty(); }
    const std::string& folder() const { return folder_; }
    // The entry's file for `key`.
    std::string path(const ProgramCache::Key& key) const;

    // The verified binary for `key`, or nothing: missing, damaged, for another key or format, or
    // not starting with `driver_magic` (when not empty). Never removes or changes a file.
    std::optional<std::vector<unsigned char>> load(const ProgramCache::Key& key, const std::string& driver_magic) const;

    // The store's builder only: writes the entry for `key` atomically (a temporary name, then
    // rename), readable by everyone. False when it cannot be written.
    bool write(const ProgramCache::Key& key, const std::vector<unsigned char>& binary) const;

private:
    std::string folder_;
};

// The program built from the store's binary for `source` and `options` on `device`, or
// nothing: no store, a miss, or a binary the driver refuses (which stays where it is).
std::optional<cl::Program> build_from_store(const ProgramStore& store, const cl::Context& context,
                                            const cl::Device& device, const ProgramCache::Key& key,
                                            const std::string& options);

}  // namespace clr
