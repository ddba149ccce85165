#include "app/compare_options.h"

#include <CLI/CLI.hpp>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <memory>
#include <vector>

#include "app/help_formatter.h"
#include "core/errors.h"
#include "core/printable_text.h"
#include "scene/limits.h"

namespace clr {
namespace {

constexpr int kMaxThreads = 4096;  // as for a run: more is a typing mistake, not a machine

// The render options a comparison takes, with the meaning they have for a run.
struct RenderValues {
    std::string size;
    std::string precision = "float";
    std::vector<std::string> defines;
    std::optional<long long> seed;
};

void add_render_options(CLI::App& app, Options& options, RenderValues& values) {
    app.add_option("--frames", options.frames,
                   "The frame of the scene's camera path to render and compare, 0-based; default 0 (a still's only "
                   "frame)");
    app.add_option("-d,--device", options.device,
                   "OpenCL device, as for a run; default $CLRENDER_DEVICE, else the first CPU device");
    app.add_option("--size", values.size, "Override the scene's resolution, e.g. 1920x1080");
    app.add_option("--spp", options.samples_per_pixel, "Samples per pixel; overrides the scene's clrender.spp")
        ->check(CLI::Range(1, kMaxSamplesPerPixel));
    app.add_option("--seed", values.seed, "Seed of the sample pattern (0 to 4294967295); overrides clrender.seed")
        ->check(CLI::Range(0LL, 4294967295LL));
    app.add_option("-D,--define", values.defines, "Set a scene value before the scene is checked, as for a run")
        ->expected(1)
        ->allow_extra_args(false)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    app.add_option("--precision", values.precision, "Arithmetic of the kernels' geometry: float (default) or double")
        ->check(CLI::IsMember({"float", "double"}));
    app.add_flag("--reference", options.reference, "Render with the double-precision host reference instead of OpenCL");
    app.add_flag("--placeholders", options.placeholders,
                 "Render a magenta checkerboard for billboard images, and a unit cube for OBJ meshes, that cannot be "
                 "read, with a warning, instead of failing");
    app.add_option("-t,--threads", options.threads, "Compute units (threads) of the CPU device to render with")
        ->check(CLI::Range(1, kMaxThreads));
    app.add_option("--kernel-dir", options.kernel_dir, "Read the OpenCL sources from this folder");
    app.add_flag("--strict", options.strict, "Treat every warning of the scene's as an error (exit 2)");
}

void read_render_values(const RenderValues& values, Options& options) {
    if (!values.size.empty()) {
        int width = 0, height = 0;
        if (!parse_image_size(values.size, width, height))
            throw CLI::ValidationError("--size", "expected WIDTHxHEIGHT with positive integers, got '" + values.size + "'");
        options.width = width;
        options.height = height;
    }
    options.double_precision = values.precision == "double";
    for (const std::string& define : values.defines) {
        try {
            options.overrides.push_back(parse_scene_override(define));
        } catch (const UsageError& error) {
            throw CLI::ValidationError(error.what());
        }
    }
    if (values.seed) options.seed = static_cast<unsigned>(*values.seed);
}

}  // namespace

bool is_compare_command(int argc, const char* const* argv) { return argc > 1 && std::strcmp(argv[1], "compare") == 0; }

ParsedCompare parse_compare_options(int argc, const char* const* argv) {
    ParsedCompare parsed;
    CompareRequest& request = parsed.request;
    CLI::App app{"clrender compare: renders a scene and compares the render with an image, pixel by pixel; exit 0 "
                 "when no pixel differs by more than the tolerance, 7 when some do",
                 "clrender compare"};
    app.formatter(std::make_shared<HelpFormatter>());
    app.add_option("SCENE", request.render.scene_path, "Scene file (.json or .js)")->required();
    app.add_option("IMAGE", request.image_path, "Image to compare the render with (PNG, JPEG or PPM), of the "
                                                "render's size")
        ->required();
    app.add_option("-o,--output", request.heat_map_path,
                   "Write a heat map of the differences (.png or .ppm): pixels beyond the tolerance from blue "
                   "(1/255) through cyan, green and yellow to red (255/255), the others the render in dark grey");
    app.add_option("--tolerance", request.tolerance,
                   "A pixel differs when one of R, G and B differs by more than N/255; 0 to 255, default 0")
        ->type_name("N")
        ->check(CLI::Range(0, 255));
    app.add_flag("--json", request.json, "Print the report as one JSON object instead of text");
    RenderValues values;
    add_render_options(app, request.render, values);
    try {
        app.parse(argc, argv);
        for (const auto& [name, value] : {std::pair{"SCENE", &request.render.scene_path},
                                          std::pair{"IMAGE", &request.image_path},
                                          std::pair{"--output", &request.heat_map_path},
                                          std::pair{"--frames", &request.render.frames},
                                          std::pair{"--device", &request.render.device},
                                          std::pair{"--size", &values.size},
                                          std::pair{"--kernel-dir", &request.render.kernel_dir}})
            if (app.count(name) > 0 && value->empty())
                throw CLI::ValidationError(name, "the value is empty; give a value or leave the option out");
        read_render_values(values, request.render);
    } catch (const CLI::ParseError& error) {
        if (error.get_exit_code() == 0) {  // --help
            parsed.exit_code = app.exit(error);
            return parsed;
        }
        std::cerr << "clrender: error: compare: " << printable(error.what())
                  << "\nRun with clrender compare --help for more information.\n";
        parsed.exit_code = kExitUsage;
        return parsed;
    }
    if (request.render.device.empty()) {
        if (const char* env = std::getenv("CLRENDER_DEVICE")) request.render.device = env;
    }
    request.render.quiet = true;  // the report is the output; a run's device line and summary are not
    request.render.progress = "none";
    return parsed;
}

}  // namespace clr
