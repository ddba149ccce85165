#include "app/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <optional>

namespace clr {
namespace {

constexpr int kBarWidth = 20;
// Updates within a frame closer together than this are not shown: nobody reads them.
constexpr double kLeastSecondsBetweenParts = 0.1;

// Seconds left at the pace so far; nothing until some of the work is done.
std::optional<double> seconds_left(double fraction, double elapsed_s) {
    if (fraction <= 0) return std::nullopt;
    return elapsed_s * (1 - fraction) / fraction;
}

// `value` to `decimals` places; dividing last gives the double nearest the decimal (41.7, not
// 41.699999999999996), which JSON then shows as written.
double rounded(double value, int decimals) {
    const double scale = std::pow(10.0, decimals);
    return std::round(value * scale) / scale;
}

}  // namespace

ProgressStyle progress_style_named(const std::string& name) {
    if (name == "json") return ProgressStyle::Json;
    if (name == "none") return ProgressStyle::None;
    return ProgressStyle::Bar;
}

std::string format_duration(double seconds) {
    long total = std::lround(std::max(0.0, seconds));
    char text[32];
    if (total >= 3600)
        std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", total / 3600, total / 60 % 60, total % 60);
    else
        std::snprintf(text, sizeof text, "%ld:%02ld", total / 60, total % 60);
    return text;
}

std::string format_progress_bar(double fraction, int frames_done, int frames, double elapsed_s) {
    fraction = std::clamp(fraction, 0.0, 1.0);
    const int filled = static_cast<int>(fraction * kBarWidth);
    std::string bar = "clrender: [" + std::string(filled, '#') + std::string(kBarWidth - filled, ' ') + "]";
    char text[96];
    std::snprintf(text, sizeof text, " %3d%%", static_cast<int>(fraction * 100));
    bar += text;
    if (frames > 1) {
        bar += "  frame " + std::to_string(std::min(frames_done + 1, frames)) + "/" + std::to_string(frames);
        if (frames_done > 0 && elapsed_s > 0) bar += "  " + format_frame_rate(frames_done / elapsed_s) + " frames/s";
    }
    bar += "  elapsed " + format_duration(elapsed_s);
    const std::optional<double> left = seconds_left(fraction, elapsed_s);
    bar += "  left " + (left ? format_duration(*left) : std::string("?"));
    return bar;
}

std::string format_frame_rate(double frames_per_second) {
    char text[32];
    if (frames_per_second >= 10)
        std::snprintf(text, sizeof text, "%.0f", frames_per_second);
    else if (frames_per_second >= 1)
        std::snprintf(text, sizeof text, "%.1f", frames_per_second);
    else
        std::snprintf(text, sizeof text, "%.2f", frames_per_second);
    return text;
}

std::string format_progress_json(int frame, int frames, int frames_done, double fraction, double elapsed_s) {
    fraction = std::clamp(fraction, 0.0, 1.0);
    const std::optional<double> left = seconds_left(fraction, elapsed_s);
    nlohmann::json line = {{"frame", frame},
                           {"frames", frames},
                           {"frames_done", frames_done},
                           {"percent", rounded(fraction * 100, 1)},
                           {"elapsed_s", rounded(elapsed_s, 2)},
                           {"eta_s", left ? nlohmann::json(rounded(*left, 2)) : nlohmann::json(nullptr)}};
    return line.dump();
}

Progress::Progress(int total_frames, ProgressStyle style, bool quiet)
    : total_(std::max(1, total_frames)),
      bar_(style == ProgressStyle::Bar && !quiet && isatty(STDERR_FILENO)),
      json_(style == ProgressStyle::Json) {}

Progress::~Progress() {
    if (line_open_) std::fputc('\n', stderr);
}

double Progress::fraction_of_run() const { return (done_ + frame_fraction_) / total_; }

void Progress::frame_started(int frame) {
    if (!started_) {  // the clock runs from the first frame, not from the program's build
        started_ = true;
        since_start_ = Stopwatch();
    }
    frame_ = frame;
    frame_fraction_ = 0;
}

void Progress::frame_part_done(double fraction) {
    frame_fraction_ = std::clamp(fraction, 0.0, 1.0);
    // Bands come several times a second; the reference reports every row, far more often.
    // The frame's last band is shown by frame_done(), which follows.
    if (frame_fraction_ >= 1 || since_last_part_.elapsed_seconds() < kLeastSecondsBetweenParts) return;
    since_last_part_ = Stopwatch();
    if (bar_) draw_bar();
    if (json_ && total_ == 1) print_json_line();  // a still's bands
}

void Progress::frame_done(int in_place) {
    ++done_;
    in_place_ = std::clamp(in_place, 0, total_);
    frame_fraction_ = 0;
    if (bar_) draw_bar();
    // A still's one line comes from all_in_place(), once its image is under its name.
    if (json_ && total_ > 1) print_json_line();
}

void Progress::all_in_place() {
    in_place_ = total_;
    done_ = total_;
    frame_fraction_ = 0;
    if (json_) print_json_line();
}

void Progress::draw_bar() {
    std::fprintf(stderr, "\r%s   ", format_progress_bar(fraction_of_run(), done_, total_, since_start_.elapsed_seconds()).c_str());
    std::fflush(stderr);
    line_open_ = true;
}

void Progress::print_json_line() const {
    const std::string line =
        format_progress_json(frame_, total_, in_place_, fraction_of_run(), since_start_.elapsed_seconds()) + "\n";
    std::fputs(line.c_str(), stderr);
    std::fflush(stderr);
}

void Progress::finish() {
    if (line_open_) std::fputc('\n', stderr);
    line_open_ = false;
}

}  // namespace clr
