#include "core/parallel_for.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <vector>

#include "core/worker_threads.h"

namespace clr {

void parallel_for(std::size_t count, std::size_t threads, const std::function<void(std::size_t)>& work) {
    if (count == 0) return;
    std::vector<std::exception_ptr> errors(count);
    std::atomic<std::size_t> next{0};
    auto worker = [&] {
        for (std::size_t i; (i = next++) < count;) {
            try {
                work(i);
            } catch (...) {
                errors[i] = std::current_exception();
            }
        }
    };
    const std::size_t helpers = std::min(std::max<std::size_t>(threads, 1), count) - 1;
    if (helpers == 0)
        worker();
    else
        WorkerThreads::shared().run(helpers, worker);
    for (const std::exception_ptr& error : errors) {
        if (error) std::rethrow_exception(error);
    }
}

}  // namespace clr
