#include "view/unused_name_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <optional>

#include "core/errors.h"
#include "core/printable_text.h"
#include "core/replacement_file.h"
#include "output/temp_files.h"

namespace clr {
namespace {

OutputError write_error(const std::string& path, const std::string& what, int error_number) {
    return OutputError(printable(path) + ": " + what + ": " + std::strerror(error_number));
}

// The new entry reaches the disk with the folder (best effort, as for every output).
void sync_folder(const std::string& folder) {
    const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return;
    ::fsync(fd);
    ::close(fd);
}

}  // namespace

std::string series_name(const std::string& base, int n) { return n <= 1 ? base : base + "-" + std::to_string(n); }

bool entry_exists(const std::string& path) {
    struct stat status;
    if (::lstat(path.c_str(), &status) == 0) return true;
    if (errno == ENOENT) return false;
    // The name is at fault, not the folder: a series' later name (NAME-2) is longer than its
    // first, which may just fit (a scene's long name, with "_path" added).
    if (errno == ENAMETOOLONG)
        throw OutputError(printable(std::filesystem::path(path).filename().string()) +
                          ": the name is longer than the folder's file system allows (" + std::strerror(errno) +
                          "); give a shorter name");
    // The folder is at fault (a file in its place, no permission to search it): no name of the
    // series would do, and "every name is taken" would send the user looking for files.
    const std::string folder = std::filesystem::path(path).parent_path().string();
    throw OutputError(printable(folder.empty() ? "." : folder) + ": cannot look for a free name in the folder: " +
                      std::strerror(errno));
}

UnusedNameFile write_under_unused_name(const std::string& folder, const std::string& base, const std::string& extension,
                                       const std::vector<std::string>& also_unused, const std::string& text,
                                       const std::function<void(const std::string& path)>& check) {
    const auto path_of = [&folder](const std::string& name, const std::string& suffix) {
        return (std::filesystem::path(folder) / (name + suffix)).string();
    };
    // Written once, then renamed to the first name that is free when the rename happens.
    std::optional<ReplacementFile> temp;
    for (int n = 1; n <= kMostNameTries; ++n) {
        const std::string name = series_name(base, n);
        const std::string path = path_of(name, extension);
        bool taken = entry_exists(path);
        for (const std::string& suffix : also_unused) taken = taken || entry_exists(path_of(name, suffix));
        if (taken) continue;
        try {
            check(path);
        } catch (const UnusableName&) {
            continue;  // as if taken: the page, which names no file, gets the next name
        }
        if (!temp) {
            // Mode 0666 (less the umask): the permissions any newly written file gets.
            const std::string temp_path = create_under_temp_name(path, [&temp](const std::string& try_path) {
                temp.emplace(try_path, 0666);
                return temp->created();
            });
            if (temp_path.empty()) throw OutputError(printable(path) + ": " + temp_creation_failure(errno));
            const char* data = text.data();
            std::size_t left = text.size();
            while (left > 0) {
                const ssize_t wrote = ::write(temp->descriptor(), data, left);
                if (wrote < 0 && errno == EINTR) continue;
                if (wrote <= 0) throw write_error(path, "write failed", wrote < 0 ? errno : ENOSPC);
                data += wrote;
                left -= static_cast<std::size_t>(wrote);
            }
            if (!temp->close(true)) throw write_error(path, "write failed", errno);
        }
        if (temp->rename_onto_unused(path)) {
            sync_folder(folder);
            return {name, path};
        }
        if (errno != EEXIST) throw write_error(path, "cannot rename the written file to its name", errno);
        // Made under that name since the look: the next name.
    }
    throw OutputError(printable(path_of(base, extension)) + " and the next " + std::to_string(kMostNameTries - 1) +
                      " names of its series (" + printable(base) + "-2" + extension +
                      ", ...) are taken; give another name or clear the folder");
}

}  // namespace clr
