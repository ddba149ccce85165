#include "app/run.h"

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>

#include "core/errors.h"
#include "device/device_context.h"
#include "device/device_selection.h"
#include "output/atomic_file.h"
#include "output/image_writer.h"
#include "reference/reference.h"
#include "render/device_camera.h"
#include "render/renderer.h"
#include "scene/scene_loader.h"

namespace clr {
namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

struct RunReport {
    std::string device;
    double build_ms = 0;
    int cache_hits = 0;
    double load_ms = 0;
    double write_ms = 0;
    FrameTiming frame;
};

void write_stats(const std::string& path, const RunReport& report) {
    nlohmann::json stats = {
        {"device", report.device},
        {"build_ms", report.build_ms},
        {"cache_hits", report.cache_hits},
        {"load_ms", report.load_ms},
        {"write_ms", report.write_ms},
        {"frames", nlohmann::json::array({{{"index", 0},
                                           {"kernel_ms", report.frame.kernel_ms},
                                           {"total_ms", report.frame.total_ms}}})},
    };
    std::string text = stats.dump(2) + "\n";
    AtomicFile file(path);
    file.write(text.data(), text.size());
    file.commit();
}

Scene load(const Options& options) {
    LoadOptions load_options;
    load_options.placeholder_images = options.placeholders;
    load_options.width_override = options.width;
    load_options.height_override = options.height;
    Scene scene = load_scene(options.scene_path, load_options);
    for (const std::string& warning : scene.warnings) std::cerr << "clrender: warning: " << scene.path << ": " << warning << "\n";
    return scene;
}

Image render_with_opencl(const Options& options, const Scene& scene, RunReport& report) {
    DeviceEntry entry = select_device(list_devices(), options.device);
    report.device = entry.device_name;
    if (!options.quiet) std::cerr << "clrender: device " << entry.device_name << "\n";
    DeviceContext device(entry);
    RendererOptions renderer_options;
    renderer_options.kernel_dir = options.kernel_dir;
    Renderer renderer(device, scene, renderer_options);
    report.build_ms = renderer.build_ms();
    const CameraKey& key = scene.camera_path.front();
    ClrCamera camera = make_device_camera(key.eye, key.lookat, scene.up, scene.fov_degrees, scene.width, scene.height);
    return renderer.render_frame(camera, &report.frame);
}

Image render_with_reference(const Scene& scene, RunReport& report) {
    report.device = "host reference (double precision)";
    auto start = Clock::now();
    const CameraKey& key = scene.camera_path.front();
    Image image = reference::render(
        scene, reference::make_camera(key.eye, key.lookat, scene.up, scene.fov_degrees, scene.width, scene.height));
    report.frame.kernel_ms = report.frame.total_ms = ms_since(start);
    return image;
}

}  // namespace

int run(const Options& options) {
    if (options.list_devices) {
        std::cout << format_device_list(list_devices());
        return kExitOk;
    }
    auto start = Clock::now();
    RunReport report;
    Scene scene = load(options);
    report.load_ms = ms_since(start);

    std::string output = options.output_path.empty() ? scene.name + ".png" : options.output_path;
    image_format_for(output);  // an unsupported extension fails before any rendering
    if (scene.is_animated() && !options.quiet)
        std::cerr << "clrender: warning: " << scene.path << ": the camera path has " << scene.camera_path.size()
                  << " keys; rendering the first one as a still\n";

    Image image = options.reference ? render_with_reference(scene, report) : render_with_opencl(options, scene, report);

    auto write_start = Clock::now();
    write_image(output, image);
    report.write_ms = ms_since(write_start);
    if (!options.stats_path.empty()) write_stats(options.stats_path, report);
    if (!options.quiet)
        std::cerr << "clrender: wrote " << output << " (" << image.width << "x" << image.height << ", kernel "
                  << report.frame.kernel_ms << " ms, total " << ms_since(start) << " ms)\n";
    return kExitOk;
}

}  // namespace clr
