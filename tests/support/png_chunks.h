// What a PNG file says besides its pixels, read with libpng: its text chunks and whether it is
// marked as sRGB, for tests of the metadata clrender writes.
#pragma once

#include <map>
#include <optional>
#include <string>

namespace clr::testing {

struct PngDescription {
    bool readable = false;
    std::optional<int> srgb_intent;            // the sRGB chunk's rendering intent, if any
    std::map<std::string, std::string> text;  // tEXt (and zTXt, iTXt) chunks: keyword -> text
};

PngDescription read_png_description(const std::string& path);

}  // namespace clr::testing
