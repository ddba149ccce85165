// ffmpeg runs as a child process started with posix_spawn, never through a shell (a path
// with spaces or quotes stays one argument). Its stdin is a pipe carrying raw rgb24 frames,
// its stdout goes to /dev/null and its stderr to a log file whose last lines explain a
// failure. It writes into a temporary file beside the final one, renamed into place only
// after ffmpeg has exited successfully (rename is atomic within one file system).
#include "output/video_encoder.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
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
#include "output/temp_files.h"

extern char** environ;

namespace clr {
namespace {

// ---- Finding the encoder -------------------------------------------------------------

bool is_executable_file(const std::string& path) {
    struct stat info {};
    return ::stat(path.c_str(), &info) == 0 && S_ISREG(info.st_mode) && ::access(path.c_str(), X_OK) == 0;
}

// The first executable `name` in the folders of $PATH, as a shell would find it. An empty
// entry means the current folder (POSIX).
std::optional<std::string> search_path(const std::string& name) {
    const char* path_variable = std::getenv("PATH");
    const std::string folders = path_variable ? path_variable : "/usr/bin:/bin";
    std::size_t start = 0;
    while (start <= folders.size()) {
        const std::size_t colon = std::min(folders.find(':', start), folders.size());
        const std::string folder = folders.substr(start, colon - start);
        const std::string candidate = (folder.empty() ? "." : folder) + "/" + name;
        if (is_executable_file(candidate)) return candidate;
        start = colon + 1;
    }
    return std::nullopt;
}

// A name with a '/' is a path; a bare name is looked up on $PATH.
std::optional<std::string> resolve_program(const std::string& name) {
    if (name.find('/') == std::string::npos) return search_path(name);
    if (is_executable_file(name)) return name;
    return std::nullopt;
}

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

std::vector<std::string> mp4_arguments(const VideoSettings& settings) {
    return {
        // H.264 in 4:2:0 needs even dimensions: pad odd ones by a black column or row rather
        // than scale (which would blur every pixel). Then convert with the BT.709 matrix and
        // say so in the stream, so that players do not guess and shift the colours.
        "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2,scale=out_color_matrix=bt709:out_range=tv,format=yuv420p",
        "-colorspace", "bt709", "-color_primaries", "bt709", "-color_trc", "bt709",
        "-c:v", "libx264", "-pix_fmt", "yuv420p", "-crf", std::to_string(settings.quality), "-preset", "medium",
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
    std::vector<std::string> arguments = {
        program, "-hide_banner", "-nostats", "-loglevel", "error",
        "-f", "rawvideo", "-pix_fmt", "rgb24",
        "-s", std::to_string(settings.width) + "x" + std::to_string(settings.height),
        "-r", decimal(settings.fps), "-i", "-"};
    const std::vector<std::string> output =
        format == VideoFormat::Mp4 ? mp4_arguments(settings) : gif_arguments();
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

// A short temporary name in the folder of `final_path` (temp_files.h: it fits wherever the
// final name fits, with the log's ".log" added, and a later run removes it if this one is
// killed). The same counter as AtomicFile's keeps the two kinds of temporary file apart.
std::string temp_path_beside(const std::string& final_path) { return temp_path_in_folder_of(final_path); }

// Creates `path`, failing if it exists (O_EXCL: never reuse a file someone else made), and
// returns the open descriptor.
int create_exclusive(const std::string& path, const std::string& final_path) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0) throw OutputError(final_path + ": cannot create a file in its folder: " + std::strerror(errno));
    return fd;
}

// Starts `arguments[0]` with stdin, stdout and stderr connected to the given descriptors.
pid_t spawn(const std::vector<std::string>& arguments, int stdin_fd, int stderr_fd) {
    std::vector<char*> argv;
    for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
    argv.push_back(nullptr);

    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, stdin_fd, STDIN_FILENO);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_adddup2(&actions, stderr_fd, STDERR_FILENO);

    // The child starts with default signal handling and nothing blocked, whatever clrender
    // (which ignores SIGPIPE) or its render threads have set.
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    sigset_t signals;
    sigemptyset(&signals);
    posix_spawnattr_setsigmask(&attributes, &signals);
    sigaddset(&signals, SIGPIPE);
    posix_spawnattr_setsigdefault(&attributes, &signals);
    // Its own process group: Ctrl-C at the terminal then reaches clrender alone, which stops
    // the encoder itself and removes its files, instead of ffmpeg dying first and the
    // interruption looking like an encoder failure.
    posix_spawnattr_setpgroup(&attributes, 0);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETPGROUP);

    pid_t pid = -1;
    const int error = ::posix_spawn(&pid, argv[0], &actions, &attributes, argv.data(), environ);
    posix_spawnattr_destroy(&attributes);
    posix_spawn_file_actions_destroy(&actions);
    if (error != 0) {
        throw OutputError("cannot start the video encoder '" + arguments[0] + "': " + std::strerror(error));
    }
    return pid;
}

// Writes all of `size` bytes, resuming after short writes and after signals interrupt the
// write, so that a frame is never sent in part. Returns 0, or the errno that stopped it.
int write_all(int fd, const std::uint8_t* data, std::size_t size) {
    while (size > 0) {
        const ssize_t written = ::write(fd, data, size);
        if (written < 0) {
            if (errno == EINTR) continue;
            return errno;
        }
        data += written;
        size -= static_cast<std::size_t>(written);
    }
    return 0;
}

std::string describe_exit(const std::string& program, int status) {
    if (WIFEXITED(status)) return "'" + program + "' exited with status " + std::to_string(WEXITSTATUS(status));
    if (WIFSIGNALED(status)) {
        return "'" + program + "' was killed by signal " + std::to_string(WTERMSIG(status)) + " (" +
               strsignal(WTERMSIG(status)) + ")";
    }
    return "'" + program + "' stopped with wait status " + std::to_string(status);
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
    for (std::size_t i = first; i < lines.size(); ++i) tail += "\n  " + lines[i];
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

}  // namespace

VideoFormat video_format_for(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension == ".mp4") return VideoFormat::Mp4;
    if (extension == ".gif") return VideoFormat::Gif;
    throw UsageError("'" + path + "': unsupported video format; use a .mp4 or .gif file name");
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
    if (!(settings_.fps > 0) || !std::isfinite(settings_.fps)) throw std::invalid_argument("VideoEncoder: bad fps");
    if (settings_.quality < 0 || settings_.quality > 51) throw std::invalid_argument("VideoEncoder: CRF outside 0-51");
    ignore_sigpipe();
    rgb_.resize(static_cast<std::size_t>(settings_.width) * settings_.height * 3);
    try {
        start();
    } catch (...) {
        abandon();  // the destructor does not run for a constructor that throws
        throw;
    }
}

VideoEncoder::~VideoEncoder() { abandon(); }

void VideoEncoder::start() {
    temp_path_ = temp_path_beside(settings_.path);
    ::close(create_exclusive(temp_path_, settings_.path));  // reserves the name; ffmpeg overwrites it
    log_path_ = temp_path_ + ".log";
    const int log_fd = create_exclusive(log_path_, settings_.path);

    // Close-on-exec on both ends: the child gets the read end as its stdin through dup2, and
    // no other child (another encoder) inherits the write end, which would keep this pipe
    // open and ffmpeg waiting for more frames forever.
    int pipe_fds[2];
    if (::pipe2(pipe_fds, O_CLOEXEC) != 0) {
        const int error = errno;
        ::close(log_fd);
        throw OutputError(settings_.path + ": cannot create a pipe to the video encoder: " + std::strerror(error));
    }
    stdin_fd_ = pipe_fds[1];
    try {
        pid_ = spawn(encoder_arguments(program_, settings_, format_, temp_path_), pipe_fds[0], log_fd);
    } catch (...) {
        ::close(pipe_fds[0]);
        ::close(log_fd);
        throw;
    }
    ::close(pipe_fds[0]);
    ::close(log_fd);
}

void VideoEncoder::add_frame(const Image& rgba) {
    if (done_) throw std::logic_error("VideoEncoder::add_frame after finish() or a failure");
    const std::size_t pixels = static_cast<std::size_t>(settings_.width) * settings_.height;
    if (rgba.width != settings_.width || rgba.height != settings_.height || rgba.rgba.size() != pixels * 4) {
        throw std::invalid_argument("VideoEncoder::add_frame: a " + std::to_string(rgba.width) + "x" +
                                    std::to_string(rgba.height) + " frame for a " + std::to_string(settings_.width) +
                                    "x" + std::to_string(settings_.height) + " video");
    }
    for (std::size_t i = 0; i < pixels; ++i) std::memcpy(&rgb_[i * 3], &rgba.rgba[i * 4], 3);

    if (const int error = write_all(stdin_fd_, rgb_.data(), rgb_.size())) {
        // EPIPE: ffmpeg closed its input, which it does only when it gives up (or exits).
        close_stdin();
        if (error != EPIPE) ::kill(pid_, SIGKILL);
        const int status = wait_for_encoder();
        const std::string reason = error == EPIPE ? "the encoder stopped reading frames: " + describe_exit(program_, status)
                                                  : std::string("cannot send a frame to the encoder: ") + std::strerror(error);
        fail(reason);
    }
    ++frames_added_;
}

void VideoEncoder::finish() {
    if (done_) throw std::logic_error("VideoEncoder::finish called twice or after a failure");
    close_stdin();  // end of stream: ffmpeg flushes and writes the file's index
    const int status = wait_for_encoder();
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) fail(describe_exit(program_, status));
    if (frames_added_ == 0) fail("no frames to encode");
    move_into_place();
    ::unlink(log_path_.c_str());
    done_ = true;
}

void VideoEncoder::move_into_place() {
    struct stat info {};
    if (::stat(temp_path_.c_str(), &info) != 0 || info.st_size == 0) {
        fail("'" + program_ + "' exited successfully but wrote no video");
    }
    if (!sync_file(temp_path_)) fail(std::string("cannot flush the video to disk: ") + std::strerror(errno));
    if (std::rename(temp_path_.c_str(), settings_.path.c_str()) != 0) {
        fail(std::string("cannot move the finished video into place: ") + std::strerror(errno));
    }
}

void VideoEncoder::close_stdin() {
    if (stdin_fd_ >= 0) ::close(stdin_fd_);
    stdin_fd_ = -1;
}

int VideoEncoder::wait_for_encoder() {
    int status = 0;
    if (pid_ <= 0) return status;  // never waitpid(-1, ...): that would reap someone else's child
    while (::waitpid(pid_, &status, 0) < 0) {
        if (errno != EINTR) {
            // Reaped already (only if someone set SIGCHLD to SIG_IGN): the status is lost, and
            // move_into_place's check for an empty file is what remains to catch a failure.
            status = 0;
            break;
        }
    }
    pid_ = -1;
    return status;
}

void VideoEncoder::remove_files() {
    if (!temp_path_.empty()) ::unlink(temp_path_.c_str());
    if (!log_path_.empty()) ::unlink(log_path_.c_str());
}

void VideoEncoder::abandon() noexcept {
    if (done_) return;
    close_stdin();
    if (pid_ > 0) {
        ::kill(pid_, SIGKILL);  // its output is going to be deleted: no need to let it finish
        wait_for_encoder();
    }
    remove_files();
    done_ = true;
}

void VideoEncoder::fail(const std::string& reason) {
    std::string message = settings_.path + ": video encoding failed: " + reason;
    const std::string log = log_tail(log_path_, 10);
    if (!log.empty()) message += "; its log ends:" + log;
    abandon();
    throw OutputError(message);
}

}  // namespace clr
