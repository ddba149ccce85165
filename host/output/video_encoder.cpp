// ffmpeg runs as a child process (output/child_process.h: never through a shell, in its own
// process group). Its stdin is a non-blocking pipe carrying raw frames (yuv420p for an MP4,
// RGBA read as rgb0 for a GIF), its stdout is the temporary file and its stderr a log file
// whose last lines explain a failure. It writes into that temporary file beside the final one,
// which clrender creates and ffmpeg opens as its own stdout (kEncoderOutput), never by name;
// after ffmpeg has exited successfully, ffprobe must read back exactly the frames sent
// (output/video_probe.h) before the file is renamed into place (rename is atomic within one
// file system). Until then an earlier video under the final name stays as it was.
#include "output/video_encoder.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <locale>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "core/errors.h"
#include "core/interruption.h"
#include "output/file_extension.h"
#include "output/full_disk_note.h"
#include "output/vanished_output_note.h"
#include "output/program_lookup.h"
#include "output/temp_files.h"
#include "output/video_probe.h"
#include "output/yuv420_frame.h"

namespace clr {
namespace {

using Clock = std::chrono::steady_clock;

// ffmpeg at -loglevel error writes a few lines; far more is a runaway encoder.
constexpr long long kMaxLogBytes = 1 << 20;

// ---- ffmpeg's command line -------------------------------------------------------------

// Locale-independent, shortest exact-enough decimal ("10", "29.97"): a decimal comma would
// break ffmpeg's parsing.
std::string decimal(double value) {
    std::ostringstream text;
    text.imbue(std::locale::classic());
    text.precision(12);
    text << value;
    return text.str();
}

// x264's preset (docs/animation.md, MP4 encoding). Preset veryfast took a third of preset
// medium's CPU time for the forest flight, where medium's had exceeded the renderer's own, for
// a file as large and a little lower quality at the same CRF.
constexpr const char* kX264Preset = "veryfast";

// x264's options beyond ffmpeg's own (docs/animation.md, MP4 encoding): the lookahead runs on
// the thread that hands x264 its frames, never on a thread of its own.
constexpr const char* kX264DeterministicLookahead = "sync-lookahead=0";

// MP4 frames go to ffmpeg as yuv420p, converted by clrender (output/yuv420_frame.h): ffmpeg's
// own conversion from RGB ran on its one main thread, in series with handing the frames to
// x264, and the pipe carries 1.5 bytes a pixel instead of 4. A GIF's palette is built from
// the frames as they are in memory, RGBA read as "rgb0" (red, green, blue and a byte ffmpeg
// ignores): it gives the same palette as rgb24 input, whatever the alpha bytes hold.
constexpr const char* kMp4PixelFormat = "yuv420p";
constexpr const char* kGifPixelFormat = "rgb0";
constexpr std::size_t kGifBytesPerPixel = 4;

// The pipe to ffmpeg holds up to one frame (at most 1 MiB, Linux's default limit for an
// unprivileged process) instead of the default 64 KiB: fewer wake-ups of clrender and ffmpeg
// per frame. Small frames keep the default size.
constexpr int kLargestPipeBytes = 1 << 20;

std::vector<std::string> mp4_arguments(const VideoSettings& settings) {
    return {
        // The frames are BT.709, limited range (rgba_to_yuv420): the stream says so, so that
        // players do not guess and shift the colours.
        "-colorspace", "bt709", "-color_primaries", "bt709", "-color_trc", "bt709", "-color_range", "tv",
        "-c:v", "libx264", "-pix_fmt", "yuv420p", "-crf", std::to_string(settings.quality), "-preset", kX264Preset,
        "-threads", std::to_string(kX264Threads),
        // No lookahead thread (x264 starts one when it has more than one frame thread): with it
        // the pictures depended on how the threads happened to be scheduled (the demo flight's
        // 96 frames encoded 20 times, on one CPU and on two, gave up to 10 different videos,
        // differing from some frame on); without it 140 encodes gave one (docs/animation.md).
        "-x264-params", kX264DeterministicLookahead,
        "-movflags", "+faststart",  // index first, so that a browser can start playing at once
        "-f", "mp4"};
}

std::vector<std::string> gif_arguments() {
    return {
        // One pass: split the frames, build a single palette from all of them, then map every
        // frame to it. Ordered (Bayer) dithering does not crawl from frame to frame as error
        // diffusion does when the camera moves, and compresses better; diff_mode=rectangle
        // re-encodes only the part of a frame that changed.
        "-filter_complex",
        "split[frames][for_palette];[for_palette]palettegen=stats_mode=full[palette];"
        "[frames][palette]paletteuse=dither=bayer:bayer_scale=3:diff_mode=rectangle",
        "-loop", "0",  // repeat forever
        "-f", "gif"};
}

std::vector<std::string> encoder_arguments(const std::string& program, const VideoSettings& settings, VideoFormat format,
                                           const std::string& output_path) {
    const bool mp4 = format == VideoFormat::Mp4;
    const int width = mp4 ? even_size(settings.width) : settings.width;
    const int height = mp4 ? even_size(settings.height) : settings.height;
    std::vector<std::string> arguments = {
        program, "-hide_banner", "-nostats", "-loglevel", "error",
        "-f", "rawvideo", "-pix_fmt", mp4 ? kMp4PixelFormat : kGifPixelFormat,
        "-s", std::to_string(width) + "x" + std::to_string(height),
        "-r", decimal(settings.fps), "-i", "-"};
    const std::vector<std::string> output =
        mp4 ? mp4_arguments(settings) : gif_arguments();
    arguments.insert(arguments.end(), output.begin(), output.end());
    // No version strings or creation times in the file: the same frames give the same bytes.
    for (const char* argument : {"-fflags", "+bitexact", "-flags:v", "+bitexact", "-y"}) arguments.push_back(argument);
    arguments.push_back(output_path);
    return arguments;
}

// ---- Processes and files --------------------------------------------------------------

// A writer to a pipe whose reader has exited gets SIGPIPE, whose default action kills the
// whole process. Ignored, the write fails with EPIPE instead, which add_frame reports.
void ignore_sigpipe() {
    static const bool ignored = [] {
        struct sigaction action {};
        action.sa_handler = SIG_IGN;
        sigemptyset(&action.sa_mask);
        return ::sigaction(SIGPIPE, &action, nullptr) == 0;
    }();
    (void)ignored;
}

// Where ffmpeg writes: the file it was given as its stdout, which clrender created. Given the
// temporary file's name, ffmpeg opened it by that name after clrender had made it, following
// whatever stood there by then: another user who may write into the folder could replace it
// with a symbolic link in between, and ffmpeg overwrote the link's target, a file of the user
// who renders. Opened through /proc, the name leads to the file itself (also for the second
// open of an MP4's +faststart), however the folder's names change meanwhile.
constexpr const char* kEncoderOutput = "/proc/self/fd/1";

// The video's temporary file, ffmpeg's stdout, and the encoder's log beside it (temp_files.h:
// the names fit wherever the final name fits, with the log's ".log" added, and a later run
// removes them if this one is killed). Each is made in the folder its entry holds open
// (FolderEntry::open), so that the entry removes that very file even if the folder is renamed
// right after.
struct EncoderFiles {
    FolderEntry video_entry;
    FolderEntry log_entry;
    int video_fd = -1;
    int log_fd = -1;
};

// Makes `temp_path` and its ".log", both new (O_EXCL: never reuse a file someone else made);
// false, errno set and nothing left behind, when either cannot be made, so that a taken log
// name makes create_under_temp_name() try another pair.
bool create_encoder_files(const std::string& temp_path, EncoderFiles& files) {
    FolderEntry video_entry(temp_path);
    const int video_fd = video_entry.open(O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (video_fd < 0) return false;
    FolderEntry log_entry(temp_path + ".log");
    const int log_fd = log_entry.open(O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (log_fd < 0) {
        const int error = errno;
        ::close(video_fd);
        video_entry.remove();
        errno = error;
        return false;
    }
    files.video_entry = std::move(video_entry);
    files.log_entry = std::move(log_entry);
    files.video_fd = video_fd;
    files.log_fd = log_fd;
    return true;
}

// The size of the file at `path`, -1 if it cannot be read.
long long file_size(const std::string& path) {
    struct stat info {};
    return ::stat(path.c_str(), &info) == 0 ? static_cast<long long>(info.st_size) : -1;
}

// The last `max_lines` non-empty lines of the log, read from its last 8 KiB only (a broken
// encoder could write a lot).
std::string log_tail(const std::string& path, std::size_t max_lines) {
    std::ifstream log(path, std::ios::binary);
    if (!log) return "";
    log.seekg(0, std::ios::end);
    const std::streamoff size = log.tellg();
    const std::streamoff start = std::max<std::streamoff>(0, size - 8192);
    log.seekg(start);
    std::vector<std::string> lines;
    std::string line;
    while (std::getline(log, line)) {
        while (!line.empty() && std::isspace(static_cast<unsigned char>(line.back()))) line.pop_back();
        if (!line.empty()) lines.push_back(line);
    }
    if (start > 0 && !lines.empty()) lines.erase(lines.begin());  // probably cut mid-line
    const std::size_t first = lines.size() > max_lines ? lines.size() - max_lines : 0;
    std::string tail;
    // Joined on one line: clrender's error is one line (main escapes what else it holds).
    for (std::size_t i = first; i < lines.size(); ++i) tail += (i == first ? " " : " | ") + lines[i];
    return tail;
}

// Flushes a file that another process wrote to disk, so that the rename that follows cannot
// outlive the data in a crash (the same promise AtomicFile keeps).
bool sync_file(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return false;
    const bool synced = ::fsync(fd) == 0;
    ::close(fd);
    return synced;
}

// How long ffprobe may take to decode the video: the stall timeout, plus a second per ten
// million pixels (decoding runs at hundreds of millions of pixels a second).
Seconds probe_limit(const VideoSettings& settings, long frames, Seconds stall_timeout) {
    const double pixels = static_cast<double>(settings.width) * settings.height * static_cast<double>(frames);
    return stall_timeout + Seconds(pixels / 1e7);
}

// The bytes of one frame as sent to ffmpeg.
std::size_t frame_bytes(const VideoSettings& settings, VideoFormat format) {
    if (format == VideoFormat::Mp4) return yuv420_bytes(settings.width, settings.height);
    return static_cast<std::size_t>(settings.width) * static_cast<std::size_t>(settings.height) * kGifBytesPerPixel;
}

// Grows the pipe behind `fd` towards one frame (kLargestPipeBytes at most). Only an
// optimisation: where the system refuses, the pipe keeps its size.
void widen_pipe(int fd, std::size_t frame_size) {
    const int wanted = static_cast<int>(std::min<std::size_t>(frame_size, kLargestPipeBytes));
    const int current = ::fcntl(fd, F_GETPIPE_SZ);
    if (current >= 0 && current < wanted) ::fcntl(fd, F_SETPIPE_SZ, wanted);
}

}  // namespace

VideoFormat video_format_for(const std::string& path) {
    const std::string extension = lowercase_extension(path);
    if (extension == ".mp4") return VideoFormat::Mp4;
    if (extension == ".gif") return VideoFormat::Gif;
    throw UsageError("'" + path + "': unsupported video format; use a .mp4 or .gif file name");
}

std::string video_fps_problem(double fps, VideoFormat format) {
    const bool gif = format == VideoFormat::Gif;
    const double lowest = gif ? kMinGifFps : kMinMp4Fps, highest = gif ? kMaxGifFps : kMaxMp4Fps;
    if (std::isfinite(fps) && fps >= lowest && fps <= highest) return "";
    const std::string why = gif ? " (its frame delays are whole hundredths of a second, from 2 to 65535)"
                                : " (ffmpeg's MP4 writer fails on slower rates)";
    // The lowest shown rounded up to a millionth, so that the rate shown is one that passes.
    return std::string(gif ? "a GIF" : "an MP4") + " takes from " + decimal(std::ceil(lowest * 1e6) / 1e6) + " to " +
           decimal(highest) +
           " frames per second" + why + ", got " + decimal(fps);
}

std::string find_encoder() {
    const char* configured = std::getenv("CLRENDER_FFMPEG");
    if (configured && *configured) {
        if (std::optional<std::string> program = resolve_program(configured)) return *program;
        throw OutputError("video encoder '" + std::string(configured) +
                          "' (from CLRENDER_FFMPEG) not found or not executable");
    }
    if (std::optional<std::string> program = search_path("ffmpeg")) return *program;
    throw OutputError("video encoder 'ffmpeg' not found on PATH; install the ffmpeg package (apt-get install ffmpeg)");
}

VideoEncoder::VideoEncoder(const VideoSettings& settings, const std::string& encoder_program)
    : settings_(settings), format_(video_format_for(settings.path)), program_(encoder_program) {
    if (settings_.width <= 0 || settings_.height <= 0) throw std::invalid_argument("VideoEncoder: empty frame size");
    if (const std::string problem = video_fps_problem(settings_.fps, format_); !problem.empty())
        throw std::invalid_argument("VideoEncoder: " + problem);
    if (settings_.quality < 0 || settings_.quality > 51) throw std::invalid_argument("VideoEncoder: CRF outside 0-51");
    stall_timeout_ = encoder_stall_timeout();
    prober_ = find_video_prober(program_);  // before the first frame: a missing checker must not waste a render
    ignore_sigpipe();
    try {
        start();
    } catch (...) {
        abandon();  // the destructor does not run for a constructor that throws
        throw;
    }
}

VideoEncoder::~VideoEncoder() { abandon(); }

void VideoEncoder::start() {
    EncoderFiles files;
    temp_path_ = create_under_temp_name(
        settings_.path, [&files](const std::string& try_path) { return create_encoder_files(try_path, files); });
    if (temp_path_.empty()) throw OutputError(settings_.path + ": " + temp_creation_failure(errno));
    temp_entry_ = std::move(files.video_entry);  // only files this run made are ever removed
    log_path_ = temp_path_ + ".log";
    log_entry_ = std::move(files.log_entry);
    const int video_fd = files.video_fd;  // ffmpeg's stdout: it writes here
    const int log_fd = files.log_fd;

    // Close-on-exec on both ends: the child gets the read end as its stdin through dup2, and
    // no other child (another encoder) inherits the write end, which would keep this pipe
    // open and ffmpeg waiting for more frames forever.
    int pipe_fds[2];
    if (::pipe2(pipe_fds, O_CLOEXEC) != 0) {
        const int error = errno;
        ::close(log_fd);
        ::close(video_fd);
        throw OutputError(settings_.path + ": cannot create a pipe to the video encoder: " + std::strerror(error));
    }
    stdin_fd_ = pipe_fds[1];
    // Only clrender's end is non-blocking (each end of a pipe has its own flags): a write
    // that would block returns at once, and the wait happens in poll(), where interruption
    // and the stall timeout are checked.
    ::fcntl(stdin_fd_, F_SETFL, O_NONBLOCK);
    widen_pipe(stdin_fd_, frame_bytes(settings_, format_));
    try {
        encoder_ = std::make_unique<ChildProcess>(encoder_arguments(program_, settings_, format_, kEncoderOutput),
                                                  pipe_fds[0], video_fd, log_fd);
    } catch (const OutputError& error) {
        ::close(pipe_fds[0]);
        ::close(video_fd);
        ::close(log_fd);
        throw OutputError(settings_.path + ": video encoder: " + error.what());
    }
    ::close(pipe_fds[0]);
    ::close(video_fd);
    ::close(log_fd);
}

void VideoEncoder::add_frame(const Image& rgba) {
    if (done_) throw std::logic_error("VideoEncoder::add_frame after finish() or a failure");
    const std::size_t pixels = static_cast<std::size_t>(settings_.width) * static_cast<std::size_t>(settings_.height);
    if (rgba.width != settings_.width || rgba.height != settings_.height || rgba.rgba.size() != pixels * 4) {
        throw std::invalid_argument("VideoEncoder::add_frame: a " + std::to_string(rgba.width) + "x" +
                                    std::to_string(rgba.height) + " frame for a " + std::to_string(settings_.width) +
                                    "x" + std::to_string(settings_.height) + " video");
    }
    check_stop();  // also when the encoder reads every frame at once and never makes send() wait
    if (format_ == VideoFormat::Mp4) {
        rgba_to_yuv420(rgba, converted_);  // into the buffer of the frame before: no allocation
        send(converted_.data(), converted_.size());
    } else {
        send(rgba.rgba.data(), rgba.rgba.size());
    }
    ++frames_added_;
}

// Writes all of `size` bytes (a frame is never sent in part). While the pipe is full it
// waits in slices of 100 ms, so that a signal, cancel(), an encoder that has exited or one
// that has read nothing for the stall timeout ends the wait.
void VideoEncoder::send(const std::uint8_t* data, std::size_t size) {
    auto last_progress = Clock::now();
    while (size > 0) {
        const ssize_t written = ::write(stdin_fd_, data, size);
        if (written > 0) {
            data += written;
            size -= static_cast<std::size_t>(written);
            last_progress = Clock::now();
            continue;
        }
        if (written < 0 && errno == EINTR) continue;
        if (written < 0 && errno == EPIPE) fail_after_broken_pipe();
        if (written < 0 && errno != EAGAIN) fail(std::string("cannot send a frame to the encoder: ") + std::strerror(errno));
        check_stop();
        if (const std::optional<int> status = encoder_->poll_exit()) {
            fail("the encoder stopped reading frames: " + describe_exit(program_, *status));
        }
        if (Clock::now() - last_progress > stall_timeout_) {
            fail("the encoder stopped reading frames for " + seconds_text(stall_timeout_) + " s");
        }
        pollfd writable{stdin_fd_, POLLOUT, 0};
        ::poll(&writable, 1, 100);
    }
}

// EPIPE: ffmpeg closed its input, which it does only when it gives up (or exits). Its exit
// status says why; it gets the stall timeout to exit.
void VideoEncoder::fail_after_broken_pipe() {
    close_stdin();
    const auto give_up = Clock::now() + stall_timeout_;
    for (int slice_ms = 1; Clock::now() < give_up; sleep_a_slice(slice_ms)) {
        if (const std::optional<int> status = encoder_->poll_exit()) {
            fail("the encoder stopped reading frames: " + describe_exit(program_, *status));
        }
        check_stop();
    }
    fail("the encoder stopped reading frames and did not exit within " + seconds_text(stall_timeout_) + " s");
}

std::unique_ptr<AtomicFile> VideoEncoder::finish_uncommitted() {
    if (done_) throw std::logic_error("VideoEncoder::finish called twice or after a failure");
    close_stdin();  // end of stream: ffmpeg flushes and writes the file's index
    const int status = wait_after_last_frame();
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) fail(describe_exit(program_, status));
    if (frames_added_ == 0) fail("no frames to encode");
    if (file_size(temp_path_) <= 0) fail("'" + program_ + "' exited successfully but wrote no video");
    check_video();
    if (!sync_file(temp_path_)) fail(std::string("cannot flush the video to disk: ") + std::strerror(errno));
    std::unique_ptr<AtomicFile> video = AtomicFile::adopt(temp_path_, settings_.path);
    temp_path_.clear();  // the AtomicFile owns it now
    log_entry_.remove();
    done_ = true;
    return video;
}

void VideoEncoder::finish() { finish_uncommitted()->commit(); }

// Waits for ffmpeg to exit after the end of the stream. It is making progress while its
// output grows (a GIF's palette is computed from all frames first, a short pause); an output
// that stops growing for the stall timeout with ffmpeg still running is an error.
int VideoEncoder::wait_after_last_frame() {
    long long last_size = file_size(temp_path_);
    auto last_progress = Clock::now();
    for (int slice_ms = 1;; sleep_a_slice(slice_ms)) {
        if (const std::optional<int> status = encoder_->poll_exit()) return *status;
        check_stop();
        const long long size = file_size(temp_path_);
        if (size != last_size) {
            last_size = size;
            last_progress = Clock::now();
        }
        if (Clock::now() - last_progress > stall_timeout_) {
            fail("the encoder did not finish: its output stopped growing for " + seconds_text(stall_timeout_) +
                 " s after the last frame");
        }
    }
}

void VideoEncoder::check_video() {
    const ProbeResult result =
        check_frame_count(prober_, temp_path_, frames_added_, log_path_,
                          probe_limit(settings_, frames_added_, stall_timeout_), [this] { check_stop(); });
    if (!result.ok) fail("the finished video is not valid: " + result.problem);
}

void VideoEncoder::check_stop() {
    // An encoder that floods its log (a broken build printing a warning per pixel) would fill
    // the disk within the stall timeout: at a gigabyte a second, a 100 ms slice overshoots by
    // about 100 MB at most.
    if (file_size(log_path_) > kMaxLogBytes)
        fail("the encoder wrote more than " + std::to_string(kMaxLogBytes >> 20) + " MiB of messages to its log");
    if (interruption_requested()) {
        abandon();
        throw_if_interrupted();
    }
    if (cancelled_) {
        abandon();
        throw OutputError(settings_.path + ": video encoding was abandoned");
    }
}

void VideoEncoder::close_stdin() {
    if (stdin_fd_ >= 0) ::close(stdin_fd_);
    stdin_fd_ = -1;
}

void VideoEncoder::remove_files() {
    if (!temp_path_.empty()) temp_entry_.remove();
    if (!log_path_.empty()) log_entry_.remove();
}

void VideoEncoder::abandon() noexcept {
    if (done_) return;
    close_stdin();
    if (encoder_) encoder_->stop();  // its output is going to be deleted: no need to let it finish
    remove_files();
    done_ = true;
}

void VideoEncoder::fail(const std::string& reason) {
    // Asked before abandon() frees the cut-off file: the space left is what the encoder met,
    // and a temporary file that is gone already was taken from under it.
    std::string message = settings_.path + ": video encoding failed: " + reason +
                          (temp_path_.empty() ? "" : full_disk_note(temp_path_) + vanished_output_note(temp_path_));
    const std::string log = log_tail(log_path_, 10);
    if (!log.empty()) message += "; its log ends:" + log;
    abandon();
    throw OutputError(message);
}

}  // namespace clr
