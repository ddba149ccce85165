#include "scene/file_names.h"

namespace clr {

std::string path_in_folder(const std::filesystem::path& folder, const std::filesystem::path& name) {
    const std::filesystem::path joined = name.is_absolute() ? name : folder / name;
    for (const std::filesystem::path& step : joined)
        if (step == "..") return joined.string();
    return joined.lexically_normal().string();
}

}  // namespace clr
