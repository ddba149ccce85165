// Where finished frames go: their image files and the video. A worker thread does the
// writing and encoding, so that writing frame N overlaps with rendering frame N+1.
#pragma once

#include <atomic>
#include <condition_variable>
#include <deque>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>

#include "app/output_plan.h"
#include "core/image.h"
#include "output/image_writer.h"
#include "output/staged_outputs.h"
#include "output/video_encoder.h"

namespace clr {

class FrameSink {
public:
    // Starts the encoder (when the plan has a video) for frames of width x height. A single
    // image file (plan.image_waits_for_stats()) goes to `staged`, written but not yet renamed.
    // `describe` gives the text that a frame's PNG carries (frame_description.h); none when empty.
    FrameSink(const OutputPlan& plan, int width, int height, double fps, int quality, StagedOutputs& staged,
              std::function<ImageText(int frame)> describe = nullptr);
    // Stops the worker; an unfinished video is abandoned and leaves no file behind.
    ~FrameSink();
    FrameSink(const FrameSink&) = delete;
    FrameSink& operator=(const FrameSink&) = delete;

    // Hands a frame over; waits while the worker is still busy with two. Rethrows an error
    // the worker met (the render then stops), and throws Interrupted on a signal while it
    // waits. `on_disk`: the frame's image file exists already (--resume, --assemble) and only
    // goes to the video.
    void push(int frame, Image image, bool on_disk = false);
    // Writes what is queued and completes and checks the video, which goes to `staged` (renamed
    // into place with the --stats report, so a failed stats write leaves the earlier video). Rethrows errors;
    // every wait in it ends on a signal (the worker's and the encoder's waits check too).
    void finish();

    double write_ms() const { return write_ms_; }  // worker time spent writing and encoding
    // Frames of an -o pattern whose files the worker has renamed into place so far (a still's
    // image and a video are in place only once the run renames them: StagedOutputs).
    int frames_in_place() const { return frames_in_place_.load(); }

    // A frame the worker has written and encoded, if one is done since the last call: its
    // storage can be recycled for a later frame: a new image costs a page fault and a zero fill
    // per page (docs/benchmarks.md, Figures behind design choices).
    std::optional<Image> take_finished();

private:
    void work();
    struct QueuedFrame {
        int frame = 0;
        Image image;
        bool on_disk = false;
    };
    void consume(const QueuedFrame& item);
    void rethrow_worker_error();

    const OutputPlan& plan_;
    StagedOutputs& staged_;
    std::function<ImageText(int frame)> describe_;
    std::unique_ptr<VideoEncoder> encoder_;
    std::deque<QueuedFrame> queue_;
    std::mutex mutex_;
    std::condition_variable changed_;
    bool closing_ = false;
    std::exception_ptr error_;
    std::optional<Image> finished_;
    double write_ms_ = 0;
    std::atomic<int> frames_in_place_{0};
    std::thread worker_;
};

}  // namespace clr
