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
#include <utility>
#include <vector>

namespace clr {

struct VideoJobState {
    int id = 0;
    std::string state;  // "running", "done" or "failed"
    int done = 0;       // frames in place (a video's count only once it is renamed into place)
    int frame = 0;      // the frame the render is on or has just finished, from 1 (0 before the first)
    int total = 0;      // frames of the video (0 until the render reports them)
    std::string file;   // the video's path
    std::string error;  // why it failed: the render's last message (of its --progress json line)
};

// What one line of a render's standard error (--progress json) says: a progress line's frame
// counts, or any other line's message (an error or warning line's own, or the line itself).
struct VideoProgressLine {
    std::optional<int> done, total;  // a progress line's frames_done and frames
    std::optional<int> frame;        // the frame it is on, from 1
    std::string message;             // another line's text, printable and shortened; "" for none
    bool warning = false;            // a warning line (its message goes to the viewer's terminal)
};

// Reads one line as above. A progress line whose counts are not whole numbers from 0 is read as
// any other line: the watcher of a render, a thread of its own, has nowhere to throw to, and one
// malformed line must not end the viewer. Throws nothing but std::bad_alloc.
VideoProgressLine read_video_progress_line(const std::string& line);

class VideoJobs {
public:
    // `render_arguments` are passed to every render after the scene and the video (device,
    // threads, precision, ...).
    explicit VideoJobs(std::vector<std::string> render_arguments);
    ~VideoJobs();  // stop()s
    VideoJobs(const VideoJobs&) = delete;
    VideoJobs& operator=(const VideoJobs&) = delete;

    // The one video's place, held from before its scene is written until its render starts,
    // so that a second request meanwhile is refused before it writes anything. Given back
    // when dropped unstarted (the scene could not be written, say).
    class Place {
    public:
        Place(Place&& other) noexcept : owner_(std::exchange(other.owner_, nullptr)) {}
        Place& operator=(Place&&) = delete;
        ~Place();

    private:
        friend class VideoJobs;
        explicit Place(VideoJobs& owner) : owner_(&owner) {}
        VideoJobs* owner_;  // null once started or moved from
    };

    // The place for a video; nullopt while another renders or holds its place.
    std::optional<Place> reserve();

    // Starts rendering `scene_path`, whose text is `scene_text`, to `video_path` in `place`;
    // returns the job's id. The render is handed the text (kSceneOnStdinVariable), not the
    // file's name to read again. Throws OutputError when the render cannot start (the place is
    // given back).
    int start(Place&& place, const std::string& scene_path, const std::string& scene_text,
              const std::string& video_path);

    // The job's state; nullopt for an id that names no job.
    std::optional<VideoJobState> state(int id) const;

    // The session's last job's state (a page loaded again follows a video that renders);
    // nullopt before the first.
    std::optional<VideoJobState> latest() const;

    // Stops a running render (it removes its unfinished files) and waits for it.
    void stop();

private:
    void watch(int read_fd);
    // Takes one line of the render's standard error into the job's state; `last_message` is
    // the last message, the failed job's error.
    void take_progress_line(const std::string& line, std::string& last_message);

    std::vector<std::string> render_arguments_;
    mutable std::mutex mutex_;
    std::vector<VideoJobState> jobs_;  // every job of the session, by id - 1
    std::unique_ptr<class ChildProcess> child_;
    std::thread watcher_;
    bool running_ = false;
    bool reserved_ = false;  // a Place is held
    bool stopping_ = false;
};

// The name of clrender's own program (the target of /proc/self/exe), which renders the videos:
// what the render's process is called. The program run is /proc/self/exe itself
// (kOwnProgram).
std::string clrender_program_path();

// The running program, as the kernel keeps it: also once its file has been replaced (a rebuild,
// an install or an upgrade renames a new file over the old name) or removed, where its name
// leads to another program or to none. The video then renders with the clrender that serves
// the page.
inline constexpr const char* kOwnProgram = "/proc/self/exe";

}  // namespace clr
