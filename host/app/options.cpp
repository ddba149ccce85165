#include "app/options.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <memory>
#include <regex>
#include <string>
#include <utility>
#include <vector>

#include "app/completion_words.h"
#include "app/display_server.h"
#include "app/help_footer.h"
#include "app/help_formatter.h"
#include "app/version_text.h"
#include "core/edit_distance.h"
#include "core/errors.h"
#include "core/message_lines.h"
#include "core/printable_text.h"
#include "scene/limits.h"

namespace clr {
namespace {

// "WxH" with positive integers.
bool parse_size(const std::string& text, int& width, int& height) {
    std::smatch match;
    static const std::regex pattern(R"((\d{1,6})[xX](\d{1,6}))");
    if (!std::regex_match(text, match, pattern)) return false;
    width = std::stoi(match[1]);
    height = std::stoi(match[2]);
    return width > 0 && height > 0;
}

// A value given as '' would read as the option left out (an empty --frames rendered every
// frame, an empty -d fell back to CLRENDER_DEVICE): such a value is a mistake in a script,
// e.g. an unset shell variable, and is refused.
void refuse_empty_values(const CLI::App& app, const std::vector<std::pair<std::string, const std::string*>>& values) {
    for (const auto& [name, value] : values) {
        if (app.count(name) > 0 && value->empty())
            throw CLI::ValidationError(name, "the value is empty; give a value or leave the option out");
    }
}

// --explain-pixel prints and writes no files: options that name outputs contradict it. (Checked
// here rather than with CLI11's excludes(), which would print the pairing under every option
// in --help and the man page.)
void refuse_outputs_with_explain_pixel(const CLI::App& app) {
    if (app.count("--explain-pixel") == 0) return;
    for (const char* output : {"--output", "--video", "--stats", "--assemble", "--resume", "--crop", "--alpha", "--plan"})
        if (app.count(output) > 0)
            throw CLI::ValidationError(std::string(output) + " excludes --explain-pixel: the explainer writes no files");
}

// More threads than this is a typing mistake, not a machine.
constexpr int kMaxThreads = 4096;
// Scene overrides and checks: -D, --seed, --strict, --check. The options are added in one
// block; their values are read by read_scene_check_options once the command line is parsed
// (docs/command-line.md, Scene overrides and checks).
struct SceneCheckOptions {
    std::vector<std::string> defines;
    std::optional<long long> seed;
};

void add_scene_check_options(CLI::App& app, Options& options, SceneCheckOptions& values) {
    app.add_option("-D,--define", values.defines,
                   "Set a scene value before the scene is checked, e.g. -D MaxDepth=2, -D spheres.0.radius=2, "
                   "-D /eye=[0,0,5]; the value is JSON, else a string. Repeatable, applied in order; --size, --spp "
                   "and --seed win over it")
        ->expected(1)
        ->allow_extra_args(false)  // one value each: `-D k=v scene.json` must not take the scene as a -D
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    app.add_option("--seed", values.seed, "Seed of the sample pattern (0 to 4294967295); overrides clrender.seed")
        ->check(CLI::Range(0LL, 4294967295LL));
    app.add_flag("--strict", options.strict, "Treat every warning as an error (exit 2, nothing written)");
    app.add_flag("--check", options.check,
                 "Check the scene, its images and the outputs as a render would, without an OpenCL device, and "
                 "print a summary; fails as the render would fail; writes nothing");
    app.add_flag("--plan", options.plan,
                 "Check as --check does, then print what the render would do as JSON: its frames, image size, "
                 "every file it writes and how it splits (frames or rows), for a render farm; writes nothing");
}

void read_scene_check_options(const SceneCheckOptions& values, Options& options) {
    for (const std::string& define : values.defines) {
        try {
            options.overrides.push_back(parse_scene_override(define));
        } catch (const UsageError& error) {
            throw CLI::ValidationError(error.what());
        }
    }
    if (values.seed) options.seed = static_cast<unsigned>(*values.seed);
}

// "unknown option '--sp'; did you mean --spp?" for the first unknown option that is a likely
// typo of a known one ("--sp", "-spp", "--sp=4"), a note for a known one given after "--",
// else "" (CLI11's message then stands).
std::string did_you_mean_option(const CLI::App& app) {
    std::vector<std::string> names;
    for (const CLI::Option* option : app.get_options())
        for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
    for (const std::string& extra : app.remaining()) {
        if (extra.size() < 2 || extra[0] != '-') continue;
        const std::string option = extra.substr(0, extra.find('='));
        // A known option left over came after "--", which makes every later word a file name.
        if (std::find(names.begin(), names.end(), option) != names.end())
            return "'" + option + "' comes after '--', which ends the options: give the options before it";
        const std::string best = closest_spelling(option, names);
        if (!best.empty()) return "unknown option '" + option + "'; did you mean " + best + "?";
    }
    return "";
}

}  // namespace

bool parse_image_size(const std::string& text, int& width, int& height) { return parse_size(text, width, height); }

ParsedOptions parse_options(int argc, const char* const* argv) {
    ParsedOptions parsed;
    Options& options = parsed.options;
    CLI::App app{"clrender: renders spheres-and-billboards scenes with OpenCL", "clrender"};
    // Version, help footer and completion (docs/command-line.md, Version): the
    // version names the build's commit and the OpenCL platforms; --help ends with the
    // environment variables, exit codes and examples; the hidden --completion-words lists
    // the options for the bash completion, so new options complete without editing it.
    app.set_version_flag("--version", std::function<std::string()>(version_text));
    app.footer(help_footer());
    app.formatter(std::make_shared<HelpFormatter>());
    app.add_flag_callback("--completion-words", [&app] {
           std::cout << completion_words(app);
           throw CLI::Success();
       })->group("");
    app.add_option("scene", options.scene_path, "Scene file (.json or .js)");
    app.add_option("-o,--output", options.output_path,
                   "Image to write (.png, .ppm, or .exr: linear float colours); for an animation a frame pattern "
                   "with %04d or ####; missing folders are made. Default: <scene name>.png for a still, "
                   "<scene name>_NNNN.png for the frames that --frames selects, no frames for a whole animation");
    app.add_option("--video", options.video_path,
                   "Video of the animation (.mp4: H.264, yuv420p; .gif). Default for an animation without -o "
                   "and --frames: <scene name>.mp4");
    app.add_option("--frames", options.frames, "Frames to render, 0-based: 7, 0-99 or 5,7,10-20; default all");
    app.add_flag("--assemble", options.assemble,
                 "Encode the frames that -o names (rendered earlier, e.g. split across processes) into --video "
                 "instead of rendering");
    app.add_flag("--resume", options.resume,
                 "Skip frames whose file (from the -o pattern, or the one image of a still or --frames N) is "
                 "finished: a PNG whose description is this render's, or any PPM or EXR file; e.g. after an "
                 "interrupted run; a video still gets every frame (existing ones are read back)");
    app.add_option("--quality", options.quality, "MP4 quality as x264 CRF, 0 (best) to 51; default 18")
        ->check(CLI::Range(0, 51));
    app.add_flag("--list-devices", options.list_devices,
                 "Print the OpenCL platforms and devices, then exit; with -d only the device it picks (exit 3 when "
                 "none)");
    app.add_flag("--frame-count", options.print_frame_count,
                 "Print the number of frames of the scene's animation (1 for a still), then exit");
    app.add_option("-d,--device", options.device,
                   "OpenCL device: cpu or gpu (the first device of that type), index (0), platform:device (0:1) "
                   "or a name substring (see --list-devices); default $CLRENDER_DEVICE, else the first CPU device");
    std::string size;
    app.add_option("--size", size, "Override the scene's resolution, e.g. 1920x1080");
    app.add_option("--spp", options.samples_per_pixel,
                   "Samples per pixel (anti-aliasing); overrides the scene's clrender.spp (default 1: pixel centres)")
        ->check(CLI::Range(1, kMaxSamplesPerPixel));
    std::string precision = "float";
    app.add_option("--precision", precision,
                   "Arithmetic of the kernels' geometry: float (default) or double (needs a device with "
                   "cl_khr_fp64, as PoCL's CPU device has)")
        ->check(CLI::IsMember({"float", "double"}));
    app.add_flag("--reference", options.reference, "Render with the double-precision host reference instead of OpenCL");
    app.add_flag("--placeholders", options.placeholders,
                 "Render a magenta checkerboard for billboard images, and a unit cube for OBJ meshes, that cannot be "
                 "read, with a warning, instead of failing");
    app.add_option("--stats", options.stats_path, "Write a JSON timing report to this file ('-': standard output)");
    app.add_flag("-q,--quiet", options.quiet, "No progress output");
    app.add_option("--kernel-dir", options.kernel_dir, "Read the OpenCL sources from this folder (kernel development)");
    // The pixel explainer (docs/explain-pixel.md): "X,Y", non-negative integers; it prints and
    // writes no files, so options that name outputs are refused with it.
    app.add_option_function<std::string>(
           "--explain-pixel",
           [&options](const std::string& text) {
               std::smatch match;
               static const std::regex pattern(R"((\d{1,6}),(\d{1,6}))");
               if (!std::regex_match(text, match, pattern))
                   throw CLI::ValidationError("--explain-pixel", "expected X,Y with non-negative integers (column,row), "
                                                                 "got '" + text + "'");
               options.explain_pixel = Options::PixelPosition{std::stoi(match[1]), std::stoi(match[2])};
           },
           "Print how pixel X,Y (column, row from the top-left, 0-based) of the frame --frames names (default 0) "
           "is computed, step by step, and the bytes the kernels give it; writes no files");

    // Progress and control (docs/command-line.md, Progress; Threads; Crop).
    app.add_option("--progress", options.progress,
                   "Progress on standard error: bar (default; only on a terminal, not with -q), none, or json "
                   "(one JSON object per line, also with -q and when not a terminal)")
        ->check(CLI::IsMember({"bar", "none", "json"}));
    app.add_option("-t,--threads", options.threads,
                   "Compute units (threads) of the CPU device to render with; default all")
        ->check(CLI::Range(1, kMaxThreads));
    std::string crop;
    app.add_option("--crop", crop,
                   "Render only pixels x0 <= x < x1, y0 <= y < y1 of the frame, as x0,x1,y0,y1; the image is the "
                   "crop's size, each pixel as in the full frame");
    SceneCheckOptions scene_check_values;
    add_scene_check_options(app, options, scene_check_values);

    // HDR and alpha outputs (docs/command-line.md, HDR and alpha outputs).
    app.add_flag("--alpha", options.alpha,
                 "Write an alpha channel: the fraction of each pixel's samples that hit an object, so the "
                 "background is transparent (PNG: straight alpha; EXR: premultiplied); not with a video or .ppm");

    // Joining tiles (docs/command-line.md, Joining tiles): one file per --join, so that the scene
    // is never taken as a tile whatever the order; repeatable. What it contradicts is refused
    // once the whole command line is parsed.
    app.add_option("--join", options.join,
                   "Make the image from TILE, a PNG that --crop wrote for this same render, instead of rendering; "
                   "repeatable, one tile each; the tiles must cover the frame exactly once (exit 2 naming the tile "
                   "otherwise); the image is byte for byte a one-process render's")
        ->type_name("TILE")
        ->expected(1)
        ->allow_extra_args(false)  // CLI11 lets a vector option take the arguments after it
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    // Streaming to tev (docs/command-line.md, Streaming to tev).
    app.add_option("--display-server", options.display_server,
                   "Show each frame in a running tev viewer at HOST:PORT (e.g. localhost:14158) as it is rendered; "
                   "a viewer that cannot be reached is a warning, never a failure")
        ->type_name("HOST:PORT");
    app.final_callback([&app, &options] {
        for (const std::string& tile : options.join)
            if (tile.empty()) throw CLI::ValidationError("--join", "the value is empty; give a tile file");
        if (options.join.empty()) return;
        for (const char* other : {"--crop", "--assemble", "--resume", "--video", "--explain-pixel"})
            if (app.count(other) > 0)
                throw CLI::ValidationError(std::string(other) + " cannot be used with --join, which makes one image "
                                           "from tiles rendered earlier (with --crop) and renders nothing");
    });

    try {
        app.parse(argc, argv);
        refuse_outputs_with_explain_pixel(app);
        if (app.count("scene") > 0 && options.scene_path.empty())
            throw CLI::ValidationError("scene", "the scene file name is empty");
        refuse_empty_values(app, {{"--output", &options.output_path},
                                  {"--video", &options.video_path},
                                  {"--frames", &options.frames},
                                  {"--device", &options.device},
                                  {"--size", &size},
                                  {"--stats", &options.stats_path},
                                  {"--kernel-dir", &options.kernel_dir},
                                  {"--crop", &crop},
                                  {"--display-server", &options.display_server}});
        if (!options.display_server.empty()) {
            try {
                parse_display_address(options.display_server);
            } catch (const UsageError& error) {
                throw CLI::ValidationError(error.what());
            }
        }
        if (!size.empty()) {
            int width = 0, height = 0;
            if (!parse_size(size, width, height))
                throw CLI::ValidationError("--size", "expected WIDTHxHEIGHT with positive integers, got '" + size + "'");
            options.width = width;
            options.height = height;
        }
        if (!crop.empty()) {
            options.crop = parse_pixel_rect(crop);
            if (!options.crop)
                throw CLI::ValidationError("--crop", "expected x0,x1,y0,y1 with 0 <= x0 < x1 and 0 <= y0 < y1, got '" +
                                                         crop + "'");
        }
        options.double_precision = precision == "double";
        read_scene_check_options(scene_check_values, options);
        if (options.scene_path.empty() && !options.list_devices)
            throw CLI::RequiredError("a scene file");
    } catch (const CLI::ParseError& error) {
        if (error.get_exit_code() == 0) {  // --help or --version: CLI11 prints them
            parsed.exit_code = app.exit(error);
            return parsed;
        }
        // A usage error, in the same form as every other error of clrender's, and a hint.
        const std::string suggestion = dynamic_cast<const CLI::ExtrasError*>(&error) ? did_you_mean_option(app) : "";
        std::cerr << message_line("error", printable(suggestion.empty() ? error.what() : suggestion), 1)
                  << (json_messages() ? "" : "Run with --help for more information.\n");
        parsed.exit_code = 1;
        return parsed;
    }
    if (options.device.empty() && !options.list_devices) {
        if (const char* env = std::getenv("CLRENDER_DEVICE")) options.device = env;
    }
    return parsed;
}

}  // namespace clr
