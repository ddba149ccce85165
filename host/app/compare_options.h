// The command line of `clrender compare SCENE IMAGE` (docs/command-line.md, Comparing with an
// image): what to render, as for a run, and how to compare it with IMAGE.
#pragma once

#include <optional>
#include <string>

#include "app/options.h"

namespace clr {

struct CompareRequest {
    Options render;              // the scene and the options that say how it renders
    std::string image_path;      // IMAGE, the image to compare the render with
    std::string heat_map_path;   // -o: the heat map to write (.png or .ppm); empty: none
    int tolerance = 0;           // --tolerance: a channel may differ by this many 1/255 steps
    bool json = false;           // --json: the report as one JSON object
};

// The request, or the exit code when parsing alone decided the outcome (--help: 0, a usage
// error: 1, after printing the message). argv[0] is the word "compare".
struct ParsedCompare {
    CompareRequest request;
    std::optional<int> exit_code;
};
ParsedCompare parse_compare_options(int argc, const char* const* argv);

// Whether the command line asks for `clrender compare` (its first argument is "compare"; a
// scene file of that name is given as ./compare).
bool is_compare_command(int argc, const char* const* argv);

}  // namespace clr
