// POST /render-video: an exported scene rendered to NAME.mp4 in --output-dir in the background,
// by clrender itself run as a child process (`clrender NAME.json --video NAME.mp4`), so that the
// video goes through the normal render and output path: the same checks, the same encoder, the
// same atomic rename, and an interrupted render leaves nothing behind. One video at a time.
#pragma once

#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace clr {

struct VideoJobState {
    int id = 0;
    std::string state;  // "running", "done" or "failed"
    int done = 0;       // frames rendered
    int total = 0;      // frames of the video (0 until the render reports them)
    std::string file;   // the video's path
    std::string error;  // why it failed: the render's last message (of its --progress json line)
};

class VideoJobs {
public:
    // `render_arguments` are passed to every render after the scene and the video (device,
    // threads, precision, ...).
    explicit VideoJobs(std::vector<std::string> render_arguments);
    ~VideoJobs();  // stop()s
    VideoJobs(const VideoJobs&) = delete;
    VideoJobs& operator=(const VideoJobs&) = delete;

    // Starts rendering `scene_path` to `video_path`; returns the job's id, or nullopt while
    // another video renders. Throws OutputError when the render cannot start.
    std::optional<int> start(const std::string& scene_path, const std::string& video_path);

    // Whether a video is rendering now.
    bool busy() const;

    // The job's state; nullopt for an id that names no job.
    std::optional<VideoJobState> state(int id) const;

    // Stops a running render (it removes its unfinished files) and waits for it.
    void stop();

private:
    void watch(int read_fd);

    std::vector<std::string> render_arguments_;
    mutable std::mutex mutex_;
    std::vector<VideoJobState> jobs_;  // every job of the session, by id - 1
    std::unique_ptr<class ChildProcess> child_;
    std::thread watcher_;
    bool running_ = false;
    bool stopping_ = false;
};

// clrender's own program (from /proc/self/exe), which renders the videos.
std::string clrender_program_path();

}  // namespace clr
