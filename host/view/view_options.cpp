#include "view/view_options.h"

#include <CLI/CLI.hpp>
#include <iostream>
#include <string>
#include <vector>

#include "core/printable_text.h"
#include "view/request_guard.h"

namespace clr {
namespace {

// Render options that name outputs or other modes: the viewer writes only what the page asks
// for, into --output-dir, so these would be silently ignored; they are refused instead.
std::string option_not_for_view(const Options& options) {
    const Options defaults;
    if (!options.output_path.empty()) return "-o";
    if (!options.video_path.empty()) return "--video";
    if (!options.frames.empty()) return "--frames";
    if (options.assemble) return "--assemble";
    if (options.resume) return "--resume";
    if (options.quality != defaults.quality) return "--quality";
    if (options.list_devices) return "--list-devices";
    if (options.print_frame_count) return "--frame-count";
    if (options.reference) return "--reference";
    if (!options.stats_path.empty()) return "--stats";
    if (options.explain_pixel) return "--explain-pixel";
    if (options.check) return "--check";
    if (!options.join.empty()) return "--join";
    if (options.crop) return "--crop";
    if (options.alpha) return "--alpha";
    if (options.progress != defaults.progress) return "--progress";
    if (options.plan) return "--plan";
    if (!options.display_server.empty()) return "--display-server";
    return "";
}

bool is_bind_address(const std::string& bind) {
    if (bind == "localhost") return true;
    const bool bracketed = bind.size() >= 2 && bind.front() == '[' && bind.back() == ']';
    return is_ip_address(bracketed ? bind.substr(1, bind.size() - 2) : bind);
}

int usage_error(const std::string& message) {
    std::cerr << "clrender: error: " << printable(message) << "\nRun 'clrender view --help' for more information.\n";
    return 1;
}

}  // namespace

ParsedViewOptions parse_view_options(int argc, const char* const* argv) {
    ParsedViewOptions parsed;
    ViewOptions& options = parsed.options;
    CLI::App app{"clrender view: renders the scene live in the browser, on a server on this machine", "clrender view"};
    app.footer(
        "The render options --size, --spp, -d, -t, -D, --precision, --placeholders, --seed, --strict, --kernel-dir "
        "and -q apply to what the viewer renders, as for a render (clrender --help).\n"
        "Prints one line, 'clrender: view at http://127.0.0.1:PORT/?token=TOKEN', and runs until Ctrl-C or SIGTERM "
        "(exit 130 or 143). See docs/command-line.md, Viewer.");
    app.allow_extras();
    app.add_option("--port", options.port, "TCP port to listen on; 0 (default): a free port")->check(CLI::Range(0, 65535));
    app.add_option("--bind", options.bind,
                   "IP address (or localhost) to listen on; default 127.0.0.1 (this machine only); an address "
                   "beyond this machine warns, since other machines may then reach the viewer");
    CLI::Option* output_dir = app.add_option("--output-dir", options.output_dir,
                                             "Folder for the scenes and videos the page exports, never replacing a "
                                             "file; default the current folder");
    bool no_browser = false;
    app.add_flag("--no-browser", no_browser, "Do not open the browser (xdg-open); only print the address");
    std::vector<std::string> render_arguments;
    try {
        app.parse(argc, argv);
        if (options.bind.empty()) throw CLI::ValidationError("--bind", "the value is empty; give an address");
        // An address, never a name: a name would be looked up (and could name another machine
        // tomorrow), and the Host check admits the bound address (view/request_guard.h).
        if (!is_bind_address(options.bind))
            throw CLI::ValidationError("--bind", "'" + printable(options.bind) +
                                                     "' is not an IP address (127.0.0.1, ::1, 0.0.0.0, ...) or localhost");
        if (options.output_dir.empty()) throw CLI::ValidationError("--output-dir", "the value is empty; give a folder");
        render_arguments = app.remaining();
    } catch (const CLI::ParseError& error) {
        if (error.get_exit_code() == 0) {
            parsed.exit_code = app.exit(error);
            return parsed;
        }
        parsed.exit_code = usage_error(error.what());
        return parsed;
    }
    options.open_browser = !no_browser;
    options.output_dir_given = output_dir->count() > 0;

    // The scene and the render options: the render command's parser, so that they are checked
    // and spelt as there.
    std::vector<const char*> render_argv{"clrender"};
    for (const std::string& argument : render_arguments) render_argv.push_back(argument.c_str());
    ParsedOptions render = parse_options(static_cast<int>(render_argv.size()), render_argv.data());
    if (render.exit_code) {
        parsed.exit_code = render.exit_code;
        return parsed;
    }
    options.render = render.options;
    const std::string refused = option_not_for_view(options.render);
    if (!refused.empty()) {
        parsed.exit_code = usage_error(refused + " does not apply to clrender view: the page exports scenes and videos "
                                                 "into --output-dir");
        return parsed;
    }
    return parsed;
}

}  // namespace clr
