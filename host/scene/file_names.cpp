#include "scene/file_names.h"

#include <sys/stat.h>

namespace clr {

std::string path_in_folder(const std::filesystem::path& folder, const std::filesystem::path& name) {
    const std::filesystem::path joined = name.is_absolute() ? name : folder / name;
    for (const std::filesystem::path& step : joined)
        if (step == "..") return joined.string();
    return joined.lexically_normal().string();
}

FileInFolderKey file_in_folder_key(const std::string& path) {
    struct stat file {}, folder {};
    const std::string parent = std::filesystem::path(path).parent_path().string();
    if (::stat(path.c_str(), &file) != 0 || ::stat(parent.empty() ? "." : parent.c_str(), &folder) != 0)
        return {0, 0, 0, 0, path};
    return {file.st_dev, file.st_ino, folder.st_dev, folder.st_ino, ""};
}

}  // namespace clr
