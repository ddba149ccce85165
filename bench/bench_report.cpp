#include "bench/bench_report.h"

#include <cstdio>
#include <fstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "bench/bench_stats.h"
#include "core/errors.h"

#if CLRENDER_BENCH_HAVE_EMBREE
#include "bench/embree_peer.h"
#endif

namespace clr::bench {
namespace {

std::string cpu_model() {
    std::ifstream in("/proc/cpuinfo");
    for (std::string line; std::getline(in, line);)
        if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
    return "unknown CPU";
}

nlohmann::json machine_json(const DeviceEntry& device) {
    return {
        {"cpu", cpu_model()},
        {"hardware_threads", std::thread::hardware_concurrency()},
        {"opencl_platform", device.platform_name},
        {"opencl_device", device.device_name},
        {"opencl_version", device.version},
        {"opencl_driver", device.device.getInfo<CL_DRIVER_VERSION>()},
#if CLRENDER_BENCH_HAVE_EMBREE
        {"embree", embree_version()},
#else
        {"embree", nullptr},
#endif
    };
}

std::string fixed(double value, int decimals) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    return text;
}

// Three significant digits for rates from 0.01 to 1000 Mrays/s.
std::string rate(double mrays) { return fixed(mrays, mrays >= 100 ? 0 : mrays >= 10 ? 1 : mrays >= 1 ? 2 : 3); }

// A row's medians and rates. The ratio compares wall times: what a user waits for.
struct Figures {
    double clr_kernel_ms = 0, clr_wall_ms = 0, embree_ms = 0;
    double clr_kernel_mrays = 0, clr_wall_mrays = 0, embree_mrays = 0;
    bool single_frame = false;  // a side timed only its slow warm-up frame
};

Figures figures_of(const SceneRow& row, const RunSettings& settings) {
    int w = settings.width, h = settings.height;
    Figures f;
    f.clr_kernel_ms = median(row.clr_kernel_ms);
    f.clr_wall_ms = median(row.clr_wall_ms);
    f.clr_kernel_mrays = mrays_per_s(w, h, f.clr_kernel_ms);
    f.clr_wall_mrays = mrays_per_s(w, h, f.clr_wall_ms);
    f.single_frame = settings.repeat > 1 && row.clr_wall_ms.size() == 1;
    if (settings.with_embree) {
        f.embree_ms = median(row.embree_wall_ms);
        f.embree_mrays = mrays_per_s(w, h, f.embree_ms);
        f.single_frame |= settings.repeat > 1 && row.embree_wall_ms.size() == 1;
    }
    return f;
}

nlohmann::json row_json(const SceneRow& row, const RunSettings& settings) {
    Figures f = figures_of(row, settings);
    nlohmann::json out = {
        {"scene", row.spec.name},
        {"spheres", row.spec.spheres},
        {"billboards", row.spec.billboards},
        {"impostors", row.spec.impostors},
        {"triangles", row.triangles},
        {"bytes_per_triangle", row.triangles ? nlohmann::json(row.bytes_per_triangle) : nlohmann::json(nullptr)},
        {"lit", row.spec.lit()},
        {"covered_pixels", row.covered},
        {"clrender",
         {{"setup_ms", row.clr_setup_ms},
          {"kernel_ms", f.clr_kernel_ms},
          {"wall_ms", f.clr_wall_ms},
          {"frames", row.clr_wall_ms.size()},
          {"mrays_kernel", f.clr_kernel_mrays},
          {"mrays_wall", f.clr_wall_mrays}}},
        {"embree", nullptr},
    };
    if (settings.with_embree) {
        out["embree"] = {{"build_ms", row.embree_build_ms},
                         {"wall_ms", f.embree_ms},
                         {"frames", row.embree_wall_ms.size()},
                         {"mrays", f.embree_mrays}};
        out["ratio_wall"] = f.clr_wall_mrays / f.embree_mrays;
        out["ratio_kernel"] = f.clr_kernel_mrays / f.embree_mrays;
        out["differing_pixels"] = row.differing;
    }
    return out;
}

}  // namespace

void print_machine(std::ostream& out, const DeviceEntry& device) {
    nlohmann::json machine = machine_json(device);
    out << "CPU: " << machine["cpu"].get<std::string>() << ", " << machine["hardware_threads"] << " hardware threads\n"
        << "OpenCL: " << device.platform_name << " / " << device.device_name << " / " << device.version << " / driver "
        << machine["opencl_driver"].get<std::string>() << "\n"
        << "Peer: " << (machine["embree"].is_null() ? "none" : machine["embree"].get<std::string>()) << "\n\n";
}

void print_table(std::ostream& out, const std::vector<SceneRow>& rows, const RunSettings& settings) {
    out << "| scene | objects | clrender Mrays/s (kernel) | clrender Mrays/s (wall) | Embree Mrays/s "
           "| clrender/Embree (wall) | differing pixels % | covered pixels % | bytes/triangle |\n"
        << "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    bool any_single = false;
    for (const SceneRow& row : rows) {
        Figures f = figures_of(row, settings);
        any_single |= f.single_frame;
        auto peer = [&](const std::string& text) { return settings.with_embree ? text : std::string("n/a"); };
        out << "| " << row.spec.name << (f.single_frame ? " *" : "") << " | " << row.spec.objects() + row.triangles
            << " | " << rate(f.clr_kernel_mrays) << " | " << rate(f.clr_wall_mrays) << " | " << peer(rate(f.embree_mrays))
            << " | " << peer(fixed(f.clr_wall_mrays / f.embree_mrays, 2)) << " | " << peer(fixed(100 * row.differing, 4))
            << " | " << fixed(100 * row.covered, 1) << " | "
            << (row.triangles ? fixed(row.bytes_per_triangle, 1) : std::string("-")) << " |\n";
    }
    out << "\n"
        << settings.width << "x" << settings.height << ", one primary ray per pixel; median of " << settings.repeat
        << " frames after a warm-up frame, the two sides alternating frame by frame.\n"
        << "Mesh rows but \"flat\" are lit: each hit that faces the sun also traces a shadow ray; their pixels differ\n"
        << "when a colour channel differs by more than " << kLitTolerance << "/255.\n";
    if (any_single)
        out << "* a side took over " << kSlowFrameMs / 1000 << " s for its warm-up frame, which is then its only timed frame.\n";
    if (!settings.with_embree) out << "Embree: not built (install libembree-dev and reconfigure).\n";
}

void write_json(const std::string& path, const std::vector<SceneRow>& rows, const DeviceEntry& device,
                const RunSettings& settings) {
    nlohmann::json out = {{"machine", machine_json(device)},
                          {"width", settings.width},
                          {"height", settings.height},
                          {"repeat", settings.repeat},
                          {"scenes", nlohmann::json::array()}};
    for (const SceneRow& row : rows) out["scenes"].push_back(row_json(row, settings));
    std::ofstream file(path);
    file << out.dump(2) << "\n";
    if (!file) throw OutputError("cannot write '" + path + "'");
}

}  // namespace clr::bench
