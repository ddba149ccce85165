#include "output/output_folders.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "core/errors.h"

namespace clr {
namespace {

namespace fs = std::filesystem;

bool exists_in_any_form(const std::string& path) {
    struct stat info {};
    return ::lstat(path.c_str(), &info) == 0;
}

bool is_folder(const std::string& path) {  // following a symbolic link to a folder
    struct stat info {};
    return ::stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode);
}

}  // namespace

std::vector<std::string> missing_folders_of(const std::string& final_path) {
    std::vector<std::string> missing;
    fs::path folder = fs::path(final_path).parent_path();
    while (!folder.empty() && !exists_in_any_form(folder.string())) {
        missing.insert(missing.begin(), folder.string());
        folder = folder.parent_path();
    }
    if (missing.empty()) return missing;  // the folder exists: prepare_output_folder() checks it
    const std::string existing = folder.empty() ? "." : folder.string();
    if (!is_folder(existing))
        throw OutputError(final_path + ": cannot create the folder '" + missing.front() + "': '" + existing +
                          "' is not a folder");
    // mkdir needs write and search permission in the deepest existing folder (and a file
    // system that is not read-only: access() reports EROFS for W_OK too).
    if (::access(existing.c_str(), W_OK | X_OK) != 0)
        throw OutputError(final_path + ": cannot create the folder '" + missing.front() + "': " + std::strerror(errno));
    return missing;
}

void make_output_folders(const std::vector<std::string>& folders, const std::string& for_output) {
    for (const std::string& folder : folders) {
        if (::mkdir(folder.c_str(), 0777) == 0) continue;
        const int error_number = errno;
        if (error_number == EEXIST && is_folder(folder)) continue;
        throw OutputError(for_output + ": cannot create the folder '" + folder + "': " + std::strerror(error_number));
    }
}

}  // namespace clr
