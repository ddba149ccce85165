#include "app/frame_sink.h"

#include <chrono>

#include "core/interruption.h"
#include "core/stopwatch.h"
#include "output/image_writer.h"

namespace clr {
namespace {

constexpr std::size_t kMaxQueuedFrames = 2;  // bounds memory: a 4K frame is 33 MB

// How often a wait for the worker looks for a signal: a stalled encoder must not keep
// Ctrl-C from stopping clrender.
constexpr std::chrono::milliseconds kInterruptionCheck{100};

}  // namespace

FrameSink::FrameSink(const OutputPlan& plan, int width, int height, double fps, int quality, StagedOutputs& staged,
                     std::function<ImageText(int frame)> describe)
    : plan_(plan), staged_(staged), describe_(std::move(describe)) {
    if (!plan_.video_path.empty()) {
        VideoSettings settings;
        settings.path = plan_.video_path;
        settings.width = width;
        settings.height = height;
        settings.fps = fps;
        settings.quality = quality;
        encoder_ = std::make_unique<VideoEncoder>(settings, plan_.encoder);
    }
    worker_ = std::thread([this] { work(); });
}

FrameSink::~FrameSink() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        closing_ = true;
        queue_.clear();
    }
    changed_.notify_all();
    // A worker waiting on a stalled encoder gives up within a slice instead of at the stall
    // timeout (nothing happens if the video is finished).
    if (encoder_) encoder_->cancel();
    if (worker_.joinable()) worker_.join();
}

void FrameSink::push(int frame, Image image, bool on_disk) {
    std::unique_lock<std::mutex> lock(mutex_);
    while (!changed_.wait_for(lock, kInterruptionCheck, [this] { return queue_.size() < kMaxQueuedFrames || error_; }))
        throw_if_interrupted();
    if (error_) std::rethrow_exception(error_);
    queue_.push_back({frame, std::move(image), on_disk});
    changed_.notify_all();
}

void FrameSink::finish() {
    {
        std::unique_lock<std::mutex> lock(mutex_);
        closing_ = true;
    }
    changed_.notify_all();
    worker_.join();
    rethrow_worker_error();
    if (encoder_) staged_.add(encoder_->finish_uncommitted());  // renamed with the --stats report
}

void FrameSink::rethrow_worker_error() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (error_) std::rethrow_exception(error_);
}

void FrameSink::work() {
    for (;;) {
        QueuedFrame item;
        {
            std::unique_lock<std::mutex> lock(mutex_);
            changed_.wait(lock, [this] { return !queue_.empty() || closing_; });
            if (queue_.empty()) return;  // closing and drained
            item = std::move(queue_.front());
            queue_.pop_front();
        }
        changed_.notify_all();
        try {
            consume(item);
            std::lock_guard<std::mutex> lock(mutex_);
            finished_ = std::move(item.image);  // its storage can take a later frame
        } catch (...) {
            std::lock_guard<std::mutex> lock(mutex_);
            error_ = std::current_exception();
            queue_.clear();
            changed_.notify_all();
            return;
        }
    }
}

std::optional<Image> FrameSink::take_finished() {
    std::lock_guard<std::mutex> lock(mutex_);
    std::optional<Image> image = std::move(finished_);
    finished_.reset();
    return image;
}

void FrameSink::consume(const QueuedFrame& item) {
    const Stopwatch write_time;
    if (!plan_.image_target.empty() && !item.on_disk) {
        const std::string path = plan_.image_path(item.frame);
        const ImageText text = describe_ ? describe_(item.frame) : ImageText{};
        if (plan_.image_waits_for_stats()) {
            staged_.add(write_image_uncommitted(path, item.image, text));
        } else {
            write_image(path, item.image, text);
            ++frames_in_place_;
        }
    }
    if (encoder_) encoder_->add_frame(item.image);
    write_ms_ += write_time.elapsed_ms();
}

}  // namespace clr
