#include "bench/error_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "bench/bench_stats.h"
#include "output/atomic_file.h"

namespace clr::bench {
namespace {

// The PSNR targets that docs/error-benchmark.md answers without a rerun.
constexpr double kDocumentedPsnrTargets[] = {30, 35, 40, 45};

// RMSEs within this fraction of each other count as equally accurate on the Pareto front.
// Float and double at the same sample count differ by less (a few edge pixels rounded the
// other way), which is no reason to call the slower of the two better; a tenth of a percent
// is 0.009 dB of PSNR.
constexpr double kRmseTolerance = 1e-3;

std::string fixed(double value, int decimals) {
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    return text;
}

// 1 - SSIM spans several decades, so it reads best in scientific notation.
std::string scientific(double value) {
    char text[64];
    std::snprintf(text, sizeof text, "%.2e", value);
    return text;
}

std::string cpu_model() {
    std::ifstream in("/proc/cpuinfo");
    for (std::string line; std::getline(in, line);)
        if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
    return "unknown CPU";
}

std::string machine_line(const DeviceEntry& device) {
    return cpu_model() + ", " + std::to_string(std::thread::hardware_concurrency()) + " hardware threads; OpenCL: " +
           device.platform_name + " / " + device.device_name + " / " + device.version;
}

// "float, 8 spp (3.12 ms)", the way a pick is quoted in text.
std::string describe_pick(const ErrorRow& row) {
    return std::string(row.precision()) + ", " + std::to_string(row.spp) + " spp (" + fixed(row.kernel_median(), 2) +
           " ms)";
}

void write_text(const std::string& path, const std::string& text) {
    AtomicFile file(path);  // a reader never sees half a document
    file.write(text.data(), text.size());
    file.commit();
}

std::string sample_list(const std::vector<int>& spp) {
    std::string text;
    for (int n : spp) text += (text.empty() ? "" : ", ") + std::to_string(n);
    return text;
}

nlohmann::json number_or_null(double value) { return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(); }

nlohmann::json row_json(const ErrorRow& row) {
    return {{"precision", row.precision()},
            {"spp", row.spp},
            {"build_ms", row.build_ms},
            {"kernel_ms", row.kernel_median()},
            {"wall_ms", row.wall_median()},
            {"kernel_ms_frames", row.kernel_ms},
            {"wall_ms_frames", row.wall_ms},
            {"rmse", row.error.rmse},
            {"psnr_db", number_or_null(row.error.psnr)},  // null: identical to the reference
            {"ssim", row.error.ssim},
            {"one_minus_ssim", 1 - row.error.ssim},
            {"pareto", row.pareto}};
}

nlohmann::json pick_json(const SceneErrors& scene, const ErrorTarget& target) {
    const ErrorRow* best = fastest_meeting(scene, target);
    if (!best) return nullptr;
    return {{"precision", best->precision()}, {"spp", best->spp}, {"kernel_ms", best->kernel_median()}};
}

nlohmann::json scene_json(const SceneErrors& scene, const ErrorRunSettings& settings,
                          const std::optional<ErrorTarget>& target) {
    nlohmann::json out = {
        {"scene", scene.name},
        {"source", scene.source},
        {"frame", scene.frame},
        {"reference", {{"precision", "double"}, {"spp", settings.reference_spp}, {"kernel_ms", scene.reference_kernel_ms}}},
        {"settings", nlohmann::json::array()},
    };
    for (const ErrorRow& row : scene.rows) out["settings"].push_back(row_json(row));
    if (target) out["fastest_meeting_target"] = pick_json(scene, *target);
    return out;
}

// How far apart float and double are at the same spp, over every scene: the largest RMSE
// difference, and double's kernel time as a multiple of float's (median and range).
void print_precision_summary(std::ostream& out, const std::vector<SceneErrors>& scenes) {
    double largest_difference = 0, largest_relative = 0;
    std::vector<double> ratios;
    for (const SceneErrors& scene : scenes)
        for (const ErrorRow& d : scene.rows)
            for (const ErrorRow& f : scene.rows)
                if (d.double_precision && !f.double_precision && d.spp == f.spp) {
                    double difference = std::abs(d.error.rmse - f.error.rmse);
                    largest_difference = std::max(largest_difference, difference);
                    if (f.error.rmse > 0) largest_relative = std::max(largest_relative, difference / f.error.rmse);
                    ratios.push_back(d.kernel_median() / f.kernel_median());
                }
    if (ratios.empty()) return;
    auto [low, high] = std::minmax_element(ratios.begin(), ratios.end());
    out << "## Float against double\n\n"
        << "At the same spp, float's and double's RMSE against the reference differ by at most "
        << fixed(largest_difference, 4) << " (0..255 scale; at most " << fixed(100 * largest_relative, 3)
        << "% of the RMSE) over every scene; double's kernel time is "
        << fixed(median(ratios), 2) << "x float's (median; from " << fixed(*low, 2) << "x to " << fixed(*high, 2)
        << "x).\n\n";
}

void print_row(std::ostream& out, const SceneErrors& scene, const ErrorRow& row) {
    out << "| " << scene.name << " | " << row.precision() << " | " << row.spp << " | " << fixed(row.kernel_median(), 2)
        << " | " << fixed(row.wall_median(), 2) << " | " << fixed(row.error.rmse, 3) << " | " << fixed(row.error.psnr, 2)
        << " | " << fixed(row.error.ssim, 5) << " | " << scientific(1 - row.error.ssim) << " | "
        << (row.pareto ? "yes" : "") << " |\n";
}

// The fastest setting per scene for each documented PSNR target, as a Markdown table.
void print_documented_targets(std::ostream& out, const std::vector<SceneErrors>& scenes) {
    out << "| scene |";
    for (double db : kDocumentedPsnrTargets) out << " PSNR >= " << db << " dB |";
    out << "\n|---|";
    for (std::size_t i = 0; i < std::size(kDocumentedPsnrTargets); ++i) out << "---|";
    out << "\n";
    for (const SceneErrors& scene : scenes) {
        out << "| " << scene.name << " |";
        for (double db : kDocumentedPsnrTargets) {
            const ErrorRow* best = fastest_meeting(scene, {ErrorTarget::Metric::Psnr, db});
            out << " " << (best ? describe_pick(*best) : "none") << " |";
        }
        out << "\n";
    }
}

constexpr const char* kHowToRead = R"(## How to read it

- Every scene is rendered at each sample count (spp) in float and in double precision, and
  compared with its **reference**: the double-precision kernel at the reference sample count,
  with the same seed and frame. The reference is the best image clrender can make, so the
  error is what fewer samples or float32 cost, not the error against the exact integral over
  each pixel (the reference's own sampling error is not in the figures).
- **kernel ms** is the median device time of the render kernel (OpenCL profiling events) over
  the timed frames, after one warm-up frame per setting; **wall ms** the median wall time of
  `Renderer::render()`: per-frame host work (screen tiles), the kernel, and reading the
  image back. The settings of a scene take turns frame by frame, so that load from other
  processes slows them alike.
- **RMSE** is the root mean square difference over every R, G and B byte (0..255 scale);
  **PSNR** is 20 log10(255 / RMSE) in dB (higher is better); **SSIM** is the mean
  structural similarity (11x11 Gaussian window, sigma 1.5, the usual constants, per colour
  channel), 1 for an identical image; **1-SSIM** is its distance from 1.
- **Pareto**: "yes" when no other setting of the same scene is both faster (kernel ms) and at
  least as accurate (RMSE no larger, counting RMSEs within 0.1% of each other as equal:
  float and double at the same spp differ by less). Only these settings are worth
  choosing: every other one is beaten by one of them on both counts. The plot draws the front
  as a line through them.
- The error is almost all at silhouettes, shadow edges and texture edges, where a pixel's
  samples see different colours. Kernel time grows about linearly with spp, while the error
  falls more slowly the more samples there are; at the highest counts part of what remains
  is the reference's own sampling error and the rounding of both images to bytes.
- Double precision changes only the kernels' geometry (rays, distances, normals), so at the
  same spp it changes a handful of edge pixels: see "Float against double" below for this
  run's figures. Double does no less work than float, so where a double point is on the
  front, its frames ran faster than float's by chance: timing noise from other processes.
- **Picking a setting for a target error**: "Fastest setting for a target PSNR" above answers
  a few targets; for another, run the benchmark with `--target-psnr DB` or
  `--target-rmse VALUE`, which prints, per scene, the fastest setting that meets it (or says
  none does), and records it in the JSON.
)";

}  // namespace

double ErrorRow::kernel_median() const { return median(kernel_ms); }
double ErrorRow::wall_median() const { return median(wall_ms); }

bool ErrorTarget::met_by(const ErrorRow& row) const {
    return metric == Metric::Psnr ? row.error.psnr >= value : row.error.rmse <= value;
}

std::string ErrorTarget::describe() const {
    std::ostringstream text;
    text << (metric == Metric::Psnr ? "PSNR >= " : "RMSE <= ") << value << (metric == Metric::Psnr ? " dB" : "");
    return text.str();
}

void mark_pareto(std::vector<ErrorRow>& rows) {
    for (ErrorRow& row : rows) {
        row.pareto = true;
        for (const ErrorRow& other : rows)
            if (other.kernel_median() < row.kernel_median() &&
                other.error.rmse <= row.error.rmse * (1 + kRmseTolerance))
                row.pareto = false;
    }
}

const ErrorRow* fastest_meeting(const SceneErrors& scene, const ErrorTarget& target) {
    const ErrorRow* best = nullptr;
    for (const ErrorRow& row : scene.rows)
        if (target.met_by(row) && (!best || row.kernel_median() < best->kernel_median())) best = &row;
    return best;
}

void print_table(std::ostream& out, const std::vector<SceneErrors>& scenes, const ErrorRunSettings& settings) {
    out << "| scene | precision | spp | kernel ms | wall ms | RMSE | PSNR dB | SSIM | 1-SSIM | Pareto |\n"
        << "|---|---|---:|---:|---:|---:|---:|---:|---:|---|\n";
    for (const SceneErrors& scene : scenes)
        for (const ErrorRow& row : scene.rows) print_row(out, scene, row);
    out << "\n"
        << settings.width << "x" << settings.height << "; median of " << settings.repeat
        << (settings.repeat == 1 ? " frame" : " frames") << " after a warm-up frame; errors against the double-precision kernel at " << settings.reference_spp
        << " spp.\n";
}

void print_target(std::ostream& out, const std::vector<SceneErrors>& scenes, const ErrorTarget& target) {
    out << "\nFastest setting with " << target.describe() << ":\n";
    for (const SceneErrors& scene : scenes) {
        const ErrorRow* best = fastest_meeting(scene, target);
        out << "- " << scene.name << ": ";
        if (best)
            out << describe_pick(*best) << ", RMSE " << fixed(best->error.rmse, 3) << ", PSNR " << fixed(best->error.psnr, 2)
                << " dB\n";
        else
            out << "none of the measured settings meets it\n";
    }
}

void write_json(const std::string& path, const std::vector<SceneErrors>& scenes, const DeviceEntry& device,
                const ErrorRunSettings& settings, const std::optional<ErrorTarget>& target) {
    nlohmann::json out = {
        {"machine",
         {{"cpu", cpu_model()},
          {"hardware_threads", std::thread::hardware_concurrency()},
          {"opencl_platform", device.platform_name},
          {"opencl_device", device.device_name},
          {"opencl_version", device.version}}},
        {"width", settings.width},
        {"height", settings.height},
        {"repeat", settings.repeat},
        {"spp", settings.spp},
        {"reference_spp", settings.reference_spp},
        {"pareto_rmse_tolerance", kRmseTolerance},  // relative: RMSEs this close count as equal
        {"target", target ? nlohmann::json(target->describe()) : nlohmann::json()},
        {"scenes", nlohmann::json::array()},
    };
    for (const SceneErrors& scene : scenes) out["scenes"].push_back(scene_json(scene, settings, target));
    write_text(path, out.dump(2) + "\n");
}

void write_markdown(const std::string& path, const std::vector<SceneErrors>& scenes, const DeviceEntry& device,
                    const ErrorRunSettings& settings, const std::string& command) {
    std::ostringstream out;
    out << "# Run time against error\n\n"
        << "<!-- Generated by scripts/error_bench.sh (bench/error_bench_main.cpp); edit the generator, not this file. -->\n\n"
        << "How much image quality each anti-aliasing sample count and each precision buys, and what it costs: "
           "every scene at "
        << sample_list(settings.spp) << " samples per pixel, in float and in double, timed and compared with a "
        << settings.reference_spp << "-spp double-precision reference.\n\n"
        << "```\nscripts/error_bench.sh                    # installs, builds build-error/ (Release), runs, and writes\n"
        << "                                          # docs/error-benchmark.md, .json and .png\n"
        << "scripts/error_bench.sh --target-psnr 40   # also prints the fastest setting per scene that meets it\n```\n\n"
        << "This run: `" << command << "`, then `scripts/plot_error_bench.py`.\n\n"
        << "Machine: " << machine_line(device) << ".\n\n"
        << "![Kernel time against RMSE per scene, Pareto front drawn](error-benchmark.png)\n\n"
        << "## Fastest setting for a target PSNR\n\n";
    print_documented_targets(out, scenes);
    out << "\n" << kHowToRead << "\n";
    print_precision_summary(out, scenes);
    out << "## The scenes\n\n"
        << "All at " << settings.width << "x" << settings.height
        << ", whatever size a scene file asks for (the field of view spans the wider side).\n\n"
        << "| scene | source |\n|---|---|\n";
    for (const SceneErrors& scene : scenes)
        out << "| " << scene.name << " | " << scene.source << (scene.frame ? ", frame " + std::to_string(scene.frame) : "")
            << " |\n";
    out << "\n## Results\n\n";
    print_table(out, scenes, settings);
    write_text(path, out.str());
}

}  // namespace clr::bench
