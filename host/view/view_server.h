// The viewer's server from start to stop: it listens (--bind, --port), prints the one line
// with its address and token, opens the browser, and serves until SIGINT, SIGTERM or SIGHUP;
// then it stops accepting, finishes or drops the requests in flight, stops a video render,
// joins its threads and returns. Requests are served by a bounded pool of threads with read
// and write timeouts and limits on a request's head, body and time (view/bounded_server), so
// that many tabs, a client that disconnects, a slow reader or one that never ends its request
// cannot stall the others or fill the memory.
#pragma once

#include <string>

#include "view/view_routes.h"

namespace clr {

struct ServerSettings {
    std::string bind = "127.0.0.1";
    int port = 0;             // 0: a free port
    bool open_browser = true;
};

// Threads that serve requests: connections beyond this wait for one. Each tab of the page keeps
// a few connections open between frames (keep-alive), ten tabs a few dozen.
constexpr int kServerThreads = 32;
// Longest wait for a client's next bytes or for it to take ours.
constexpr int kClientTimeoutSeconds = 5;
// Longest an idle kept-alive connection keeps its thread.
constexpr int kKeepAliveSeconds = 2;
// Requests one kept-alive connection serves before it is closed.
constexpr std::size_t kKeepAliveRequests = 10000;
// Largest request body (the camera keys of an export: about 100 bytes a key).
constexpr std::size_t kMostRequestBytes = 2 * 1024 * 1024;

// Serves until a signal arrives, then throws Interrupted (exit 128 + signal); the requests are
// guarded for the port actually bound. Throws UsageError when the address cannot be
// bound, OutputError when the line with the address cannot be printed and no browser is
// opened with it.
[[noreturn]] void serve_view(const ServerSettings& settings, const std::string& token, const Scene& scene,
                             RenderService& renderer, const PathExporter& exporter, VideoJobs& videos);

}  // namespace clr
