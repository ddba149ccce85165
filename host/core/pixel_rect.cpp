#include "core/pixel_rect.h"

#include <regex>

namespace clr {

std::optional<PixelRect> parse_pixel_rect(const std::string& text) {
    // At most 6 digits: no image is a million pixels wide, and stoi cannot overflow.
    static const std::regex pattern(R"((\d{1,6}),(\d{1,6}),(\d{1,6}),(\d{1,6}))");
    std::smatch match;
    if (!std::regex_match(text, match, pattern)) return std::nullopt;
    PixelRect rect{std::stoi(match[1]), std::stoi(match[2]), std::stoi(match[3]), std::stoi(match[4])};
    if (rect.x0 >= rect.x1 || rect.y0 >= rect.y1) return std::nullopt;
    return rect;
}

std::string format_pixel_rect(const PixelRect& rect) {
    return std::to_string(rect.x0) + "," + std::to_string(rect.x1) + "," + std::to_string(rect.y0) + "," +
           std::to_string(rect.y1);
}

}  // namespace clr
