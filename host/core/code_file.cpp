#include "core/code_file.h"

#include <dlfcn.h>
#include <errno.h>
#include <sys/stat.h>

#include <cstring>
#include <filesystem>
#include <system_error>

namespace clr {
namespace {

constexpr const char* kRunningProgram = "/proc/self/exe";

std::string with_size_and_time(const std::string& name, const char* file) {
    struct stat info;
    if (::stat(file, &info) != 0) return name;
    return name + " " + std::to_string(info.st_size) + " " + std::to_string(info.st_mtim.tv_sec) + "." +
           std::to_string(info.st_mtim.tv_nsec);
}

}  // namespace

std::string code_file_identity(const void* function) {
    Dl_info info{};
    if (::dladdr(function, &info) == 0 || !info.dli_fname) return "unknown";
    // dladdr names the main program by its argv[0]: "clrender" run through PATH was looked up
    // in the working folder (no file, or another one), so that every build run that way had one
    // key and an upgrade read the entries of the build before it.
    if (program_invocation_name && std::strcmp(info.dli_fname, program_invocation_name) == 0) {
        std::error_code error;
        const std::filesystem::path running = std::filesystem::read_symlink(kRunningProgram, error);
        if (!error) return with_size_and_time(running.string(), kRunningProgram);
    }
    return with_size_and_time(info.dli_fname, info.dli_fname);
}

}  // namespace clr
