#include "view/view_command.h"

#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <exception>
#include <filesystem>
#include <iostream>
#include <system_error>

#include "app/exit_status.h"
#include "core/errors.h"
#include "core/interruption.h"
#include "core/printable_text.h"
#include "device/driver_settings.h"
#include "scene/bounded_file.h"
#include "scene/scene_loader.h"
#include "view/access_token.h"
#include "view/path_export.h"
#include "view/render_service.h"
#include "view/video_job.h"
#include "view/view_options.h"
#include "view/view_server.h"

namespace clr {
namespace {

namespace fs = std::filesystem;

std::string read_scene_text(const std::string& path) {
    try {
        return read_bounded_file(path, kMaxSceneFileBytes);
    } catch (const BoundedFileError& error) {
        throw SceneError(printable(path), "", std::string("cannot read scene file: ") + printable(error.what()));
    }
}

// The scene as a render loads it (the same options, warnings and --strict).
Scene load_view_scene(const Options& options, const std::string& text) {
    LoadOptions load_options;
    load_options.placeholder_images = options.placeholders;
    load_options.width_override = options.width;
    load_options.height_override = options.height;
    load_options.samples_override = options.samples_per_pixel;
    load_options.seed_override = options.seed;
    load_options.overrides = options.overrides;
    Scene scene = parse_scene(text, options.scene_path, load_options);
    for (const std::string& warning : scene.warnings)
        std::cerr << "clrender: warning: " << printable(scene.path + ": " + warning) << "\n";
    if (options.strict && !scene.warnings.empty()) {
        const std::size_t n = scene.warning_count;
        throw SceneError(printable(scene.path), "",
                         std::to_string(n) + (n == 1 ? " warning" : " warnings") + " (above), and --strict makes warnings errors");
    }
    return scene;
}

// The output folder is checked before anything listens, so that an export does not fail only
// when the user has recorded a path. The current folder (the default) that cannot be written
// is only a warning: viewing needs no folder, and --output-dir names one for the exports.
void check_output_dir(const std::string& folder, bool given) {
    std::error_code error;
    const fs::file_status status = fs::status(folder, error);
    if (!fs::exists(status))
        throw OutputError("--output-dir " + printable(folder) + ": no such folder (make it first)");
    if (!fs::is_directory(status)) throw OutputError("--output-dir " + printable(folder) + ": not a folder");
    if (::access(folder.c_str(), W_OK | X_OK) == 0) return;
    const std::string why = std::strerror(errno);
    if (given) throw OutputError("--output-dir " + printable(folder) + ": cannot write there (" + why + ")");
    std::cerr << "clrender: warning: the current folder cannot be written (" << why
              << "): exports and videos will fail; --output-dir names a folder for them\n";
}

// What a video render needs of the command line beyond the exported scene, which holds the
// rest (-D values, --size, --spp, --seed).
std::vector<std::string> video_render_arguments(const Options& options) {
    std::vector<std::string> arguments;
    if (!options.device.empty()) arguments.insert(arguments.end(), {"-d", options.device});
    if (options.threads) arguments.insert(arguments.end(), {"-t", std::to_string(*options.threads)});
    if (options.double_precision) arguments.insert(arguments.end(), {"--precision", "double"});
    if (options.placeholders) arguments.push_back("--placeholders");
    // A file changed since the viewer loaded the scene may now give a warning (the video reads
    // the meshes and images again): under --strict the video is refused, as a render would be.
    if (options.strict) arguments.push_back("--strict");
    if (!options.kernel_dir.empty()) arguments.insert(arguments.end(), {"--kernel-dir", options.kernel_dir});
    return arguments;
}

int run_view(const ViewOptions& view) {
    const Options& options = view.render;
    if (options.threads) limit_cpu_threads(*options.threads);  // before any driver loads
    install_interruption_handlers();
    check_output_dir(view.output_dir, view.output_dir_given);
    const std::string text = read_scene_text(options.scene_path);
    const Scene scene = load_view_scene(options, text);
    throw_if_interrupted();
    const std::string token = make_access_token();
    RenderService renderer(scene, options);
    if (!options.quiet) std::cerr << "clrender: device " << printable(renderer.device_name()) << "\n";
    const PathExporter exporter(scene, text, options, view.output_dir);
    VideoJobs videos(video_render_arguments(options));
    throw_if_interrupted();
    serve_view({view.bind, view.port, view.open_browser}, token, scene, renderer, exporter, videos);
}

}  // namespace

int view_main(int argc, const char* const* argv) {
    const ParsedViewOptions parsed = parse_view_options(argc, argv);
    if (parsed.exit_code) return *parsed.exit_code;
    try {
        return run_view(parsed.options);
    } catch (const Interrupted& stopped) {
        // The viewer's normal end: no frame or file to speak of, as a render's message does.
        const int signal_number = stopped.code() - 128;
        std::cerr << "clrender: view stopped by "
                  << (signal_number == SIGINT ? "SIGINT (Ctrl-C)" : signal_number == SIGHUP ? "SIGHUP" : "SIGTERM") << "\n";
        return stopped.code();
    } catch (...) {
        const ExitStatus status = exit_status_for(std::current_exception());
        std::cerr << status.message << "\n";
        return status.code;
    }
}

}  // namespace clr
