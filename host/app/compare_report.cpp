#include "app/compare_report.h"

#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/printable_text.h"

namespace clr {
namespace {

// "0.0326%": four significant digits, so that one pixel of millions is not shown as 0%.
std::string percent(double share) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g%%", share * 100.0);
    return text;
}

std::string rgb(const std::array<std::uint8_t, 3>& colour) {
    return std::to_string(colour[0]) + "," + std::to_string(colour[1]) + "," + std::to_string(colour[2]);
}

}  // namespace

std::string compare_report_text(const CompareFacts& facts, const ImageDifference& difference) {
    std::ostringstream text;
    text << "compared: " << printable(facts.scene_path) << " (frame " << facts.frame << ", " << difference.width << "x"
         << difference.height << ") with " << printable(facts.image_path) << "\n";
    text << "differing: " << difference.differing << " of " << difference.pixels() << " pixels ("
         << percent(difference.differing_share()) << ") differ by more than " << difference.tolerance
         << "/255 in R, G or B\n";
    text << "largest difference: " << difference.largest << "/255\n";
    if (!difference.largest_pixels.empty()) {
        text << "most different pixels (column,row: rendered R,G,B vs image R,G,B):\n";
        for (const PixelDifference& pixel : difference.largest_pixels)
            text << "  " << pixel.x << "," << pixel.y << ": " << rgb(pixel.rendered) << " vs " << rgb(pixel.image)
                 << " (" << pixel.difference << "/255)\n";
    }
    if (!facts.heat_map_path.empty()) text << "heat map: " << printable(facts.heat_map_path) << "\n";
    return text.str();
}

std::string compare_report_json(const CompareFacts& facts, const ImageDifference& difference) {
    nlohmann::ordered_json pixels = nlohmann::ordered_json::array();
    for (const PixelDifference& pixel : difference.largest_pixels)
        pixels.push_back({{"x", pixel.x},
                          {"y", pixel.y},
                          {"rendered", pixel.rendered},
                          {"image", pixel.image},
                          {"difference", pixel.difference}});
    nlohmann::ordered_json report = {
        {"scene", facts.scene_path},
        {"frame", facts.frame},
        {"image", facts.image_path},
        {"width", difference.width},
        {"height", difference.height},
        {"tolerance", difference.tolerance},
        {"pixels", difference.pixels()},
        {"differing", difference.differing},
        {"differing_share", difference.differing_share()},
        {"largest", difference.largest},
        {"largest_pixels", pixels},
        {"heat_map", facts.heat_map_path.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(facts.heat_map_path)},
    };
    // A file name is not guaranteed to be UTF-8: invalid bytes become U+FFFD, so the report
    // stays JSON.
    return report.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

}  // namespace clr
