#include "core/cache_folder.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace clr {
namespace {

// A folder this user owns and nobody else can write: entries found there were written by this
// user's own runs (or by something that could already run code as this user).
bool is_private_folder(const struct stat& info) {
    return S_ISDIR(info.st_mode) && info.st_uid == ::geteuid() && (info.st_mode & (S_IWGRP | S_IWOTH)) == 0;
}

// mkdir with mode 0700; "already there" is fine (what is there is checked afterwards).
bool make_private_folder(const std::string& path) { return ::mkdir(path.c_str(), 0700) == 0 || errno == EEXIST; }

bool usable_root(const std::string& root, bool create) {
    struct stat info;
    if (::lstat(root.c_str(), &info) != 0) {
        if (!create) return false;
        // The folders above are ordinary ones (~/.cache is shared by many programs): only
        // clrender's own folder is made private.
        std::error_code ignored;
        const std::filesystem::path parent = std::filesystem::path(root).parent_path();
        if (!parent.empty()) std::filesystem::create_directories(parent, ignored);
        if (!make_private_folder(root)) return false;
    }
    return ::stat(root.c_str(), &info) == 0 && is_private_folder(info);  // follows a symlinked root
}

}  // namespace

std::string cache_folder_from_environment() {
    if (const char* folder = std::getenv("CLRENDER_CACHE_DIR")) {
        const std::string chosen(folder);
        return chosen == "off" ? std::string() : chosen;
    }
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::string(xdg) + "/clrender";
    if (const char* home = std::getenv("HOME"); home && *home) return std::string(home) + "/.cache/clrender";
    return "";
}

std::string usable_cache_subfolder(const std::string& root, const std::string& name, bool create) {
    if (root.empty() || !usable_root(root, create)) return "";
    const std::string folder = root + "/" + name;
    struct stat info;
    if ((create && !make_private_folder(folder)) || ::lstat(folder.c_str(), &info) != 0 || !is_private_folder(info)) return "";
    return folder;
}

}  // namespace clr
