// The threads that the scene loader's parallel loops run on (image headers, cache reads and
// decoding), started once and reused. Why not a thread per loop: creating a thread takes the
// dynamic loader's TLS lock, which the OpenCL driver's dlopen (PoCL and LLVM, tens of
// milliseconds, on the device listing thread) holds, so a loop starting its threads then waited
// for the whole driver load before reading a single image. run() starts them before the device
// listing begins (docs/benchmarks.md, Against POV-Ray); elsewhere the first loop starts them.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <mutex>
#include <vector>

namespace clr {

class WorkerThreads {
public:
    // The process's one set; never destroyed (idle threads end with the process).
    static WorkerThreads& shared();

    // At most this many threads are ever started, whatever a caller asks for.
    static constexpr std::size_t kMostThreads = 256;

    // Starts threads until `count` (at most kMostThreads) are running; fewer when the system refuses one (a process
    // limit, no memory for a stack): callers then share the work with fewer.
    void start(std::size_t count);

    // Calls `task` on the calling thread and on up to `helpers` started threads at once, and
    // returns when every call has returned. `task` must not throw. A second caller while one
    // runs (or a task calling it) gets no helpers: its task runs on its own thread only.
    void run(std::size_t helpers, const std::function<void()>& task);

private:
    WorkerThreads() = default;
    void start_more(std::size_t count);  // start(), busy_ held
    // Thread `index` waits for each run() after generation `seen` and takes part if asked.
    void serve(std::size_t index, std::uint64_t seen);

    std::mutex busy_;  // one run() at a time uses the threads
    std::mutex mutex_;
    std::condition_variable wake_, done_;
    std::size_t started_ = 0;
    std::uint64_t generation_ = 0;  // counts run()s, so that a thread takes each task once
    std::size_t helpers_ = 0;       // how many of the threads take part in this run()
    std::size_t unfinished_ = 0;
    const std::function<void()>* task_ = nullptr;
};

}  // namespace clr
