#include "scene/value_ranges.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace clr {

std::string number_text(double value) {
    // The fewest significant digits that read back as the same double, e.g. 1e15, not
    // 1000000000000000.0 (nlohmann) or 1.0000000000000000e+15 (%.17g).
    char text[32];
    for (int digits = 1; digits <= 17; ++digits) {
        std::snprintf(text, sizeof text, "%.*g", digits, value);
        if (std::strtod(text, nullptr) == value) break;
    }
    // "1e+15" -> "1e15", "1e-05" -> "1e-5": as a person writes it.
    std::string shown = text;
    const std::size_t e = shown.find('e');
    if (e == std::string::npos) return shown;
    std::string exponent = shown.substr(e + 1);
    const bool negative = exponent[0] == '-';
    exponent.erase(0, exponent.find_first_not_of("+-0"));
    shown = shown.substr(0, e + 1) + (negative ? "-" : "") + (exponent.empty() ? "0" : exponent);
    // A whole number that is no longer written out ("30", "100") reads better than "3e1".
    if (std::fabs(value) < 1e15 && value == std::floor(value)) {
        char whole[32];
        std::snprintf(whole, sizeof whole, "%.0f", value);
        if (std::string(whole).size() <= shown.size()) return whole;
    }
    return shown;
}

std::string position_range_text() {
    return "every coordinate must be from " + number_text(-kMaxCoordinate) + " to " + number_text(kMaxCoordinate);
}

std::string length_range_text() {
    return "lengths must be from " + number_text(kMinLength) + " to " + number_text(kMaxLength);
}

void check_position(const Vec3& position, const std::string& location, const std::string& label,
                    const Diagnostics& diagnostics) {
    for (int axis = 0; axis < 3; ++axis) {
        const double coordinate = position[axis];
        if (std::fabs(coordinate) <= kMaxCoordinate) continue;
        const std::string index = std::to_string(axis);
        diagnostics.fail(location + "/" + index, label + "[" + index + "] is " + number_text(coordinate) +
                                                     ", outside the range clrender renders exactly enough: " +
                                                     position_range_text());
    }
}

Vec3 read_position(const Node& node) {
    const Vec3 position = node.vec3();
    check_position(position, node.location(), node.label(), node.diagnostics());
    return position;
}

double read_length(const Node& node) {
    const double value = node.number();
    if (!(value > 0)) node.fail(node.label() + " must be > 0 (got " + node.shown() + ")");
    if (value < kMinLength || value > kMaxLength)
        node.fail(node.label() + " " + number_text(value) + " is outside the range clrender renders exactly enough: " +
                  length_range_text());
    return value;
}

}  // namespace clr
