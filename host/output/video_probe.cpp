// Why -count_frames: it decodes every frame, so corrupt data counts as missing frames, and it
// is exact for both our MP4 (H.264) and GIF settings, identical frames included. Counting
// packets (-count_packets) is about four times cheaper but only reads the container: a
// truncated H.264 packet still counts. Decoding costs about 7 ms of CPU a frame of 1280x720
// (docs/animation.md, How the video is checked and how a stuck encoder is stopped).
#include "output/video_probe.h"

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include <sys/wait.h>

#include "core/errors.h"
#include "core/usable_cpus.h"
#include "output/child_process.h"
#include "output/program_lookup.h"

namespace clr {
namespace {

constexpr std::size_t kMaxOutput = 4096;  // a frame count is a few digits; more is nonsense

// Closes a descriptor when it goes out of scope.
struct FileDescriptor {
    int fd = -1;
    ~FileDescriptor() {
        if (fd >= 0) ::close(fd);
    }
    void close() {
        if (fd >= 0) ::close(fd);
        fd = -1;
    }
};

// ffprobe decodes on one thread unless told otherwise; the check runs after the last frame,
// when the renderer and the encoder are done, so it gets every CPU clrender may use.
std::vector<std::string> prober_arguments(const std::string& prober, const std::string& video) {
    return {prober, "-v", "error", "-threads", std::to_string(usable_cpu_count()), "-select_streams", "v:0",
            "-count_frames", "-show_entries", "stream=nb_read_frames", "-of", "default=noprint_wrappers=1:nokey=1",
            video};
}

// The whole of `text` as a count, or nullopt ("N/A" when no video stream was found).
std::optional<long> parse_count(std::string text) {
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
    if (text.empty() || text.size() > 12) return std::nullopt;
    for (char c : text)
        if (!std::isdigit(static_cast<unsigned char>(c))) return std::nullopt;
    return std::strtol(text.c_str(), nullptr, 10);
}

std::string shown(const std::string& text) {
    std::string cut = text.substr(0, 40);
    while (!cut.empty() && std::isspace(static_cast<unsigned char>(cut.back()))) cut.pop_back();
    return cut.empty() ? "nothing" : "'" + cut + "'";
}

}  // namespace

std::string find_video_prober(const std::string& encoder_program) {
    const char* configured = std::getenv("CLRENDER_FFPROBE");
    if (configured && *configured) {
        if (std::optional<std::string> program = resolve_program(configured)) return *program;
        throw OutputError("video checker '" + std::string(configured) +
                          "' (from CLRENDER_FFPROBE) not found or not executable");
    }
    const std::filesystem::path beside = std::filesystem::path(encoder_program).parent_path() / "ffprobe";
    if (!beside.parent_path().empty() && is_executable_file(beside.string())) return beside.string();
    if (std::optional<std::string> program = search_path("ffprobe")) return *program;
    throw OutputError("video checker 'ffprobe' not found beside '" + encoder_program +
                      "' or on PATH; install the ffmpeg package (apt-get install ffmpeg)");
}

ProbeResult check_frame_count(const std::string& prober, const std::string& video, long expected_frames,
                              const std::string& log_path, Seconds limit, const std::function<void()>& check_stop) {
    int pipe_fds[2];
    if (::pipe2(pipe_fds, O_CLOEXEC) != 0) return {false, std::string("cannot create a pipe: ") + std::strerror(errno)};
    FileDescriptor output{pipe_fds[0]}, output_end{pipe_fds[1]};
    ::fcntl(output.fd, F_SETFL, O_NONBLOCK);  // reads wait in poll(), where check_stop can run
    FileDescriptor log{::open(log_path.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC)};
    std::unique_ptr<ChildProcess> started;
    try {
        started = std::make_unique<ChildProcess>(prober_arguments(prober, video), -1, output_end.fd, log.fd);
    } catch (const OutputError& error) {
        return {false, std::string("the check cannot run: ") + error.what()};
    }
    ChildProcess& probe = *started;
    output_end.close();  // else the read below never sees the end of the output
    log.close();

    const auto give_up = std::chrono::steady_clock::now() + limit;
    std::string text;
    char buffer[512];
    for (;;) {
        const ssize_t got = ::read(output.fd, buffer, sizeof buffer);
        if (got > 0) {
            if (text.size() < kMaxOutput) text.append(buffer, static_cast<std::size_t>(got));
            continue;
        }
        if (got == 0) break;  // the end: ffprobe has closed its stdout, it is exiting
        if (errno != EINTR && errno != EAGAIN) break;
        check_stop();
        if (std::chrono::steady_clock::now() > give_up) {
            return {false, "'" + prober + "' did not finish checking it within " + seconds_text(limit) + " s"};
        }
        pollfd readable{output.fd, POLLIN, 0};
        ::poll(&readable, 1, 100);
    }
    std::optional<int> status;
    for (int slice_ms = 1; !(status = probe.poll_exit());) {
        check_stop();
        if (std::chrono::steady_clock::now() > give_up) {
            return {false, "'" + prober + "' did not finish checking it within " + seconds_text(limit) + " s"};
        }
        sleep_a_slice(slice_ms);
    }
    if (!WIFEXITED(*status) || WEXITSTATUS(*status) != 0) {
        return {false, "the check cannot read it: " + describe_exit(prober, *status)};
    }
    const std::optional<long> frames = parse_count(text);
    if (!frames) return {false, "the check found no countable video stream in it ('" + prober + "' printed " + shown(text) + ")"};
    if (*frames != expected_frames) {
        return {false, "it holds " + std::to_string(*frames) + " readable frame(s), " + std::to_string(expected_frames) +
                           " were sent"};
    }
    return {true, ""};
}

}  // namespace clr
