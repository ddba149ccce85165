// Why a process group and WNOWAIT: the program's own process group holds it and everything it
// starts (a shell script's children, for example). Signalling the group stops them all. The
// group's id stays reserved while its leader is unreaped, so the group is signalled before
// the leader is reaped: a later, unrelated process can never receive the signal.
#include "output/child_process.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <thread>

#include "core/interruption.h"
#include "core/errors.h"

extern char** environ;

namespace clr {
namespace {

void connect(posix_spawn_file_actions_t& actions, int fd, int target, int mode_without_fd) {
    if (fd >= 0)
        posix_spawn_file_actions_adddup2(&actions, fd, target);
    else
        posix_spawn_file_actions_addopen(&actions, target, "/dev/null", mode_without_fd, 0);
}

}  // namespace

ChildProcess::ChildProcess(const std::vector<std::string>& arguments, int stdin_fd, int stdout_fd, int stderr_fd,
                           const std::string& program, const std::vector<std::string>& more_environment) {
    std::vector<char*> argv;
    for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
    argv.push_back(nullptr);
    std::vector<char*> environment;
    for (char** entry = environ; *entry; ++entry) environment.push_back(*entry);
    for (const std::string& entry : more_environment) environment.push_back(const_cast<char*>(entry.c_str()));
    environment.push_back(nullptr);

    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    connect(actions, stdin_fd, STDIN_FILENO, O_RDONLY);
    connect(actions, stdout_fd, STDOUT_FILENO, O_WRONLY);
    connect(actions, stderr_fd, STDERR_FILENO, O_WRONLY);
    // Nothing else of clrender's: a descriptor opened without O_CLOEXEC (a library's socket,
    // such as the viewer's connections) would otherwise stay open for as long as the child runs.
    posix_spawn_file_actions_addclosefrom_np(&actions, STDERR_FILENO + 1);

    // The child starts with default signal handling and nothing blocked, whatever clrender
    // (which ignores SIGPIPE) or its render threads have set.
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    sigset_t signals;
    sigemptyset(&signals);
    posix_spawnattr_setsigmask(&attributes, &signals);
    sigaddset(&signals, SIGPIPE);
    posix_spawnattr_setsigdefault(&attributes, &signals);
    // Its own process group: Ctrl-C at the terminal then reaches clrender alone, which stops
    // the child itself and removes its files, instead of the child dying first and the
    // interruption looking like its failure.
    posix_spawnattr_setpgroup(&attributes, 0);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETPGROUP);

    const int error = ::posix_spawn(&pid_, program.empty() ? argv[0] : program.c_str(), &actions, &attributes,
                                    argv.data(), environment.data());
    posix_spawnattr_destroy(&attributes);
    posix_spawn_file_actions_destroy(&actions);
    if (error != 0) {
        pid_ = -1;
        throw OutputError("cannot start '" + arguments[0] + "': " + std::strerror(error));
    }
    track_child_group(pid_);  // killed by a forced stop (core/interruption.h)
}

ChildProcess::~ChildProcess() { stop(); }

bool ChildProcess::has_exited() const {
    siginfo_t info;
    std::memset(&info, 0, sizeof info);
    if (::waitid(P_PID, static_cast<id_t>(pid_), &info, WEXITED | WNOHANG | WNOWAIT) != 0) {
        // ECHILD: reaped already (only if someone set SIGCHLD to SIG_IGN); EINTR: ask again later.
        return errno == ECHILD;
    }
    return info.si_pid != 0;
}

std::optional<int> ChildProcess::poll_exit() {
    if (pid_ <= 0) return 0;
    if (!has_exited()) return std::nullopt;
    return reap();
}

int ChildProcess::reap() noexcept {
    ::killpg(pid_, SIGKILL);  // what the program left running; its zombie keeps the group id ours
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0) {
        if (errno != EINTR) {
            status = 0;  // reaped already: the status is lost (callers check the output itself)
            break;
        }
    }
    untrack_child_group(pid_);
    pid_ = -1;
    return status;
}

int ChildProcess::stop(std::chrono::milliseconds grace) noexcept {
    if (pid_ <= 0) return 0;
    ::killpg(pid_, SIGTERM);
    const auto give_up = std::chrono::steady_clock::now() + grace;
    int slice_ms = 1;
    while (!has_exited() && std::chrono::steady_clock::now() < give_up) sleep_a_slice(slice_ms);
    return reap();  // SIGKILLs the group first, so the wait cannot block for long
}

std::string describe_exit(const std::string& program, int status) {
    if (WIFEXITED(status)) return "'" + program + "' exited with status " + std::to_string(WEXITSTATUS(status));
    if (WIFSIGNALED(status)) {
        return "'" + program + "' was killed by signal " + std::to_string(WTERMSIG(status)) + " (" +
               strsignal(WTERMSIG(status)) + ")";
    }
    return "'" + program + "' stopped with wait status " + std::to_string(status);
}

void sleep_a_slice(int& slice_ms) {
    std::this_thread::sleep_for(std::chrono::milliseconds(slice_ms));
    slice_ms = std::min(slice_ms * 2, 100);
}

}  // namespace clr
