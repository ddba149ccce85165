// An output's format is chosen by its file name's extension, whatever its case (.PNG, .Mp4).
#pragma once

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

namespace clr {

// The extension of `path` with its dot, in lower case: ".png"; "" when there is none.
inline std::string lowercase_extension(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

}  // namespace clr
