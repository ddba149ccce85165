// Tiles for the --join and --resume tests: PNGs as clrender writes them, altered in one way
// (a text chunk, the pixels' size), as a file from another render or a forged one would be.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/pixel_rect.h"

namespace clr::testing {

// Rewrites the PNG at `path` with its text `key` set to `value` (nullopt: removed), pixels unchanged.
void set_png_text(const std::string& path, const std::string& key, const std::optional<std::string>& value);

// A preparation for a bad-input catalogue case: in the case's folder, clrender runs with each
// of `commands` (its arguments, e.g. a tile with --crop), then `alter` (if any) changes what
// they wrote.
std::function<void(const std::string& folder)> clrender_writes(
    std::vector<std::string> commands, std::function<void(const std::string& folder)> alter = nullptr);

// Rewrites the PNG at `path` as the `rect` of its pixels, its text unchanged.
void cut_png(const std::string& path, const PixelRect& rect);

}  // namespace clr::testing
