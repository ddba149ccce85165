// What the user asked for on the command line (SPEC 3).
#pragma once

#include <optional>
#include <string>

namespace clr {

struct Options {
    std::string scene_path;
    std::string output_path;     // empty: <scene name>.png in the current folder
    std::string device;          // selector; empty: CLRENDER_DEVICE, else the first CPU device
    std::optional<int> width;    // --size
    std::optional<int> height;
    bool list_devices = false;
    bool reference = false;      // render with the double-precision host reference
    bool placeholders = false;   // stand-in images for missing ones
    bool quiet = false;
    std::string stats_path;      // JSON timing report
    std::string kernel_dir;      // load kernels from this folder (kernel development)
};

// Parses argv. Returns the options, or an exit code when parsing alone decided the outcome
// (--help: 0, a usage error: 1, after printing the message).
struct ParsedOptions {
    Options options;
    std::optional<int> exit_code;
};
ParsedOptions parse_options(int argc, const char* const* argv);

}  // namespace clr
