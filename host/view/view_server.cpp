#include "view/view_server.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <thread>

#include "app/standard_output.h"
#include "core/errors.h"
#include "core/interruption.h"
#include "core/printable_text.h"
#include "view/bounded_server.h"
#include "view/opener_page.h"
#include "view/scene_summary.h"
#include "view/socket_address.h"

extern char** environ;

namespace clr {
namespace {

// Opens `target` with xdg-open, in a session of its own so that the browser it starts is not
// ours to stop. Returns its pid, or -1 (with a warning) when it cannot start.
pid_t open_browser(const std::string& target) {
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addclosefrom_np(&actions, STDERR_FILENO + 1);
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    sigset_t signals;
    sigemptyset(&signals);
    posix_spawnattr_setsigmask(&attributes, &signals);
    sigaddset(&signals, SIGPIPE);
    posix_spawnattr_setsigdefault(&attributes, &signals);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSID);
    pid_t pid = -1;
    const char* argv[] = {"xdg-open", target.c_str(), nullptr};
    const int error = ::posix_spawnp(&pid, "xdg-open", &actions, &attributes, const_cast<char**>(argv), environ);
    posix_spawnattr_destroy(&attributes);
    posix_spawn_file_actions_destroy(&actions);
    if (error != 0) {
        std::cerr << "clrender: warning: cannot open the browser (xdg-open: " << std::strerror(error)
                  << "); open the address above yourself\n";
        return -1;
    }
    return pid;
}

// Reaps xdg-open once it has exited; warns when it failed. Never blocks.
void reap_browser_opener(pid_t& pid) {
    if (pid <= 0) return;
    int status = 0;
    if (::waitpid(pid, &status, WNOHANG) != pid) return;
    pid = -1;
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        std::cerr << "clrender: warning: xdg-open could not open the browser; open the address above yourself\n";
}

// `listening` gets the listening socket, for the backlog and the address it is bound to (see
// serve_view).
void configure(httplib::Server& server, int& listening) {
    server.set_read_timeout(kClientTimeoutSeconds, 0);
    server.set_write_timeout(kClientTimeoutSeconds, 0);
    server.set_keep_alive_timeout(kKeepAliveSeconds);
    // The live view asks for frame after frame on one connection; a new connection every few
    // frames (cpp-httplib's default is 5 requests) would cost a handshake each time.
    server.set_keep_alive_max_count(kKeepAliveRequests);
    server.set_payload_max_length(kMostRequestBytes);
    // The listening socket is reused at once after a restart, and stays out of the children
    // (a video render) that the server starts.
    server.set_socket_options([&listening](socket_t socket) {
        listening = socket;
        int yes = 1;
        ::setsockopt(socket, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
        ::fcntl(socket, F_SETFD, FD_CLOEXEC);
    });
}

// Whether the request's Content-Length (given once, digits, at most kMostRequestBytes) is one
// the server reads.
bool body_length_allowed(const httplib::Request& request) {
    const std::optional<std::size_t> length = declared_body_length(request);
    return request.has_header("Content-Length") && length && *length <= kMostRequestBytes;
}

// `host` is the address the printed line names (url_host).
void warn_about_bind(const std::string& bind, const std::string& host) {
    if (bind == "127.0.0.1") return;
    if (bind == "localhost")
        std::cerr << "clrender: warning: --bind localhost: listening on " << printable(host)
                  << " only, the address printed (a browser may look localhost up as another address)\n";
    else if (is_loopback_address(bind))
        std::cerr << "clrender: warning: --bind " << printable(bind) << ": listening on " << printable(bind)
                  << " rather than 127.0.0.1\n";
    else
        std::cerr << "clrender: warning: --bind " << printable(bind)
                  << ": the viewer listens beyond this machine; anyone who can reach it and learns the address "
                     "(with its token) can drive it\n";
}

}  // namespace

void serve_view(const ServerSettings& settings, const std::string& token, const Scene& scene, RenderService& renderer,
                const PathExporter& exporter, VideoJobs& videos) {
    AnswerBudget answers;  // before the server: its answers hold parts of it until they are sent
    BoundedServer server(kServerThreads);  // cpp-httplib's, with limits on a request's head and time
    int listening = -1;
    configure(server, listening);
    const std::string bind_address =
        settings.bind.size() >= 2 && settings.bind.front() == '[' ? settings.bind.substr(1, settings.bind.size() - 2) : settings.bind;
    int port = settings.port;
    if (port == 0)
        port = server.bind_to_any_port(bind_address);
    else if (!server.bind_to_port(bind_address, port))
        port = -1;
    const int bind_error = errno;
    if (port <= 0)
        throw UsageError("cannot listen on " + printable(settings.bind) + " port " + std::to_string(settings.port) +
                         (settings.port ? " (in use? --port 0 picks a free one)" : "") + ": " + std::strerror(bind_error));
    // cpp-httplib listens with a backlog of 5: ten tabs connecting at once would see their
    // connections dropped and retried a second later. The backlog is raised on the same socket.
    if (listening >= 0) ::listen(listening, SOMAXCONN);
    // The line names the address bound, not the --bind value: cpp-httplib binds a name's first
    // address only (localhost: 127.0.0.1), and a browser given the name may try another first.
    const std::optional<SocketAddress> bound = listening >= 0 ? local_address_of(listening) : std::nullopt;
    const std::string host = url_host(bound ? bound->ip : bind_address);
    warn_about_bind(settings.bind, host);
    const RequestGuard guard(token, settings.bind, port);
    ViewSession session{scene, renderer, exporter, videos, guard, answers,
                        std::make_shared<const std::string>(scene_summary_json(scene))};
    add_view_routes(server, session);
    server.set_answer_headers(view_answer_headers());  // on every answer, refusals included
    // A client that asks before sending its body (Expect: 100-continue) is invited only when
    // the request may be served: cpp-httplib would invite any, a foreign page's or one whose
    // Content-Length is over the limit, and then read the body it invited.
    server.set_expect_100_continue_handler([&guard](const httplib::Request& request, httplib::Response& response) {
        if (guard.check(request_facts(request)) == RequestVerdict::Forbidden)
            response.status = 403;
        else if (refused_body_format(request, response))
            return response.status;  // 415, as the routes answer it, with its Connection: close
        else if (request.has_header("Transfer-Encoding") || !request.has_header("Content-Length"))
            response.status = 411;  // as the routes answer it (view_routes.cpp)
        else if (!declared_body_length(request))
            response.status = 400;  // no clear length (view_routes.cpp)
        else if (!body_length_allowed(request))
            response.status = 413;
        else
            return 100;
        response.set_header("Connection", "close");
        return response.status;
    });

    std::atomic<bool> listener_ended{false};
    std::thread listener([&server, &listener_ended] {
        server.listen_until_stopped();
        listener_ended = true;
    });
    // Until the listener runs, Server::stop() would do nothing and the join below would wait
    // forever: a signal right after the line is printed must still stop the server.
    while (!server.is_running() && !listener_ended) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    if (listener_ended) {
        listener.join();
        throw UsageError("cannot listen on " + printable(settings.bind) + " port " + std::to_string(port));
    }
    const std::string url = "http://" + host + ":" + std::to_string(port) + "/?token=" + token;
    std::cout << "clrender: view at " << url << "\n";
    const std::string unprinted = flush_standard_output();  // "" when the line was written
    // xdg-open gets a page that only this user can read, which forwards the browser to the
    // address: never the address itself, whose token every user could read in its arguments.
    std::string why;
    const std::optional<OpenerPage> page = settings.open_browser ? OpenerPage::write(url, why) : std::nullopt;
    // The line lost (a full disk, a closed pipe or standard output) and no browser given the
    // address: nothing could ever reach the viewer, so it does not serve on in silence.
    if (!unprinted.empty() && !page) {
        server.stop();
        listener.join();
        throw OutputError("standard output: cannot write the viewer's address (" + unprinted + ")" +
                          (settings.open_browser ? "; the browser cannot be opened with it either (" + printable(why) + ")"
                                                 : "; with --no-browser nothing else would show it"));
    }
    if (!unprinted.empty())
        std::cerr << "clrender: warning: standard output: cannot write the viewer's address (" << unprinted
                  << "); the browser is opened with it all the same\n";
    pid_t opener = -1;
    if (settings.open_browser) {
        if (page)
            opener = open_browser(page->path());
        else
            std::cerr << "clrender: warning: cannot open the browser (" << printable(why)
                      << "); open the address above yourself\n";
    }
    while (!interruption_requested()) {
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        reap_browser_opener(opener);
    }
    // Stop accepting and close the connections; requests in flight end (a frame stops within
    // a band once the signal is seen), the pool's threads are joined.
    server.stop();
    listener.join();
    videos.stop();
    throw_if_interrupted();
    throw std::logic_error("the viewer stopped without a signal");
}

}  // namespace clr
