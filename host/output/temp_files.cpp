#include "output/temp_files.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <regex>
#include <string>

#include "core/errors.h"
#include "core/sha256.h"

namespace clr {
namespace {

namespace fs = std::filesystem;

std::string first_line_of(const char* path) {
    std::ifstream in(path);
    std::string line;
    std::getline(in, line);
    return line;
}

std::string host_name() {
    char name[256] = {};
    return ::gethostname(name, sizeof name - 1) == 0 ? name : "";
}

// The machine (machine id and host name) and the process-id namespace: two containers on
// one machine share a folder but not their process ids, so they must not share a host id.
std::string compute_host_id() {
    std::error_code ignored;
    const std::string pid_namespace = fs::read_symlink("/proc/self/ns/pid", ignored).string();
    try {
        Sha256 hash;
        hash.add_field(first_line_of("/etc/machine-id")).add_field(host_name()).add_field(pid_namespace);
        return to_hex(hash.finish()).substr(0, 8);  // eight hex digits: the name must stay short
    } catch (const std::exception&) {  // libcrypto unusable: a fixed id still names our files
        return "00000000";
    }
}

const std::regex& temp_name_form() {
    static const std::regex form(R"(\.clrender-([0-9a-f]{8})-([0-9]{1,10})-[0-9]{1,10}\.tmp(\.log)?)");
    return form;
}

// A number other users cannot guess, from the kernel's random bytes.
std::uint32_t unpredictable_number() {
    std::uint32_t number = 0;
    if (::getrandom(&number, sizeof number, GRND_NONBLOCK) == static_cast<ssize_t>(sizeof number)) return number;
    return std::random_device{}();  // no getrandom (a kernel before 3.17): still the OS's randomness
}

// The usual name's form with an unpredictable number for the counter (at most 10 digits),
// so that the sweep still recognises it.
std::string unpredictable_temp_path_in_folder_of(const std::string& final_path) {
    const std::string name = ".clrender-" + temp_host_id() + "-" + std::to_string(::getpid()) + "-" +
                             std::to_string(unpredictable_number()) + ".tmp";
    return (fs::path(final_path).parent_path() / name).string();
}

bool process_is_gone(long pid) {
    if (pid <= 0 || pid == static_cast<long>(::getpid())) return false;
    return ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH;  // EPERM: alive, someone else's
}

}  // namespace

const std::string& temp_host_id() {
    static const std::string id = compute_host_id();
    return id;
}

std::string temp_path_in_folder_of(const std::string& final_path) {
    static std::atomic<unsigned> counter{0};
    const std::string name = ".clrender-" + temp_host_id() + "-" + std::to_string(::getpid()) + "-" +
                             std::to_string(counter++) + ".tmp";
    return (fs::path(final_path).parent_path() / name).string();
}

std::string create_under_temp_name(const std::string& final_path,
                                   const std::function<bool(const std::string& temp_path)>& create) {
    for (int attempt = 0; attempt < kMostTempNameTries; ++attempt) {
        const std::string temp_path =
            attempt == 0 ? temp_path_in_folder_of(final_path) : unpredictable_temp_path_in_folder_of(final_path);
        if (create(temp_path)) return temp_path;
        if (errno != EEXIST) return "";
    }
    errno = EEXIST;
    return "";
}

std::string temp_creation_failure(int error_number) {
    const std::string reason = std::strerror(error_number);
    if (error_number != EEXIST) return "cannot create a file in its folder: " + reason;
    return "cannot create a temporary file in its folder: the " + std::to_string(kMostTempNameTries) +
           " names tried (.clrender-*.tmp) were all taken by files this run did not make";
}

bool is_stale_temp_name(const std::string& file_name) {
    std::smatch match;
    if (!std::regex_match(file_name, match, temp_name_form())) return false;
    if (match[1].str() != temp_host_id()) return false;  // another machine's: its pid means nothing here
    return process_is_gone(std::stol(match[2].str()));
}

int sweep_stale_temp_files(const std::string& folder) {
    int removed = 0;
    std::error_code error;
    fs::directory_iterator entries(folder.empty() ? "." : folder, error);
    for (; !error && entries != fs::directory_iterator(); entries.increment(error)) {
        const fs::directory_entry& entry = *entries;
        std::error_code ignored;
        if (!entry.is_regular_file(ignored) || entry.is_symlink(ignored)) continue;
        if (!is_stale_temp_name(entry.path().filename().string())) continue;
        if (::unlink(entry.path().c_str()) == 0) ++removed;
    }
    return removed;
}

void prepare_output_folder(const std::string& final_path) {
    sweep_stale_temp_files(fs::path(final_path).parent_path().string());
    probe_output_folder(final_path);
}

void probe_output_folder(const std::string& final_path) {
    const std::string probe = create_under_temp_name(final_path, [](const std::string& temp_path) {
        const int fd = ::open(temp_path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
        if (fd >= 0) ::close(fd);
        return fd >= 0;
    });
    if (probe.empty()) throw OutputError(final_path + ": " + temp_creation_failure(errno));
    ::unlink(probe.c_str());
}

}  // namespace clr
