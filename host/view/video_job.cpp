#include "view/video_job.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <exception>
#include <filesystem>
#include <future>
#include <iostream>
#include <limits>
#include <nlohmann/json.hpp>

#include "core/errors.h"
#include "core/printable_text.h"
#include "core/stop_with_parent.h"
#include "output/child_process.h"
#include "output/output_target.h"
#include "scene/scene_loader.h"

namespace clr {

std::string clrender_program_path() {
    std::error_code error;
    const std::filesystem::path self = std::filesystem::read_symlink(kOwnProgram, error);
    if (error) throw OutputError("cannot find clrender's own program to render the video: " + error.message());
    return self.string();
}

namespace {

// A path as the render's command line must get it: one that begins with '-' (under an
// --output-dir named "-out") would be read as an option, so it is given as "./-out/...".
std::string never_an_option(const std::string& path) { return !path.empty() && path[0] == '-' ? "./" + path : path; }

// A file in memory that holds `text` and can no longer change (sealed), for the render's
// standard input: the scene the viewer wrote and checked, whatever happens to its file in
// --output-dir meanwhile (another program that may write there renamed a scene of its own over
// it, and the render, which read it by name, rendered that into the video).
int sealed_text(const std::string& text) {
    const int file = ::memfd_create("clrender-video-scene", MFD_CLOEXEC | MFD_ALLOW_SEALING);
    if (file < 0) throw OutputError(std::string("cannot hand the scene to the video render: ") + std::strerror(errno));
    for (std::size_t written = 0; written < text.size();) {
        const ssize_t now = ::write(file, text.data() + written, text.size() - written);
        if (now < 0 && errno == EINTR) continue;
        if (now <= 0) {
            const int error = errno;
            ::close(file);
            throw OutputError(std::string("cannot hand the scene to the video render: ") + std::strerror(error));
        }
        written += static_cast<std::size_t>(now);
    }
    if (::fcntl(file, F_ADD_SEALS, F_SEAL_SHRINK | F_SEAL_GROW | F_SEAL_WRITE | F_SEAL_SEAL) != 0) {
        const int error = errno;
        ::close(file);
        throw OutputError(std::string("cannot hand the scene to the video render: ") + std::strerror(error));
    }
    return file;
}

// A whole number from 0 to INT_MAX; nullopt for anything else (text, a fraction, a negative or
// larger number), which get<int>() would throw at or wrap.
std::optional<int> count_of(const nlohmann::json& object, const char* key) {
    const auto value = object.find(key);
    if (value == object.end()) return std::nullopt;
    if (value->is_number_unsigned()) {
        const std::uint64_t count = value->get<std::uint64_t>();
        if (count <= std::uint64_t(std::numeric_limits<int>::max())) return static_cast<int>(count);
    } else if (value->is_number_integer()) {
        const std::int64_t count = value->get<std::int64_t>();
        if (count >= 0 && count <= std::numeric_limits<int>::max()) return static_cast<int>(count);
    }
    return std::nullopt;
}

}  // namespace

VideoProgressLine read_video_progress_line(const std::string& line) {
    VideoProgressLine read;
    const nlohmann::json progress = nlohmann::json::parse(line, nullptr, false);
    if (progress.is_object()) {
        read.done = count_of(progress, "frames_done");
        read.total = count_of(progress, "frames");
        if (read.done && read.total) {
            // A video's frames are done only once it is in place: its progress is the frame.
            const std::optional<int> frame = count_of(progress, "frame");
            if (frame && *frame < std::numeric_limits<int>::max()) read.frame = *frame + 1;
            return read;
        }
        read.done = read.total = std::nullopt;
        const auto message = progress.find("message");
        if (message != progress.end() && message->is_string()) {
            // An error or warning line of --progress json: its message, as the page shows it.
            read.message = shortened(printable(message->get<std::string>()), kLongestDetail);
            const auto level = progress.find("level");
            read.warning = level != progress.end() && *level == "warning";
            return read;
        }
    }
    read.message = shortened(printable(line), kLongestDetail);
    return read;
}

VideoJobs::VideoJobs(std::vector<std::string> render_arguments) : render_arguments_(std::move(render_arguments)) {}

VideoJobs::~VideoJobs() { stop(); }

VideoJobs::Place::~Place() {
    if (!owner_) return;
    std::lock_guard<std::mutex> lock(owner_->mutex_);
    owner_->reserved_ = false;
}

std::optional<VideoJobs::Place> VideoJobs::reserve() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (running_ || reserved_) return std::nullopt;
    reserved_ = true;
    return Place(*this);
}

int VideoJobs::start(Place&& place, const std::string& scene_path, const std::string& scene_text,
                     const std::string& video_path) {
    std::lock_guard<std::mutex> lock(mutex_);
    place.owner_ = nullptr;  // taken here: the job runs, or the render could not start
    reserved_ = false;
    if (watcher_.joinable()) watcher_.join();  // the last job's, finished
    child_.reset();
    std::vector<std::string> arguments{clrender_program_path(), never_an_option(scene_path), "--video",
                                       never_an_option(video_path), "--progress", "json", "-q"};
    arguments.insert(arguments.end(), render_arguments_.begin(), render_arguments_.end());
    const int scene = sealed_text(scene_text);
    int fds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0) {
        const int error = errno;
        ::close(scene);
        throw OutputError(std::string("cannot create a pipe for the video render: ") + std::strerror(error));
    }
    // The render is started by the thread that watches it, which ends only once the render has
    // been reaped: the render stops when the thread that started it ends (stop_with_parent.h),
    // which is then when the viewer's process ends, killed outright too, and never before.
    std::promise<std::exception_ptr> started;
    std::future<std::exception_ptr> start_result = started.get_future();
    watcher_ = std::thread([this, arguments, fds, scene, started = std::move(started)]() mutable {
        try {
            const std::vector<std::string> environment{stop_with_parent_entry(),
                                                       std::string(kLinksReplacedVariable) + "=1",
                                                       std::string(kSceneOnStdinVariable) + "=1"};
            child_ = std::make_unique<ChildProcess>(arguments, scene, -1, fds[1], kOwnProgram, environment);
        } catch (...) {
            ::close(scene);
            ::close(fds[0]);
            ::close(fds[1]);
            started.set_value(std::current_exception());
            return;
        }
        ::close(scene);
        ::close(fds[1]);
        started.set_value(nullptr);
        watch(fds[0]);
    });
    if (const std::exception_ptr failure = start_result.get()) {
        watcher_.join();
        std::rethrow_exception(failure);
    }
    VideoJobState job;
    job.id = static_cast<int>(jobs_.size()) + 1;
    job.state = "running";
    job.file = video_path;
    jobs_.push_back(job);
    running_ = true;
    return job.id;
}

void VideoJobs::take_progress_line(const std::string& line, std::string& last_message) {
    const VideoProgressLine read = read_video_progress_line(line);
    if (read.done && read.total) {
        std::lock_guard<std::mutex> lock(mutex_);
        jobs_.back().done = *read.done;
        jobs_.back().total = *read.total;
        if (read.frame) jobs_.back().frame = *read.frame;
        return;
    }
    if (!read.message.empty()) last_message = read.message;
    // The video reads the meshes and images again: a file changed since the viewer started may
    // give a warning, which a finished job does not show. It goes to the viewer's terminal, where
    // the scene's own warnings went, as a render prints it.
    if (read.warning) std::cerr << ("clrender: warning: " + read.message + "\n") << std::flush;
}

// Reads the render's progress lines (--progress json) until it closes its standard error,
// then reaps it.
void VideoJobs::watch(int read_fd) {
    std::string pending, last_message;
    char buffer[4096];
    for (;;) {
        const ssize_t got = ::read(read_fd, buffer, sizeof buffer);
        if (got < 0 && errno == EINTR) continue;
        if (got <= 0) break;
        pending.append(buffer, static_cast<std::size_t>(got));
        for (std::size_t end; (end = pending.find('\n')) != std::string::npos; pending.erase(0, end + 1))
            take_progress_line(pending.substr(0, end), last_message);
        if (pending.size() > 65536) pending.clear();  // no line is that long: drop garbage
    }
    ::close(read_fd);
    int slice_ms = 1;
    for (;;) {
        std::unique_lock<std::mutex> lock(mutex_);
        const std::optional<int> status = child_->poll_exit();
        if (!status) {
            lock.unlock();
            sleep_a_slice(slice_ms);
            continue;
        }
        VideoJobState& job = jobs_.back();
        const bool ok = !stopping_ && WIFEXITED(*status) && WEXITSTATUS(*status) == 0;
        job.state = ok ? "done" : "failed";
        if (stopping_)
            job.error = "the viewer stopped before the video was finished";
        else if (!ok)
            job.error = last_message.empty() ? describe_exit("clrender", *status) : last_message;
        running_ = false;
        return;
    }
}

std::optional<VideoJobState> VideoJobs::state(int id) const {
    std::lock_guard<std::mutex> lock(mutex_);
    if (id < 1 || static_cast<std::size_t>(id) > jobs_.size()) return std::nullopt;
    return jobs_[static_cast<std::size_t>(id) - 1];
}

std::optional<VideoJobState> VideoJobs::latest() const {
    std::lock_guard<std::mutex> lock(mutex_);
    if (jobs_.empty()) return std::nullopt;
    return jobs_.back();
}

void VideoJobs::stop() {
    std::unique_lock<std::mutex> lock(mutex_);
    if (running_ && child_) {
        stopping_ = true;
        // clrender removes its unfinished files and stops its encoder on SIGTERM: it is given the
        // time that takes (its bands are a fraction of a second, the encoder's grace half a second).
        child_->stop(std::chrono::seconds(10));  // the watcher then reads the end of its output
    }
    lock.unlock();
    if (watcher_.joinable()) watcher_.join();
}

}  // namespace clr
