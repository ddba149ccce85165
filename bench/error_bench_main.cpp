// clrender_error_bench: run time against error (docs/error-benchmark.md, How to read it). Renders
// each scene at several sample counts in float and in double, times every setting, compares
// its image with a high-sample double-precision reference (RMSE, PSNR, SSIM), marks the Pareto
// front, and optionally names the fastest setting that meets a target error.
//
//   clrender_error_bench [--size 480x270] [--repeat 3] [--spp 1,2,4,8,16,32] [--reference-spp 256]
//                        [--scenes a,b] [--device SEL] [--root DIR] [--json PATH] [--markdown PATH]
//                        [--images DIR] [--target-psnr DB | --target-rmse VALUE]
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "bench/bench_program.h"
#include "bench/bench_stats.h"
#include "core/stopwatch.h"
#include "bench/error_metrics.h"
#include "bench/error_report.h"
#include "bench/error_scenes.h"
#include "core/errors.h"
#include "device/device_selection.h"
#include "output/image_writer.h"
#include "render/renderer.h"
#include "scene/scene_loader.h"

namespace clr::bench {
namespace {

struct Options {
    ErrorRunSettings settings;
    std::string device;
    std::string root = CLRENDER_SOURCE_DIR;
    std::vector<std::string> scenes;  // empty: all
    std::string json_path, markdown_path, images_dir;
    std::optional<ErrorTarget> target;
    std::string command;  // as run, for the Markdown document
};

void parse_size(const std::string& text, ErrorRunSettings& settings) {
    char x = 0;
    std::istringstream in(text);
    if (!(in >> settings.width >> x >> settings.height) || x != 'x' || settings.width < kSsimWindow ||
        settings.height < kSsimWindow)
        throw UsageError("--size wants WIDTHxHEIGHT, at least " + std::to_string(kSsimWindow) + " each (SSIM's window), not '" +
                         text + "'");
}

std::string command_line(int argc, char** argv) {
    std::string text = std::filesystem::path(argv[0]).filename().string();
    for (int i = 1; i < argc; ++i) text += std::string(" ") + argv[i];
    return text;
}

// The options, or nothing when CLI11 has handled the command line (--help, an error) and
// the process should end with `exit_code`.
std::optional<Options> parse_options(int argc, char** argv, int& exit_code) {
    Options options;
    ErrorRunSettings& settings = options.settings;
    settings.spp = {1, 2, 4, 8, 16, 32};
    std::string size = "480x270";
    double target_psnr = 0, target_rmse = 0;
    CLI::App app{"clrender's run time against image error, per sample count and precision"};
    app.add_option("--size", size, "image size WIDTHxHEIGHT")->capture_default_str();
    app.add_option("--repeat", settings.repeat, "timed frames per setting (the median is reported)")
        ->capture_default_str()
        ->check(CLI::PositiveNumber);
    app.add_option("--spp", settings.spp, "sample counts to measure, comma-separated")
        ->delimiter(',')
        ->capture_default_str()
        ->check(CLI::Range(1, kMaxSamplesPerPixel));
    app.add_option("--reference-spp", settings.reference_spp, "samples per pixel of the double-precision reference")
        ->capture_default_str()
        ->check(CLI::Range(1, kMaxSamplesPerPixel));
    app.add_option("--scenes", options.scenes, "scenes to run, comma-separated (default: all)")->delimiter(',');
    app.add_option("--device", options.device, "OpenCL device: index, platform:device or name (default: first CPU)");
    app.add_option("--root", options.root, "the repository, where scenes/ is read from")->capture_default_str();
    app.add_option("--json", options.json_path, "write every figure as JSON to this file");
    app.add_option("--markdown", options.markdown_path, "write the table and how to read it as Markdown to this file");
    app.add_option("--images", options.images_dir, "write each scene's reference and each setting's image as PNG here");
    auto* psnr = app.add_option("--target-psnr", target_psnr, "print the fastest setting per scene with PSNR >= DB");
    auto* rmse = app.add_option("--target-rmse", target_rmse, "print the fastest setting per scene with RMSE <= VALUE");
    psnr->excludes(rmse);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        exit_code = app.exit(error);
        return std::nullopt;
    }
    parse_size(size, settings);
    if (psnr->count()) options.target = ErrorTarget{ErrorTarget::Metric::Psnr, target_psnr};
    if (rmse->count()) options.target = ErrorTarget{ErrorTarget::Metric::Rmse, target_rmse};
    options.command = command_line(argc, argv);
    return options;
}

std::vector<ErrorScene> chosen_scenes(const Options& options) {
    std::vector<ErrorScene> all = error_bench_scenes(options.root, options.settings.width, options.settings.height);
    if (options.scenes.empty()) return all;
    std::vector<ErrorScene> chosen;
    for (const std::string& name : options.scenes) {
        auto it = std::find_if(all.begin(), all.end(), [&](const ErrorScene& s) { return s.name == name; });
        if (it == all.end()) {
            std::string names;
            for (const ErrorScene& s : all) names += (names.empty() ? "" : ", ") + s.name;
            throw UsageError("--scenes: no scene '" + name + "'; the scenes are " + names);
        }
        chosen.push_back(*it);
    }
    return chosen;
}

std::string file_name_of(const std::string& name) {
    std::string file;
    for (char c : name) file += std::isalnum(static_cast<unsigned char>(c)) ? c : '-';
    return file;
}

// A renderer for the view at `spp` samples per pixel. Each setting gets its own, so that all
// of a scene's settings can take turns frame by frame; the program is built once per
// precision, as PoCL caches builds of the same source and options.
std::unique_ptr<Renderer> make_renderer(DeviceContext& device, const ErrorScene& view, int spp, bool double_precision) {
    Scene scene = view.scene;
    scene.sampling.samples_per_pixel = spp;
    RendererOptions options;
    options.double_precision = double_precision;
    return std::make_unique<Renderer>(device, scene, options);
}

// One frame of `view`, timed: the kernel from OpenCL's profiling, the wall time around it all.
Image render_timed(Renderer& renderer, const ErrorScene& view, double* kernel_ms, double* wall_ms) {
    FrameTiming timing;
    const Stopwatch stopwatch;
    Image image = renderer.render(view.key, view.frame, &timing);
    if (wall_ms) *wall_ms = stopwatch.elapsed_ms();
    if (kernel_ms) *kernel_ms = timing.kernel_ms;
    return image;
}

Image render_reference(DeviceContext& device, const ErrorScene& view, const Options& options, SceneErrors& result) {
    std::cerr << "error bench: " << view.name << ": reference, double, " << options.settings.reference_spp << " spp"
              << std::endl;
    std::unique_ptr<Renderer> renderer = make_renderer(device, view, options.settings.reference_spp, true);
    Image reference = render_timed(*renderer, view, &result.reference_kernel_ms, nullptr);
    if (!options.images_dir.empty())
        write_image(options.images_dir + "/" + file_name_of(view.name) + "-reference.png", reference);
    return reference;
}

// A renderer and a row for every setting, each warmed up by one untimed frame (which also
// pays PoCL's compile for the work-group size on first use).
std::vector<std::unique_ptr<Renderer>> set_up_settings(DeviceContext& device, const ErrorScene& view,
                                                       const ErrorRunSettings& settings, std::vector<ErrorRow>& rows) {
    std::vector<std::unique_ptr<Renderer>> renderers;
    for (bool double_precision : {false, true})
        for (int spp : settings.spp) {
            ErrorRow row;
            row.double_precision = double_precision;
            row.spp = spp;
            const Stopwatch stopwatch;
            renderers.push_back(make_renderer(device, view, spp, double_precision));
            row.build_ms = stopwatch.elapsed_ms();
            render_timed(*renderers.back(), view, nullptr, nullptr);
            rows.push_back(row);
        }
    return renderers;
}

// `repeat` timed frames of every setting, the settings taking turns frame by frame so that
// load from other processes slows them alike. Returns each setting's last image.
std::vector<Image> time_in_turns(const std::vector<std::unique_ptr<Renderer>>& renderers, const ErrorScene& view,
                                 int repeat, std::vector<ErrorRow>& rows) {
    std::vector<Image> images(rows.size());
    for (int frame = 0; frame < repeat; ++frame)
        for (std::size_t i = 0; i < rows.size(); ++i) {
            double kernel_ms = 0, wall_ms = 0;
            images[i] = render_timed(*renderers[i], view, &kernel_ms, &wall_ms);
            rows[i].kernel_ms.push_back(kernel_ms);
            rows[i].wall_ms.push_back(wall_ms);
        }
    return images;
}

// Every setting of one scene: timed, compared with the reference, and the Pareto front marked.
SceneErrors run_scene(DeviceContext& device, const ErrorScene& view, const Options& options) {
    SceneErrors result{view.name, view.source, view.frame, 0, {}};
    Image reference = render_reference(device, view, options, result);
    std::vector<std::unique_ptr<Renderer>> renderers = set_up_settings(device, view, options.settings, result.rows);
    std::cerr << "error bench: " << view.name << ": timing " << result.rows.size() << " settings" << std::endl;
    std::vector<Image> images = time_in_turns(renderers, view, options.settings.repeat, result.rows);
    for (std::size_t i = 0; i < result.rows.size(); ++i) {
        ErrorRow& row = result.rows[i];
        row.error = compare_to_reference(images[i], reference);
        if (!options.images_dir.empty())
            write_image(options.images_dir + "/" + file_name_of(view.name) + "-" + row.precision() + "-" +
                            std::to_string(row.spp) + ".png",
                        images[i]);
    }
    mark_pareto(result.rows);
    return result;
}

int run(const Options& options) {
    std::vector<ErrorScene> views = chosen_scenes(options);
    DeviceEntry entry = select_device(list_devices(), options.device);
    DeviceContext device(entry);
    if (!options.images_dir.empty()) std::filesystem::create_directories(options.images_dir);
    std::vector<SceneErrors> results;
    for (const ErrorScene& view : views) results.push_back(run_scene(device, view, options));

    print_table(std::cout, results, options.settings);
    if (options.target) print_target(std::cout, results, *options.target);
    if (!options.json_path.empty()) write_json(options.json_path, results, entry, options.settings, options.target);
    if (!options.markdown_path.empty())
        write_markdown(options.markdown_path, results, entry, options.settings, options.command);
    return kExitOk;
}

}  // namespace
}  // namespace clr::bench

int main(int argc, char** argv) {
    return clr::bench::run_bench_program("clrender_error_bench", argc, argv, clr::bench::parse_options, clr::bench::run);
}
