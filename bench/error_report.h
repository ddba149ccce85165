// The run-time-against-error benchmark's results (docs/error-benchmark.md): one row per scene,
// precision and sample count, with its times and its error against the scene's reference;
// the Pareto front; the fastest row that meets a target; and the table, JSON and Markdown
// they are written as.
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "bench/error_metrics.h"
#include "device/device_selection.h"

namespace clr::bench {

struct ErrorRunSettings {
    int width = 480, height = 270;
    int repeat = 3;            // timed frames per setting, after a warm-up frame
    std::vector<int> spp;      // sample counts measured, in both precisions
    int reference_spp = 256;   // the reference: double precision at this many samples
};

// One measured setting of one scene.
struct ErrorRow {
    bool double_precision = false;
    int spp = 1;
    double build_ms = 0;                     // program build and scene upload
    std::vector<double> kernel_ms, wall_ms;  // per timed frame
    ImageError error;                        // of the last frame (every frame is the same image)
    bool pareto = false;                     // see mark_pareto

    const char* precision() const { return double_precision ? "double" : "float"; }
    double kernel_median() const;
    double wall_median() const;
};

struct SceneErrors {
    std::string name, source;
    int frame = 0;                  // animation frame (seeds the samples)
    double reference_kernel_ms = 0;  // one untimed-for-the-table frame of the reference
    std::vector<ErrorRow> rows;
};

// A target error: the fastest row with PSNR >= value (dB), or with RMSE <= value.
struct ErrorTarget {
    enum class Metric { Psnr, Rmse } metric = Metric::Psnr;
    double value = 0;
    bool met_by(const ErrorRow& row) const;
    std::string describe() const;  // "PSNR >= 40 dB"
};

// Marks the rows that no other row of the scene beats: a row is on the Pareto front unless
// another is strictly faster (median kernel time) and at least as accurate (RMSE no larger,
// counting RMSEs within 0.1% of each other as equal).
void mark_pareto(std::vector<ErrorRow>& rows);

// The row with the smallest median kernel time that meets `target`, or null.
const ErrorRow* fastest_meeting(const SceneErrors& scene, const ErrorTarget& target);

void print_table(std::ostream& out, const std::vector<SceneErrors>& scenes, const ErrorRunSettings& settings);
void print_target(std::ostream& out, const std::vector<SceneErrors>& scenes, const ErrorTarget& target);

// Both throw OutputError when the file cannot be written. `command` is the benchmark's
// command line, quoted in the document.
void write_json(const std::string& path, const std::vector<SceneErrors>& scenes, const DeviceEntry& device,
                const ErrorRunSettings& settings, const std::optional<ErrorTarget>& target);
void write_markdown(const std::string& path, const std::vector<SceneErrors>& scenes, const DeviceEntry& device,
                    const ErrorRunSettings& settings, const std::string& command);

}  // namespace clr::bench
