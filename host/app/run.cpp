#include "app/run.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <future>
#include <iostream>
#include <sstream>
#include <system_error>
#include <nlohmann/json.hpp>

#include "app/frame_description.h"
#include "app/explain_pixel.h"
#include "app/check_summary.h"
#include "app/frame_sink.h"
#include "app/linear_outputs.h"
#include "app/opencl_frame_renderer.h"
#include "app/plan_json.h"
#include "app/reference_frame_renderer.h"
#include "app/description_check.h"
#include "app/display_server.h"
#include "app/tile_join.h"
#include "core/interruption.h"
#include "core/message_lines.h"
#include "core/printable_text.h"
#include "core/stopwatch.h"
#include "shared/clr_types.h"
#include "core/usable_cpus.h"
#include "core/worker_threads.h"
#include "render/compiled_scene.h"
#include "app/output_plan.h"
#include "app/progress.h"
#include "core/errors.h"
#include "device/device_selection.h"
#include "device/kernel_sources.h"
#include "device/driver_limits.h"
#include "device/driver_settings.h"
#include "output/atomic_file.h"
#include "output/staged_outputs.h"
#include "scene/camera_path.h"
#include "scene/image_cache.h"
#include "scene/image_loader.h"
#include "scene/scene_loader.h"

namespace clr {
namespace {

namespace fs = std::filesystem;

struct FrameRecord {
    int index = 0;
    FrameTiming timing;
};

// Everything the --stats report says.
struct RunReport {
    std::string device;
    int compute_units = 0;  // of the OpenCL device; 0 for the reference
    double load_ms = 0;
    double build_ms = 0;
    int cache_hits = 0;
    int store_hits = 0;
    std::string primary_rays;  // empty for the reference
    double render_ms = 0;
    double write_ms = 0;
    double total_ms = 0;
    std::vector<FrameRecord> frames;
    std::size_t tiles_joined = 0;  // --join
    bool image_was_finished = false;  // --resume found the one image finished: nothing written but the stats
    std::size_t frames_skipped = 0;   // frames --resume found finished
    nlohmann::json scene_objects;     // what the scene holds, by kind
};

// The scene's objects by kind, and what its meshes take on the device (each triangle's
// struct, and three corner normals where the mesh gives them).
nlohmann::json scene_objects(const Scene& scene) {
    return {{"spheres", scene.spheres.size()},
            {"billboards", scene.billboards.size()},
            {"impostors", scene.impostors.size()},
            {"meshes", scene.meshes.size()},
            {"triangles", scene.triangles.size()},
            {"planes", scene.planes.size()},
            {"lights", scene.lights.size()},
            {"triangle_device_bytes", triangle_device_bytes(scene)}};
}

std::string stats_text(const RunReport& report) {
    nlohmann::json frames = nlohmann::json::array();
    for (const FrameRecord& frame : report.frames)
        frames.push_back({{"index", frame.index}, {"kernel_ms", frame.timing.kernel_ms}, {"total_ms", frame.timing.total_ms}});
    nlohmann::json stats = {
        {"device", report.device},
        {"compute_units", report.compute_units},
        {"build_ms", report.build_ms},
        {"cache_hits", report.cache_hits},  // programs built from clrender's program cache
        {"store_hits", report.store_hits},  // programs built from the store installed with clrender
        {"primary_rays", report.primary_rays.empty() ? nlohmann::json() : nlohmann::json(report.primary_rays)},
        {"scene", report.scene_objects},
        {"stages_ms", {{"load", report.load_ms}, {"build", report.build_ms}, {"render", report.render_ms},
                       {"write", report.write_ms}, {"total", report.total_ms}}},
        {"frames", frames},
    };
    // A driver's device name is not guaranteed to be UTF-8: invalid bytes become U+FFFD, so
    // the report is still JSON instead of the run failing for it.
    return stats.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

// Written under a temporary name; renamed into place with a still's image (staged_outputs.h).
std::unique_ptr<AtomicFile> write_stats(const std::string& path, const RunReport& report) {
    const std::string text = stats_text(report);
    auto file = std::make_unique<AtomicFile>(path);
    file->write(text.data(), text.size());
    file->complete();
    return file;
}

// --stats -: the report on standard output. A closed pipe or a full disk behind standard
// output is an output error.
void print_stats(const RunReport& report) {
    const std::string text = stats_text(report);
    if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size() || std::fflush(stdout) != 0)
        throw OutputError(std::string("--stats -: cannot write the report to standard output: ") + std::strerror(errno));
}

Scene load(const Options& options) {
    LoadOptions load_options;
    load_options.placeholder_images = options.placeholders;
    load_options.width_override = options.width;
    load_options.height_override = options.height;
    load_options.samples_override = options.samples_per_pixel;
    load_options.seed_override = options.seed;
    load_options.overrides = options.overrides;
    // --check and --plan decode the images too: a damaged one fails them as it fails a render,
    // and the scene's digest (in each frame's description, which --resume and --assemble
    // compare) is the render's.
    load_options.count_frames_only = options.print_frame_count;  // neither images nor size
    Scene scene = load_scene(options.scene_path, load_options);
    for (const std::string& warning : scene.warnings)
        std::cerr << message_line("warning", printable(scene.path + ": " + warning));
    // --strict: the warnings above are the problems; this line says why they stop the run.
    if (options.strict && !scene.warnings.empty()) {
        const std::size_t n = scene.warning_count;
        throw SceneError(printable(scene.path), "",
                         std::to_string(n) + (n == 1 ? " warning" : " warnings") + " (above), and --strict makes warnings errors");
    }
    return scene;
}

// The OpenCL devices, listed on another thread while the scene loads: the driver's start
// (PoCL loads LLVM) is a large part of a warm run, and decoding the scene's images more
// (docs/benchmarks.md, Figures behind design choices).
using DeviceList = std::future<std::vector<DeviceEntry>>;

// A machine that cannot start the thread lists them when they are needed instead.
DeviceList list_devices_meanwhile() {
    try {
        return std::async(std::launch::async, list_devices);
    } catch (const std::system_error&) {
        return std::async(std::launch::deferred, list_devices);
    }
}

// `part_done` gets the fraction of each frame rendered, band by band (or row by row);
// `linear_frames`: frames also carry their linear colours (Image::linear).
// `still`: the run renders one frame (RendererOptions::general_stand_in).
std::unique_ptr<FrameRenderer> make_renderer(const Options& options, const Scene& scene, DeviceList& devices,
                                             std::function<void(double)> part_done, bool linear_frames, bool still) {
    // A long frame stops within a band (or a reference row) of a signal, not at its end.
    if (options.reference)
        return make_reference_frame_renderer(scene, throw_if_interrupted, options.crop, part_done, linear_frames);
    RendererOptions renderer_options;
    renderer_options.float_output = linear_frames;
    renderer_options.between_bands = throw_if_interrupted;
    renderer_options.band_done = std::move(part_done);
    renderer_options.crop = options.crop;
    renderer_options.kernel_dir = options.kernel_dir;
    renderer_options.double_precision = options.double_precision;
    renderer_options.general_stand_in = still;
    // run() lists the devices while the scene loads whenever it renders with OpenCL.
    return make_opencl_frame_renderer(scene, devices.get(), options.device, renderer_options, options.threads);
}

// The size of the frames this run writes: the scene's, or the crop's (docs/command-line.md, Crop).
struct FrameSize {
    int width = 0, height = 0;
};

FrameSize frame_size(const Options& options, const Scene& scene) {
    if (options.crop) return {options.crop->width(), options.crop->height()};
    return {scene.width, scene.height};
}

// A crop must lie inside the frame; the frame's size is known once the scene (and --size) is.
void check_crop(const Options& options, const Scene& scene) {
    if (options.crop && !options.crop->inside(scene.width, scene.height))
        throw UsageError("--crop " + format_pixel_rect(*options.crop) + " reaches outside the " +
                         std::to_string(scene.width) + "x" + std::to_string(scene.height) +
                         " image (x1 at most the width, y1 at most the height)");
}

// A frame written earlier (--assemble, --resume), checked to be of the scene's size.
Image read_frame(const OutputPlan& plan, const FrameSize& size, int frame) {
    std::string path = plan.image_path(frame);
    std::shared_ptr<const Image> image;
    try {
        image = load_image(path);
    } catch (const ImageError& error) {
        throw SceneError(path, "", std::string("cannot read frame ") + std::to_string(frame) + ": " + error.what());
    }
    if (image->width != size.width || image->height != size.height)
        throw SceneError(path, "", "frame " + std::to_string(frame) + " is " + std::to_string(image->width) + "x" +
                                       std::to_string(image->height) + ", the scene renders " +
                                       std::to_string(size.width) + "x" + std::to_string(size.height));
    return *image;
}

// Renders the planned frames one after another; the sink writes and encodes each while the
// next one renders. The program and scene buffers are made once, before the first frame.
void render_frames(const Options& options, const Scene& scene, const OutputPlan& plan, RunReport& report,
                   DeviceList& devices, StagedOutputs& staged, Progress& progress) {
    Progress* shown = nullptr;  // the progress of the frames, once they start
    std::unique_ptr<FrameRenderer> renderer = make_renderer(
        options, scene, devices,
        [&shown](double fraction) {
            if (shown) shown->frame_part_done(fraction);
        },
        needs_linear_frames(options, plan), plan.frames.size() == 1);
    report.device = renderer->device_name();
    report.compute_units = renderer->compute_units();
    report.build_ms = renderer->build_ms();
    report.cache_hits = renderer->cache_hits();
    report.store_hits = renderer->store_hits();
    report.primary_rays = renderer->primary_rays();
    if (!options.quiet)
        std::cerr << message_line("info", "device " + printable(report.device) +
                                              (report.compute_units > 0 ? " (compute units: " + std::to_string(report.compute_units) + ")" : ""));
    make_missing_folders(plan);  // the device is ready: nothing refuses the run before it renders

    const FrameSize size = frame_size(options, scene);
    FrameSink sink(plan, size.width, size.height, scene.animation.fps, options.quality, staged,
                   [&scene, &options](int frame) { return describe_frame(scene, frame, options); });
    DisplayStream display(options.display_server, scene.name, size.width, size.height);  // --display-server
    shown = &progress;
    // Frames under their final names: those --resume found, and those the sink has renamed.
    auto in_place = [&] { return static_cast<int>(report.frames_skipped) + sink.frames_in_place(); };
    const Stopwatch render_time;
    for (int frame : plan.frames) {
        throw_if_interrupted();
        progress.frame_started(frame);
        if (options.resume && plan.frame_on_disk(frame)) {
            if (!plan.video_path.empty()) sink.push(frame, read_frame(plan, size, frame), true);
            ++report.frames_skipped;
            progress.frame_done(in_place());
            continue;
        }
        FrameRecord record{frame, {}};
        if (std::optional<Image> written = sink.take_finished()) renderer->recycle(std::move(*written));
        Image image = renderer->render(camera_at_frame(scene, frame), frame, &record.timing);
        report.frames.push_back(record);
        display.show(image);
        prepare_linear_frame(image, options, plan, scene);
        sink.push(frame, std::move(image));
        progress.frame_done(in_place());
    }
    throw_if_interrupted();
    sink.finish();
    progress.finish();
    report.render_ms = render_time.elapsed_ms();
    report.write_ms = sink.write_ms();
    renderer->store_built_programs();  // the outputs are complete: the next run starts faster
}

// --assemble: encodes frames rendered earlier (by this or other processes) into the video.
void assemble_frames(const Options& options, const Scene& scene, const OutputPlan& plan, RunReport& report,
                     StagedOutputs& staged, Progress& progress) {
    report.device = "none (assembling frames)";
    make_missing_folders(plan);
    const FrameSize size = frame_size(options, scene);
    FrameSink sink(plan, size.width, size.height, scene.animation.fps, options.quality, staged);
    for (int frame : plan.frames) {
        throw_if_interrupted();
        progress.frame_started(frame);
        check_frame_description(plan.image_path(frame), frame, describe_frame(scene, frame, options));
        sink.push(frame, read_frame(plan, size, frame), true);
        progress.frame_done(0);  // the video is in place only at the end
    }
    sink.finish();
    progress.finish();
    report.write_ms = sink.write_ms();
}

// --check reaches every refusal of a render that needs no device, including those of the files
// the run reads back instead of rendering: --join's tiles, --assemble's frames and the frames
// that --resume reads back into a video.
void check_read_back_files(const Options& options, const Scene& scene, const OutputPlan& plan) {
    if (!options.join.empty()) {
        join_tiles(options, scene, plan.frames.front());
        return;
    }
    const FrameSize size = frame_size(options, scene);
    for (int frame : plan.frames) {
        throw_if_interrupted();
        if (plan.assemble) {
            check_frame_description(plan.image_path(frame), frame, describe_frame(scene, frame, options));
            read_frame(plan, size, frame);
        } else if (options.resume && plan.frame_on_disk(frame) && !plan.video_path.empty()) {
            read_frame(plan, size, frame);
        }
    }
}

// --kernel-dir's sources are read and their includes resolved before a device builds them: a
// missing file is found without one.
void check_kernel_sources(const Options& options, const OutputPlan& plan) {
    const bool renders = options.join.empty() && !plan.assemble && !(options.resume && plan.only_image_finished());
    if (!options.kernel_dir.empty() && !options.reference && renders)
        assemble_program_source(kRenderTilesProgram.entry, options.kernel_dir);
}

// A stream buffer that takes everything and keeps nothing: --check runs the explainer for its
// checks, and its text (which can be large) is not wanted.
struct DiscardingBuffer : std::streambuf {
    int overflow(int c) override { return traits_type::not_eof(c); }
    std::streamsize xsputn(const char*, std::streamsize count) override { return count; }
};

// Prints --check's summary or --plan's JSON on standard output, checking that it got there.
int print_check_result(const std::string& text) {
    std::cout << text << std::flush;
    if (!std::cout) throw OutputError("standard output: cannot write the result (disk full or pipe closed?)");
    return kExitOk;
}

// What the frames of this run were: "48 frames", or with --resume "2 frames rendered, 46 already
// finished (--resume)", so that a resumed run does not claim to have written what it skipped.
std::string frames_text(const OutputPlan& plan, const RunReport& report) {
    const std::size_t skipped = report.frames_skipped;
    if (skipped == 0) return std::to_string(plan.frames.size()) + " frames";
    const std::size_t rendered = plan.frames.size() - skipped;
    return std::to_string(rendered) + (rendered == 1 ? " frame" : " frames") + " rendered, " + std::to_string(skipped) +
           " already finished (--resume)";
}

// "wrote anim_0000.png ... anim_0047.png (48 frames, no video: ...)" for the default frames.
void print_default_frames(const OutputPlan& plan, const RunReport& report) {
    std::string line = "wrote " + printable(plan.image_path(plan.frames.front()));
    if (plan.frames.size() > 1)
        line += " ... " + printable(plan.image_path(plan.frames.back())) + " (" + frames_text(plan, report) + ")";
    std::cerr << message_line("info", line + "; no video for a --frames selection (--video makes one)");
}

// The "wrote" line of the image or frames; none for an image that --resume found finished
// (run() says that, also with -q).
void print_images_written(const OutputPlan& plan, const RunReport& report) {
    if (report.image_was_finished) return;
    if (report.tiles_joined > 0)
        std::cerr << message_line("info", "wrote " + printable(plan.image_path(plan.frames.front())) + " (joined from " +
                                              std::to_string(report.tiles_joined) + " tiles)");
    else if (plan.default_frame_digits > 0)
        print_default_frames(plan, report);
    else if (!plan.image_target.empty() && !plan.assemble)
        std::cerr << message_line(
            "info", "wrote " +
                        printable(plan.frames.size() == 1 ? plan.image_path(plan.frames.front()) : plan.image_target) +
                        (plan.frames.size() > 1 ? " (" + frames_text(plan, report) + ")" : ""));
}

void print_summary(const OutputPlan& plan, const RunReport& report) {
    print_images_written(plan, report);
    if (!plan.video_path.empty())
        std::cerr << message_line("info", "wrote " + printable(plan.video_path) + " (" +
                                              std::to_string(plan.frames.size()) + " frames)");
    double kernel_ms = 0;
    for (const FrameRecord& frame : report.frames) kernel_ms += frame.timing.kernel_ms;
    std::ostringstream line;
    line << report.frames.size() << " frame(s), kernel " << kernel_ms << " ms, build " << report.build_ms
         << " ms, total " << report.total_ms << " ms";
    std::cerr << message_line("info", line.str());
}

}  // namespace

int run(const Options& options) {
    prepare_for_driver_limits();  // before any driver loads (device/driver_limits.h)
    if (options.threads) limit_cpu_threads(*options.threads);  // before any driver loads
    if (options.list_devices) {
        std::vector<DeviceEntry> devices = list_devices();
        // With -d: only the device a render would pick, or the render's error (exit 3).
        if (!options.device.empty()) devices = {select_device(devices, options.device)};
        return print_check_result(format_device_list(devices));
    }
    install_interruption_handlers();  // before anything is read or written (caches included)
    const Stopwatch run_time;
    RunReport report;
    DeviceList devices;
    // --check and --plan never open an OpenCL platform: they must work where there is none.
    // --join renders nothing; --resume of a finished image neither: it lists them when it renders.
    if (!options.reference && !options.assemble && !options.print_frame_count && !options.check && !options.plan &&
        options.join.empty()) {
        // What would wait for the driver's dlopen on the listing thread, done before it starts:
        // the image loader's threads (core/worker_threads.h) and the image cache's first key.
        if (!options.resume) {
            WorkerThreads::shared().start(static_cast<std::size_t>(usable_cpu_count()) - 1);
            ImageCache::prepare_keys();
        }
        devices = options.resume ? std::async(std::launch::deferred, list_devices) : list_devices_meanwhile();
    }
    Scene scene = load(options);
    report.load_ms = run_time.elapsed_ms();
    report.scene_objects = scene_objects(scene);
    if (options.print_frame_count) {
        std::cout << animation_frame_count(scene) << "\n";
        return kExitOk;
    }
    check_crop(options, scene);
    throw_if_interrupted();
    if (options.explain_pixel && options.check) {  // the explainer's own checks, without the kernels
        DiscardingBuffer nowhere;
        std::ostream discarded(&nowhere);
        explain_pixel(options, scene, {}, discarded);
        return print_check_result(check_summary(scene, options.double_precision));
    }
    if (options.explain_pixel) {  // prints, writes no files (docs/explain-pixel.md)
        KernelRendererFactory kernel_renderer;
        // The kernels render only the explained pixel: a 1x1 crop has the full frame's bytes
        // there (docs/command-line.md, Crop), at a fraction of a full frame's cost.
        Options one_pixel = options;
        one_pixel.crop = PixelRect{options.explain_pixel->x, options.explain_pixel->x + 1, options.explain_pixel->y,
                                   options.explain_pixel->y + 1};
        if (!options.reference)
            kernel_renderer = [&] { return make_renderer(one_pixel, scene, devices, {}, false, true); };
        explain_pixel(options, scene, kernel_renderer, std::cout);  // streamed, bounded, checked
        return kExitOk;
    }
    OutputPlan plan = plan_outputs(options, scene);  // every usage and encoder check, before rendering
    check_linear_outputs(options, plan);
    for (const std::string& warning : plan.warnings) std::cerr << message_line("warning", printable(warning));
    throw_if_interrupted();
    if (options.check || options.plan) check_kernel_sources(options, plan);
    // --plan does not read the files the run reads back: a farm plans the run before they exist.
    if (options.plan) return print_check_result(plan_json(options, scene, plan));
    if (options.check) {
        check_read_back_files(options, scene, plan);
        return print_check_result(check_summary(scene, options.double_precision));
    }

    // A still's image or an animation's video, and the stats, are renamed into place together,
    // once all are written: a failure in any leaves the earlier files as they were. Frames of
    // a pattern are in place already (docs/animation.md).
    StagedOutputs staged;
    Progress progress(static_cast<int>(plan.frames.size()), progress_style_named(options.progress), options.quiet);
    bool frames_progress = false;  // the progress reports this run's frames (not joined tiles, nothing to render)
    if (!options.join.empty()) {
        report.device = "none (joining tiles)";
        staged.add(write_joined_image(options, scene, plan));
        report.tiles_joined = options.join.size();
    } else if (plan.assemble) {
        assemble_frames(options, scene, plan, report, staged, progress);
        frames_progress = true;
    } else if (options.resume && plan.only_image_finished()) {  // a requeued farm task, say
        report.device = "none (nothing to render)";
        report.image_was_finished = true;
    } else {
        render_frames(options, scene, plan, report, devices, staged, progress);
        frames_progress = true;
    }
    report.total_ms = run_time.elapsed_ms();
    if (!plan.stats_path.empty()) staged.add(write_stats(plan.stats_path, report));
    throw_if_interrupted();
    // --stats -: printed before the renames, so that a report that cannot be written leaves
    // the earlier files as they were, as a --stats file that cannot be written does.
    if (plan.stats_to_standard_output) print_stats(report);
    staged.commit_all();
    if (frames_progress) progress.all_in_place();  // only now is every file under its name
    if (report.image_was_finished)  // also with -q: the farm's log shows why the task did nothing
        std::cerr << message_line("info", printable(plan.image_path(plan.frames.front())) +
                                              " is finished (--resume); nothing to render");
    if (!options.quiet) print_summary(plan, report);
    return kExitOk;
}

Scene load_scene_for_run(const Options& options) { return load(options); }

Image render_one_frame(const Options& options, const Scene& scene, int frame) {
    check_crop(options, scene);
    DeviceList devices;
    if (!options.reference) devices = std::async(std::launch::deferred, list_devices);
    std::unique_ptr<FrameRenderer> renderer = make_renderer(options, scene, devices, {}, false, true);
    Image image = renderer->render(camera_at_frame(scene, frame), frame, nullptr);
    renderer->store_built_programs();
    return image;
}

}  // namespace clr
