#include "app/frame_sink.h"

#include <chrono>

#include "output/image_writer.h"

namespace clr {
namespace {

constexpr std::size_t kMaxQueuedFrames = 2;  // bounds memory: a 4K frame is 33 MB

}  // namespace

FrameSink::FrameSink(const OutputPlan& plan, int width, int height, double fps, int quality) : plan_(plan) {
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
    if (worker_.joinable()) worker_.join();
}

void FrameSink::push(int frame, Image image) {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [this] { return queue_.size() < kMaxQueuedFrames || error_; });
    if (error_) std::rethrow_exception(error_);
    queue_.emplace_back(frame, std::move(image));
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
    if (encoder_) encoder_->finish();
}

void FrameSink::rethrow_worker_error() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (error_) std::rethrow_exception(error_);
}

void FrameSink::work() {
    for (;;) {
        std::pair<int, Image> item;
        {
            std::unique_lock<std::mutex> lock(mutex_);
            changed_.wait(lock, [this] { return !queue_.empty() || closing_; });
            if (queue_.empty()) return;  // closing and drained
            item = std::move(queue_.front());
            queue_.pop_front();
        }
        changed_.notify_all();
        try {
            consume(item.first, item.second);
        } catch (...) {
            std::lock_guard<std::mutex> lock(mutex_);
            error_ = std::current_exception();
            queue_.clear();
            changed_.notify_all();
            return;
        }
    }
}

void FrameSink::consume(int frame, const Image& image) {
    auto start = std::chrono::steady_clock::now();
    if (!plan_.image_target.empty() && !plan_.assemble) write_image(plan_.image_path(frame), image);
    if (encoder_) encoder_->add_frame(image);
    write_ms_ += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace clr
