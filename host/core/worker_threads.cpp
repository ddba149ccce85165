#include "core/worker_threads.h"

#include <algorithm>
#include <system_error>
#include <thread>

namespace clr {

WorkerThreads& WorkerThreads::shared() {
    static WorkerThreads* const threads = new WorkerThreads();  // threads still wait on it at exit
    return *threads;
}

void WorkerThreads::start(std::size_t count) {
    std::lock_guard<std::mutex> busy(busy_);
    start_more(count);
}

void WorkerThreads::start_more(std::size_t count) {
    count = std::min(count, kMostThreads);
    for (std::size_t index = started_; index < count; ++index) {
        std::uint64_t now = 0;
        {
            std::lock_guard<std::mutex> lock(mutex_);
            now = generation_;  // not read by the thread itself: a run() may begin before it does
        }
        try {
            std::thread([this, index, now] { serve(index, now); }).detach();
        } catch (const std::system_error&) {
            return;  // no more threads: those started share the work
        }
        std::lock_guard<std::mutex> lock(mutex_);
        started_ = index + 1;
    }
}

void WorkerThreads::run(std::size_t helpers, const std::function<void()>& task) {
    std::unique_lock<std::mutex> busy(busy_, std::try_to_lock);
    std::size_t taking_part = 0;
    if (busy.owns_lock()) {
        start_more(helpers);
        std::lock_guard<std::mutex> lock(mutex_);
        taking_part = std::min(helpers, started_);  // fewer where the system refused threads
        helpers_ = taking_part;
        unfinished_ = taking_part;
        task_ = &task;
        ++generation_;
    }
    if (taking_part > 0) wake_.notify_all();
    task();
    if (taking_part == 0) return;
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [this] { return unfinished_ == 0; });
    task_ = nullptr;
}

void WorkerThreads::serve(std::size_t index, std::uint64_t seen) {
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
        wake_.wait(lock, [&] { return generation_ != seen; });
        seen = generation_;
        if (index >= helpers_) continue;
        const std::function<void()>* task = task_;
        lock.unlock();
        (*task)();
        lock.lock();
        if (--unfinished_ == 0) done_.notify_all();
    }
}

}  // namespace clr
