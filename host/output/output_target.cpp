#include "output/output_target.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>

#include "core/errors.h"

namespace clr {
namespace {

namespace fs = std::filesystem;

// What a file that is not a regular file is, for the refusal message.
std::string kind_of(mode_t mode) {
    if (S_ISDIR(mode)) return "a folder";
    if (S_ISFIFO(mode)) return "a named pipe (FIFO)";
    if (S_ISSOCK(mode)) return "a socket";
    if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device";
    return "not a regular file";
}

OutputError refusal(const std::string& path, const std::string& what) {
    return OutputError(path + ": " + what + "; clrender writes outputs only to regular files (or through symbolic links to them)");
}

// Whether a symbolic link at an output's name is replaced rather than written through: in the
// render of the viewer's video, whose name another program may link elsewhere meanwhile (the
// video then replaced a file outside --output-dir).
bool links_replaced() {
    const char* value = std::getenv(kLinksReplacedVariable);
    return value != nullptr && std::string(value) == "1";
}

}  // namespace

std::string resolve_output_target(const std::string& path) {
    struct stat link_info {};
    if (::lstat(path.c_str(), &link_info) != 0) {
        // Missing: a new file. Any other failure (a missing folder, no permission) surfaces
        // as "cannot create a file in its folder" when the folder is prepared.
        return path;
    }
    if (S_ISREG(link_info.st_mode)) return path;
    if (S_ISLNK(link_info.st_mode) && links_replaced()) return path;  // the rename replaces the link
    if (!S_ISLNK(link_info.st_mode)) throw refusal(path, "is " + kind_of(link_info.st_mode));

    struct stat target_info {};
    if (::stat(path.c_str(), &target_info) != 0)
        throw refusal(path, std::string("is a symbolic link that cannot be followed (") + std::strerror(errno) + ")");
    if (!S_ISREG(target_info.st_mode)) throw refusal(path, "is a symbolic link to " + kind_of(target_info.st_mode));
    std::error_code error;
    const fs::path target = fs::canonical(path, error);
    if (error) throw refusal(path, "is a symbolic link that cannot be resolved (" + error.message() + ")");
    return target.string();
}

FileIdentity identify_file(const std::string& path) {
    FileIdentity identity;
    struct stat info {};
    const auto by_inode = [&] {
        identity.path.clear();
        identity.exists = true;
        identity.device = info.st_dev;
        identity.inode = info.st_ino;
        return identity;
    };
    if (::stat(path.c_str(), &info) == 0) return by_inode();
    std::error_code error;
    fs::path absolute = fs::absolute(path, error);
    if (error) absolute = path;  // no working folder (removed meanwhile): the name as given
    const fs::path normal = fs::weakly_canonical(absolute, error);
    identity.path = (error ? absolute.lexically_normal() : normal).string();
    // "sub/../scene.obj" with no folder "sub": stat() fails, but an output there is made by
    // creating "sub" and then lands on scene.obj itself, which is the file to compare with.
    if (::stat(identity.path.c_str(), &info) == 0) return by_inode();
    return identity;
}

}  // namespace clr
