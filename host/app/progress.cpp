#include "app/progress.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>

namespace clr {

std::string format_duration(double seconds) {
    long total = std::lround(std::max(0.0, seconds));
    char text[32];
    if (total >= 3600)
        std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", total / 3600, total / 60 % 60, total % 60);
    else
        std::snprintf(text, sizeof text, "%ld:%02ld", total / 60, total % 60);
    return text;
}

Progress::Progress(int total_frames, bool quiet)
    : total_(total_frames), enabled_(!quiet && total_frames > 1 && isatty(STDERR_FILENO)) {}

void Progress::frame_done() {
    ++done_;
    if (enabled_) draw();
}

void Progress::draw() const {
    const double elapsed = since_start_.elapsed_seconds();
    double fps = elapsed > 0 ? done_ / elapsed : 0;
    double left = fps > 0 ? (total_ - done_) / fps : 0;
    std::fprintf(stderr, "\rclrender: frame %d/%d  %.1f fps  ETA %s   ", done_, total_, fps, format_duration(left).c_str());
    std::fflush(stderr);
}

void Progress::finish() {
    if (enabled_) std::fputc('\n', stderr);
}

}  // namespace clr
