// clrender_bench: clrender and an Embree peer side by side on the same generated scenes,
// in one process, so that their ratio holds even on a noisy machine (docs/benchmarks.md,
// How to read the table).
//
//   clrender_bench [--size 1920x1080] [--repeat 5] [--device SEL] [--scenes a,b] [--json PATH]
//                  [--images DIR]
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "bench/bench_program.h"
#include "bench/bench_report.h"
#include "bench/bench_scenes.h"
#include "bench/bench_stats.h"
#include "bench/clrender_side.h"
#include "bench/triangle_memory.h"
#include "core/errors.h"
#include "core/memory_budget.h"
#include "core/stopwatch.h"
#include "device/device_selection.h"
#include "output/image_writer.h"
#include "render/frame_camera.h"

#if CLRENDER_BENCH_HAVE_EMBREE
#include "bench/embree_peer.h"
#endif

namespace clr::bench {
namespace {

struct Options {
    RunSettings settings;
    std::string device;
    std::vector<std::string> scenes;  // empty: all
    std::string json_path;
    std::string images_dir;
    std::optional<bool> per_pixel;  // --per-pixel, --screen-tiles; unset: as the device prefers
    std::optional<bool> packets_walk_bvh;  // --bvh-packets, --tile-lists; unset: as the scene prefers
    std::string kernel_dir;                // --kernel-dir; empty: the embedded kernels
};

void parse_size(const std::string& text, RunSettings& settings) {
    char x = 0;
    std::istringstream in(text);
    if (!(in >> settings.width >> x >> settings.height) || x != 'x' || settings.width <= 0 || settings.height <= 0)
        throw UsageError("--size wants WIDTHxHEIGHT, e.g. 1920x1080, not '" + text + "'");
}

// The options, or nothing when CLI11 has handled the command line (--help, an error) and
// the process should end with `exit_code`.
std::optional<Options> parse_options(int argc, char** argv, int& exit_code) {
    Options options;
    std::string size = "1920x1080";
    CLI::App app{"clrender and Embree side by side: primary rays per second on generated scenes"};
    app.add_option("--size", size, "image size WIDTHxHEIGHT")->capture_default_str();
    app.add_option("--repeat", options.settings.repeat, "timed frames per scene and side (the median is reported)")
        ->capture_default_str()
        ->check(CLI::PositiveNumber);
    app.add_option("--device", options.device, "OpenCL device: index, platform:device or name (default: first CPU)");
    app.add_option("--scenes", options.scenes, "scenes to run, comma-separated (default: all)")->delimiter(',');
    auto* per_pixel = app.add_flag_callback(
        "--per-pixel", [&] { options.per_pixel = true; },
        "clrender's primary rays one work-item a pixel through the BVH (a GPU's default; docs/benchmarks.md, A GPU)");
    app.add_flag_callback("--screen-tiles", [&] { options.per_pixel = false; },
                          "clrender's primary rays in screen tiles of 16-ray packets (a CPU's default)")
        ->excludes(per_pixel);
    auto* bvh_packets = app.add_flag_callback(
        "--bvh-packets", [&] { options.packets_walk_bvh = true; },
        "clrender's 16-ray packets walk the BVH instead of screen-tile lists (the default from 200,000 triangles)");
    bvh_packets->excludes(per_pixel);
    app.add_flag_callback("--tile-lists", [&] { options.packets_walk_bvh = false; },
                          "clrender's 16-ray packets search lists binned into screen tiles (the default below)")
        ->excludes(per_pixel)
        ->excludes(bvh_packets);
    app.add_option("--json", options.json_path, "also write the results as JSON to this file");
    app.add_option("--images", options.images_dir, "write clrender's image of each scene as PNG into this folder");
    app.add_option("--kernel-dir", options.kernel_dir,
                   "read clrender's OpenCL sources from this folder (kernel development: one binary, two kernels)");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        exit_code = app.exit(error);
        return std::nullopt;
    }
    parse_size(size, options.settings);
#if CLRENDER_BENCH_HAVE_EMBREE
    options.settings.with_embree = true;
#endif
    return options;
}

// What a mesh scene's run took at its peak, clrender's and Embree's copies together: 10.97 GB
// for "100x100k triangles" (9.9M), about 1,100 bytes a triangle; a margin on top.
constexpr std::uint64_t kPeakBytesPerTriangle = 1200;

// The scenes to run: those named, else every scene whose triangles fit half of this machine's
// memory (the others are named on standard error, and run when named).
std::vector<BenchSceneSpec> chosen_specs(const Options& options) {
    if (options.scenes.empty()) {
        std::vector<BenchSceneSpec> specs;
        for (const BenchSceneSpec& spec : bench_scene_specs()) {
            const std::uint64_t needed = static_cast<std::uint64_t>(spec.triangles()) * kPeakBytesPerTriangle;
            if (needed <= default_memory_budget())
                specs.push_back(spec);
            else
                std::cerr << "bench: " << spec.name << ": left out: it takes about " << gib_text(needed)
                          << ", more than half of this machine's memory (run it with --scenes)" << std::endl;
        }
        return specs;
    }
    std::vector<BenchSceneSpec> specs;
    for (const std::string& name : options.scenes) {
        try {
            specs.push_back(find_bench_scene(name));
        } catch (const std::invalid_argument& error) {
            throw UsageError(error.what());
        }
    }
    return specs;
}

std::string file_name_of(const std::string& scene_name) {
    std::string name;
    for (char c : scene_name) name += std::isalnum(static_cast<unsigned char>(c)) ? c : '-';
    return name;
}

// Fractions of pixels that show an object, and that differ between the two id maps.
void compare_ids(const std::vector<std::uint32_t>& clr, const std::vector<std::uint32_t>* embree, SceneRow& row) {
    std::size_t covered = 0, differing = 0;
    for (std::size_t i = 0; i < clr.size(); ++i) {
        covered += clr[i] != kBackgroundId;
        if (embree) differing += clr[i] != (*embree)[i];
    }
    row.covered = static_cast<double>(covered) / clr.size();
    row.differing = static_cast<double>(differing) / clr.size();
}

// For a lit scene, whose colours no longer encode ids: the fraction of pixels that show an
// object (by the peer's ids when there is one, else by clrender's colour against the black
// background) and of pixels whose colours differ by more than kLitTolerance in a channel.
void compare_lit(const Image& clr, const std::vector<std::uint32_t>* ids, const std::vector<std::uint8_t>* rgb,
                 SceneRow& row) {
    std::size_t pixels = static_cast<std::size_t>(clr.width) * clr.height, covered = 0, differing = 0;
    for (std::size_t i = 0; i < pixels; ++i) {
        const std::uint8_t* c = &clr.rgba[4 * i];
        covered += ids ? (*ids)[i] != kBackgroundId : (c[0] | c[1] | c[2]) != 0;
        if (!rgb) continue;
        bool differs = false;
        for (int channel = 0; channel < 3; ++channel)
            differs |= std::abs(int{c[channel]} - int{(*rgb)[3 * i + channel]}) > kLitTolerance;
        differing += differs;
    }
    row.covered = static_cast<double>(covered) / pixels;
    row.differing = static_cast<double>(differing) / pixels;
}

// A side's warm-up frame is kept as its only timed frame when slower than kSlowFrameMs.
bool keep_if_slow(double ms, std::vector<double>& samples) {
    if (ms <= kSlowFrameMs) return false;
    samples.push_back(ms);
    return true;
}

// Timed frames come in blocks of this many per side, each block after one untimed frame.
// Alternating single frames let each side's worker threads, still spinning for a few ms after
// its own frame (Embree's task scheduler does), take a core from the other side's next frame:
// clrender's 16+16 rate then came out either ~430 or ~230 Mrays/s from run to run.
constexpr int kBlockFrames = 3;
// clrender's untimed frames before its block last at least this long: one frame of 3 ms
// (the small scenes) ended while Embree's threads still spun, and its timed frames ran on
// one core of two, twice as slow, in some runs and not in others (docs/benchmarks.md,
// Packet fixed costs). Embree's own block still follows clrender's frames at once.
constexpr double kClrenderSettleMs = 30;

// Both sides warm up, then render their timed frames in alternating blocks, so that whatever
// else the machine does meanwhile slows both alike and their ratio holds, while neither side's
// threads run into the other's frames.
SceneRow run_scene(DeviceContext& device, const BenchSceneSpec& spec, const Options& options) {
    const RunSettings& settings = options.settings;
    Scene scene = make_bench_scene(spec, settings.width, settings.height);
    const CameraKey& key = scene.camera_path.front();
    // Embree's copy of the scene keeps scene coordinates (origin (0, 0, 0)).
    ClrCamera camera = make_frame_camera(key.eye, key.lookat, scene.up, scene.fov_degrees, settings.width, settings.height).device();
    SceneRow row;
    row.spec = spec;
    if (!scene.triangles.empty()) {
        TriangleMemory memory = triangle_memory(scene);
        row.triangles = memory.triangles;
        row.bytes_per_triangle = memory.per_triangle();
    }

    std::cerr << "bench: " << spec.name << ": setting up" << std::endl;
    ClrenderSide clr(device, scene, options.per_pixel, options.packets_walk_bvh, options.kernel_dir);
    row.clr_setup_ms = clr.setup_ms();
    ClrenderFrame warmup = clr.render_frame();
    bool clr_done = keep_if_slow(warmup.wall_ms, row.clr_wall_ms);
    if (clr_done) row.clr_kernel_ms.push_back(warmup.kernel_ms);
#if CLRENDER_BENCH_HAVE_EMBREE
    EmbreePeer embree(scene, camera);
    row.embree_build_ms = embree.build_ms();
    bool embree_done = keep_if_slow(embree.trace_frame(), row.embree_wall_ms);
#endif

    std::cerr << "bench: " << spec.name << ": timing" << std::endl;
    for (int timed = 0; timed < settings.repeat; timed += kBlockFrames) {
        int block = std::min(kBlockFrames, settings.repeat - timed);
        if (!clr_done) {
            // Untimed: the other side's threads may still be about.
            for (const Stopwatch settle; settle.elapsed_ms() < kClrenderSettleMs;) clr.render_frame();
            for (int i = 0; i < block; ++i) {
                ClrenderFrame frame = clr.render_frame();
                row.clr_kernel_ms.push_back(frame.kernel_ms);
                row.clr_wall_ms.push_back(frame.wall_ms);
            }
        }
#if CLRENDER_BENCH_HAVE_EMBREE
        if (!embree_done) {
            embree.trace_frame();
            for (int i = 0; i < block; ++i) row.embree_wall_ms.push_back(embree.trace_frame());
        }
#endif
    }

    if (!options.images_dir.empty())
        write_image(options.images_dir + "/" + file_name_of(spec.name) + ".png", clr.image());
#if CLRENDER_BENCH_HAVE_EMBREE
    if (spec.lit())
        compare_lit(clr.image(), &embree.ids(), &embree.rgb(), row);
    else
        compare_ids(object_ids(clr.image()), &embree.ids(), row);
#else
    if (spec.lit())
        compare_lit(clr.image(), nullptr, nullptr, row);
    else
        compare_ids(object_ids(clr.image()), nullptr, row);
#endif
    return row;
}

int run(const Options& options) {
    std::vector<BenchSceneSpec> specs = chosen_specs(options);
    DeviceEntry entry = select_device(list_devices(), options.device);
    DeviceContext device(entry);
    print_machine(std::cout, entry);
    std::vector<SceneRow> rows;
    for (const BenchSceneSpec& spec : specs) rows.push_back(run_scene(device, spec, options));
    print_table(std::cout, rows, options.settings);
    if (!options.json_path.empty()) write_json(options.json_path, rows, entry, options.settings);
    return kExitOk;
}

}  // namespace
}  // namespace clr::bench

int main(int argc, char** argv) {
    return clr::bench::run_bench_program("clrender_bench", argc, argv, clr::bench::parse_options, clr::bench::run);
}
