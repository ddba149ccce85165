// Loops whose iterations are independent, on the process's worker threads
// (core/worker_threads.h): the scene loader's image reads, the screen tiles' binning.
#pragma once

#include <cstddef>
#include <functional>

namespace clr {

// Runs work(0) .. work(count - 1), each once, on the calling thread and up to `threads` - 1
// worker threads, which take the indices in turn; returns when every call has returned, then
// rethrows the first exception (in index order), e.g. out of memory. With `threads` <= 1,
// where no thread could be started, or while another loop has the threads, the calling thread
// does all the work: slower, the same result.
void parallel_for(std::size_t count, std::size_t threads, const std::function<void(std::size_t)>& work);

}  // namespace clr
