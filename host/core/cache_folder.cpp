#include "core/cache_folder.h"

#include <cstdlib>

namespace clr {

std::string cache_folder_from_environment() {
    if (const char* folder = std::getenv("CLRENDER_CACHE_DIR")) {
        const std::string chosen(folder);
        return chosen == "off" ? std::string() : chosen;
    }
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::string(xdg) + "/clrender";
    if (const char* home = std::getenv("HOME"); home && *home) return std::string(home) + "/.cache/clrender";
    return "";
}

}  // namespace clr
