// The files of the viewer page (viewer/ in the source tree), embedded into the binary at build
// time (cmake/embed_viewer.cmake), so that `clrender view` never reads a file to serve them.
#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

namespace clr {

struct EmbeddedAsset {
    const char* path;  // relative to viewer/, e.g. "index.html"
    const char* bytes;
    std::size_t size;
    std::string_view content() const { return {bytes, size}; }
};

// Every file directly under viewer/, sorted by path.
const std::vector<EmbeddedAsset>& embedded_viewer_assets();

// The asset named `path` (relative to viewer/, exactly as embedded), or nullptr.
const EmbeddedAsset* find_viewer_asset(std::string_view path);

}  // namespace clr
