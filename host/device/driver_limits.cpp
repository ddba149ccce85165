#include "device/driver_limits.h"

#include <dirent.h>
#include <fcntl.h>
#include <pthread.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fstream>

#include "core/interruption.h"
#include "core/message_lines.h"

namespace clr {
namespace {

// PoCL's compiler, its ld and the dlopen of the result take this many descriptors beyond those
// clrender holds: a cold build failed or aborted with `ulimit -n` 5 to 14 and passed from 15 (5 in use before the driver loads).
constexpr long kDescriptorsForTheDriver = 10;

std::string mebibytes(std::uint64_t bytes) { return std::to_string(bytes >> 20) + " MiB"; }

long descriptors_in_use() {
    DIR* folder = ::opendir("/proc/self/fd");
    if (!folder) return 0;
    long count = -1;  // the listing's own descriptor
    while (::readdir(folder)) ++count;
    ::closedir(folder);
    return count - 2;  // "." and ".."
}

std::optional<long> descriptor_limit() {
    struct rlimit limit;
    if (::getrlimit(RLIMIT_NOFILE, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return std::nullopt;
    return static_cast<long>(limit.rlim_cur);
}

bool too_few_descriptors() {
    const std::optional<long> limit = descriptor_limit();
    return limit && *limit - descriptors_in_use() < kDescriptorsForTheDriver;
}

std::string address_space_text(std::uint64_t limit) {
    return "the address space is limited to " + mebibytes(limit) + " (ulimit -v " + std::to_string(limit >> 10) +
           "), and PoCL needs about " + mebibytes(kAddressSpaceForABuild) +
           " more than clrender's own to build the kernels: allow more, or unset the limit";
}

std::string descriptor_text() {
    return "too few file descriptors: the limit is " + std::to_string(descriptor_limit().value_or(0)) +
           " (ulimit -n) and " + std::to_string(descriptors_in_use()) + " are in use; PoCL's compiler needs about " +
           std::to_string(kDescriptorsForTheDriver) + " more";
}

// The deepest folder of `path` that exists, or "" when a part of it is not a folder.
std::string existing_folder_of(std::string path) {
    while (!path.empty()) {
        struct stat info;
        if (::stat(path.c_str(), &info) == 0) return S_ISDIR(info.st_mode) ? path : "";
        const std::size_t slash = path.find_last_of('/');
        if (slash == std::string::npos) return ".";
        path = slash == 0 ? "/" : path.substr(0, slash);
    }
    return "";
}

// Whether PoCL can make and write its cache folder (access() answers for root too on a
// read-only file system).
bool cache_folder_writable(const std::string& path) {
    const std::string folder = existing_folder_of(path);
    return !folder.empty() && ::access(folder.c_str(), W_OK | X_OK) == 0;
}

bool pocl_kernel_cache_off() {
    const char* setting = std::getenv("POCL_KERNEL_CACHE");
    return setting && std::string(setting) == "0";
}

// The crash diagnosis: the line and exit code, made before the driver loads, since a signal
// handler may only write() and _exit().
// One whole line per signal named (SIGSEGV, SIGABRT, any other), text or JSON.
char crash_lines[3][1200];
int crash_exit_code = kExitInternal;
// Standard error as it was before the driver loaded: a build holds it in a capture
// (device/stderr_capture.h), and a crash there must still be seen.
int crash_stderr = STDERR_FILENO;

extern "C" void report_driver_crash(int signal_number) {
    kill_child_groups();  // the encoder must not outlive clrender
    const char* line = crash_lines[signal_number == SIGSEGV ? 0 : signal_number == SIGABRT ? 1 : 2];
    for (std::size_t left = std::strlen(line); left > 0;) {
        const ssize_t written = ::write(crash_stderr, line, left);
        if (written <= 0) break;
        line += written;
        left -= static_cast<std::size_t>(written);
    }
    ::_exit(crash_exit_code);
}

std::atomic<bool> crash_diagnosis_set{false};

void set_crash_diagnosis(const std::string& message, int exit_code) {
    const char* names[] = {"SIGSEGV", "SIGABRT", "a signal"};
    for (int i = 0; i < 3; ++i) {
        const std::string line = message_line("error", message + " (the process crashed with " + names[i] + ")", exit_code);
        std::snprintf(crash_lines[i], sizeof crash_lines[i], "%s", line.c_str());
    }
    crash_exit_code = exit_code;
    const int saved = ::fcntl(STDERR_FILENO, F_DUPFD_CLOEXEC, 3);
    if (saved >= 0) crash_stderr = saved;
#if !defined(__SANITIZE_ADDRESS__)  // AddressSanitizer reports faults itself
    struct sigaction action;
    std::memset(&action, 0, sizeof action);
    action.sa_handler = report_driver_crash;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESETHAND;
    for (int signal_number : {SIGSEGV, SIGBUS, SIGABRT, SIGILL, SIGFPE}) ::sigaction(signal_number, &action, nullptr);
    crash_diagnosis_set = true;
#endif
}

}  // namespace

std::optional<std::uint64_t> address_space_limit() {
    struct rlimit limit;
    if (::getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return std::nullopt;
    return static_cast<std::uint64_t>(limit.rlim_cur);
}

std::uint64_t address_space_in_use() {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
        if (line.rfind("VmSize:", 0) == 0) return std::strtoull(line.c_str() + 7, nullptr, 10) << 10;  // kB
    return 0;
}

void check_room_for_a_build() {
    const std::optional<std::uint64_t> limit = address_space_limit();
    if (!limit) return;
    const std::uint64_t in_use = address_space_in_use();
    if (in_use + kAddressSpaceForABuild <= *limit) return;
    throw Error("out of memory: cannot build the OpenCL kernels: " + mebibytes(in_use) + " of address space in use, " +
                    address_space_text(*limit),
                kExitOutOfMemory);
}

std::string pocl_cache_folder() {
    if (const char* folder = std::getenv("POCL_CACHE_DIR"); folder && *folder) return folder;
    if (const char* folder = std::getenv("XDG_CACHE_HOME"); folder && *folder) return std::string(folder) + "/pocl";
    if (const char* home = std::getenv("HOME"); home && *home) return std::string(home) + "/.cache/pocl";
    return "";
}

std::optional<Error> driver_trouble(const std::string& what_failed) {
    // A limit with room for two builds beside what is mapped is not the cause.
    if (const std::optional<std::uint64_t> limit = address_space_limit();
        limit && *limit < address_space_in_use() + 2 * kAddressSpaceForABuild)
        return Error("out of memory: " + what_failed + ": " + address_space_text(*limit), kExitOutOfMemory);
    if (too_few_descriptors()) return Error(what_failed + ": " + descriptor_text(), kExitDevice);
    const std::string cache = pocl_cache_folder();
    if (!cache.empty() && !pocl_kernel_cache_off() && !cache_folder_writable(cache))
        return Error(what_failed + ": PoCL's kernel cache folder '" + cache +
                         "' cannot be written (PoCL then starts no device and builds nothing); make it writable or "
                         "point POCL_CACHE_DIR at a writable folder",
                     kExitDevice);
    return std::nullopt;
}

void prepare_for_driver_limits() {
    struct rlimit descriptors;
    // Up to the usual default soft limit, not to the hard one (often a million): the encoder
    // and other children inherit it.
    constexpr rlim_t kUsualSoftLimit = 1024;
    if (::getrlimit(RLIMIT_NOFILE, &descriptors) == 0 && descriptors.rlim_cur < kUsualSoftLimit &&
        descriptors.rlim_cur < descriptors.rlim_max) {
        descriptors.rlim_cur = std::min(descriptors.rlim_max, kUsualSoftLimit);
        ::setrlimit(RLIMIT_NOFILE, &descriptors);
    }
    if (const std::optional<std::uint64_t> limit = address_space_limit())
        set_crash_diagnosis("out of memory: the OpenCL driver failed: " + address_space_text(*limit), kExitOutOfMemory);
    else if (too_few_descriptors())
        set_crash_diagnosis("the OpenCL driver failed: " + descriptor_text(), kExitDevice);
}

}  // namespace clr

// PoCL aborts when a thread or an allocation fails (PoCL 3.1: "PTHREAD ERROR in
// pthread_scheduler_init"). A SIGABRT handler alone does not see that: LLVM, loaded by PoCL,
// installs its own, and glibc's abort() resets the action to the default once a handler
// returns. Defined in the program, this abort() is the one the driver's calls reach (the
// program's symbols come first), so the diagnosis is printed whoever handles SIGABRT. Without
// a diagnosis it does what glibc's does.
extern "C" [[noreturn]] void abort() noexcept {
    if (clr::crash_diagnosis_set) clr::report_driver_crash(SIGABRT);
    struct sigaction fallback;
    std::memset(&fallback, 0, sizeof fallback);
    fallback.sa_handler = SIG_DFL;
    sigemptyset(&fallback.sa_mask);
    ::sigaction(SIGABRT, &fallback, nullptr);
    sigset_t abort_only;
    sigemptyset(&abort_only);
    sigaddset(&abort_only, SIGABRT);
    ::pthread_sigmask(SIG_UNBLOCK, &abort_only, nullptr);
    ::raise(SIGABRT);
    ::_exit(128 + SIGABRT);
}
