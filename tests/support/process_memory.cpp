#include "support/process_memory.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

namespace clr::testing {

long resident_mib(pid_t pid) {
    std::ifstream status("/proc/" + std::to_string(pid) + "/status");
    for (std::string line; std::getline(status, line);) {
        if (line.rfind("VmRSS:", 0) != 0) continue;
        std::istringstream fields(line.substr(6));
        long kib = 0;
        fields >> kib;
        return kib / 1024;
    }
    return 0;
}

long rise_during(pid_t pid, const std::function<void()>& work) {
    const long before = resident_mib(pid);
    std::atomic<long> peak{before};
    std::atomic<bool> done{false};
    std::thread watcher([&] {
        while (!done) {
            peak = std::max(peak.load(), resident_mib(pid));
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
    });
    work();
    done = true;
    watcher.join();
    return peak - before;
}

}  // namespace clr::testing
