// Built OpenCL programs kept across runs: the device's binary of a program, keyed on
// everything that can change it (device, driver, platform, build options, the whole source).
// Building from the binary skips the compiler front end: on PoCL 4 ms instead of 26 ms with
// PoCL's own cache warm. Entries are written atomically (temporary file, then rename); an
// entry that is missing, unreadable, truncated or for another key is a miss, never an error.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "device/opencl.h"

namespace clr {

class ProgramCache {
public:
    // The folder from the environment (core/cache_folder.h): $CLRENDER_CACHE_DIR when set
    // ("off" or empty: no cache), else $XDG_CACHE_HOME/clrender, else $HOME/.cache/clrender.
    static ProgramCache from_environment();

    explicit ProgramCache(std::string folder) : folder_(std::move(folder)) {}
    bool enabled() const { return !folder_.empty(); }
    const std::string& folder() const { return folder_; }

    // The key of a program: every input of the build, as text.
    static std::string key(const cl::Device& device, const std::string& source, const std::string& options);
    // The entry's file for `key`.
    std::string path(const std::string& key) const;

    std::optional<std::vector<unsigned char>> load(const std::string& key) const;
    // Best effort: a folder that cannot be written just leaves the cache empty.
    void store(const std::string& key, const std::vector<unsigned char>& binary) const;

private:
    std::string folder_;
};

}  // namespace clr
