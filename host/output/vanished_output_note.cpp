#include "output/vanished_output_note.h"

#include <sys/stat.h>

#include <cerrno>
#include <filesystem>

#include "core/printable_text.h"

namespace clr {

std::string vanished_output_note(const std::string& temporary_path) {
    struct stat info {};
    if (::lstat(temporary_path.c_str(), &info) == 0 || (errno != ENOENT && errno != ENOTDIR)) return "";
    std::string folder = std::filesystem::path(temporary_path).parent_path().string();
    if (folder.empty()) folder = ".";
    if (::stat(folder.c_str(), &info) != 0 && (errno == ENOENT || errno == ENOTDIR))
        return "; the folder '" + printable(folder) + "' is gone: it was removed or renamed while the output was made";
    return "; its temporary file '" + printable(temporary_path) +
           "' is gone: it was removed, or its folder renamed, while the output was made";
}

}  // namespace clr
