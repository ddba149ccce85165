// Built OpenCL programs kept across runs: the device's binary of a program, keyed on the SHA-256
// of everything that can change it (device, driver, platform, build options, the whole source,
// this entry format). Building from the binary skips the compiler front end, several times
// faster on PoCL than a build with PoCL's own cache warm (docs/benchmarks.md, Figures behind
// design choices). Entries live in programs/ under the cache folder
// (core/cache_entry_folder.h): written atomically, checked in full before the driver sees a
// byte (core/cache_entry.h), and kept under a size limit. An entry that is missing or fails a
// check is a miss, never an error, and is replaced.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/cache_entry_folder.h"
#include "core/sha256.h"
#include "device/opencl.h"

namespace clr {

class ProgramCache {
public:
    // Part of every key and header: bump it when the entry's content changes meaning.
    // 3: binaries built with with_exact_arithmetic()'s options, which keys do not hold.
    static constexpr std::uint32_t kFormatVersion = 3;
    // A few programs per feature set of a scene, each a few MB on PoCL.
    static constexpr std::uint64_t kDefaultSizeLimit = std::uint64_t(256) << 20;

    using Key = Sha256Digest;

    // programs/ under the folder from the environment (core/cache_folder.h): $CLRENDER_CACHE_DIR
    // when set ("off" or empty: no cache), else $XDG_CACHE_HOME/clrender, else
    // $HOME/.cache/clrender.
    static ProgramCache from_environment();

    // Entries go in `cache_folder`/programs; "" disables the cache.
    explicit ProgramCache(std::string cache_folder, std::uint64_t size_limit = kDefaultSizeLimit);
    bool enabled() const { return entries_.enabled(); }
    const std::string& cache_folder() const { return entries_.root(); }
    std::string folder() const { return entries_.folder(); }

    // The key of a program: every input of the build.
    static Key key(const cl::Device& device, const std::string& source, const std::string& options);
    // The entry's file for `key`.
    std::string path(const Key& key) const { return entries_.path(key); }

    // The verified binary stored for `key`; nothing on a miss.
    std::optional<std::vector<unsigned char>> load(const Key& key) const;
    // The verified binary for `key` for building a program, held aside (CacheEntryFolder::borrow)
    // until the build has succeeded: then give_back(), or discard() when the driver refused it.
    // A binary that fails the driver's own magic (`driver_magic`, when not empty) is refused
    // here, before the driver sees it.
    std::optional<std::vector<unsigned char>> borrow(const Key& key, const std::string& driver_magic,
                                                     std::string& aside) const;
    void give_back(const Key& key, const std::string& aside) const { entries_.give_back(key, aside); }
    void discard(const std::string& aside) const { entries_.discard(aside); }
    // The first bytes of every binary `device`'s driver produces, when clrender knows them
    // (PoCL: "poclbin\0"); "" otherwise.
    static std::string driver_magic(const cl::Device& device);
    // Best effort: a folder that cannot be written just leaves the cache empty.
    void store(const Key& key, const std::vector<unsigned char>& binary) const;

private:
    CacheEntryFolder entries_;
};

}  // namespace clr
