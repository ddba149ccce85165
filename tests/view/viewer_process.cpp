#include "view/viewer_process.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <regex>
#include <thread>

#include "support/temp_folder.h"

extern char** environ;

namespace clr::testing {

ViewerProcess::ViewerProcess(const std::string& arguments, const std::string& folder, const std::string& environment,
                             bool open_browser, const std::string& program)
    : folder_(folder) {
    int fds[2];
    if (::pipe(fds) != 0) return;
    // Through the shell, for the folder and the arguments' quoting; exec keeps the pid clrender's.
    const std::string command = "cd '" + folder + "' && " + environment + " exec '" + (program.empty() ? std::string(CLRENDER_BINARY) : program) + "' view " +
                                arguments + (open_browser ? "" : " --no-browser") + " --port 0 2> view-stderr.txt";
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[1], STDOUT_FILENO);
    posix_spawn_file_actions_addclose(&actions, fds[0]);
    posix_spawn_file_actions_addclose(&actions, fds[1]);
    const char* argv[] = {"/bin/sh", "-c", command.c_str(), nullptr};
    if (::posix_spawn(&pid_, "/bin/sh", &actions, nullptr, const_cast<char**>(argv), environ) != 0) pid_ = -1;
    posix_spawn_file_actions_destroy(&actions);
    ::close(fds[1]);
    if (pid_ <= 0) {
        ::close(fds[0]);
        return;
    }
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::minutes(2);
    std::string text;
    while (text.find('\n') == std::string::npos && std::chrono::steady_clock::now() < give_up) {
        pollfd ready{fds[0], POLLIN, 0};
        if (::poll(&ready, 1, 200) <= 0) continue;
        char buffer[512];
        const ssize_t got = ::read(fds[0], buffer, sizeof buffer);
        if (got <= 0) break;  // exited before printing
        text.append(buffer, static_cast<std::size_t>(got));
    }
    ::close(fds[0]);  // nothing more is printed to standard output
    line_ = text.substr(0, text.find('\n'));
    std::smatch match;
    static const std::regex address(R"(clrender: view at http://127\.0\.0\.1:(\d+)/\?token=([0-9a-f]{32}))");
    if (std::regex_match(line_, match, address)) {
        port_ = std::stoi(match[1]);
        token_ = match[2];
    }
}

ViewerProcess::~ViewerProcess() {
    if (pid_ > 0) {
        ::kill(pid_, SIGKILL);
        ::waitpid(pid_, nullptr, 0);
    }
}

std::unique_ptr<httplib::Client> ViewerProcess::client() const {
    auto client = std::make_unique<httplib::Client>("127.0.0.1", port_);
    client->set_read_timeout(120, 0);
    client->set_connection_timeout(10, 0);
    return client;
}

std::string ViewerProcess::with_token(const std::string& path_and_query) const {
    return path_and_query + (path_and_query.find('?') == std::string::npos ? "?" : "&") + "token=" + token_;
}

int ViewerProcess::stop(int signal, int seconds) {
    if (pid_ <= 0) return -1;
    ::kill(pid_, signal);
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(seconds);
    while (std::chrono::steady_clock::now() < give_up) {
        int status = 0;
        if (::waitpid(pid_, &status, WNOHANG) == pid_) {
            pid_ = -1;
            return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status) + 1000;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return -1;
}

std::string ViewerProcess::output() const { return line_ + "\n" + read_bytes(folder_ + "/view-stderr.txt"); }

}  // namespace clr::testing
