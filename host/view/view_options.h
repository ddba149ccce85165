// What `clrender view SCENE [options]` was asked for: the server's own options and the render
// options that apply to what it renders (docs/command-line.md, Viewer).
#pragma once

#include <optional>
#include <string>

#include "app/options.h"

namespace clr {

struct ViewOptions {
    // The scene and the render options that apply to the view: --size, --spp, -d, -t, -D,
    // --precision, --placeholders, --seed, --strict, --kernel-dir, -q; parsed by the render
    // command's own parser, so that they mean exactly what they mean for a render.
    Options render;
    int port = 0;                    // --port; 0: a free port the system picks
    std::string bind = "127.0.0.1";  // --bind
    std::string output_dir = ".";    // --output-dir: where exported scenes and videos go
    bool output_dir_given = false;   // --output-dir was on the command line
    bool open_browser = true;        // off with --no-browser
};

struct ParsedViewOptions {
    ViewOptions options;
    std::optional<int> exit_code;  // --help: 0; a usage error: 1 (after printing the message)
};

// Parses the arguments after `view` (argv[0] is "view").
ParsedViewOptions parse_view_options(int argc, const char* const* argv);

}  // namespace clr
