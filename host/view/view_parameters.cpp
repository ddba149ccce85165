#include "view/view_parameters.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <regex>

#include "core/printable_text.h"
#include "scene/limits.h"
#include "scene/scene.h"
#include "view/query_tokens.h"

namespace clr {
namespace {

// A parameter's text in a message: printable and short, whatever was sent.
std::string shown(const std::string& text) { return "'" + printable(shortened(text, 40)) + "'"; }

// The value of `name`, if given; given twice is refused (which one would count?).
std::optional<std::string> single(const QueryParameters& query, const std::string& name) {
    const auto [first, last] = query.equal_range(name);
    if (first == last) return std::nullopt;
    if (std::next(first) != last) throw ParameterError(name, name + " is given more than once");
    return first->second;
}

std::optional<Vec3> read_vector(const QueryParameters& query, const std::string& name) {
    const std::optional<std::string> text = single(query, name);
    if (!text) return std::nullopt;
    double values[3];
    std::size_t start = 0;
    for (int i = 0; i < 3; ++i) {
        const std::size_t comma = text->find(',', start);
        const bool last = i == 2;
        if (last != (comma == std::string::npos))
            throw ParameterError(name, name + " must be three numbers x,y,z, got " + shown(*text));
        const std::string part = text->substr(start, last ? std::string::npos : comma - start);
        const std::optional<double> value = parse_plain_number(part);
        if (!value)
            throw ParameterError(name, name + " must be three finite numbers x,y,z; " + shown(part) + " is not one");
        values[i] = *value;
        start = comma + 1;
    }
    return Vec3{values[0], values[1], values[2]};
}

// A whole number of at most `digits` digits (so it fits an int), without sign or spaces.
std::optional<int> read_whole(const QueryParameters& query, const std::string& name, int digits, const std::string& what) {
    const std::optional<std::string> text = single(query, name);
    if (!text) return std::nullopt;
    static const std::regex whole(R"(\d+)");
    if (!std::regex_match(*text, whole))
        throw ParameterError(name, name + " must be " + what + ", got " + shown(*text));
    // Leading zeros aside, more digits than `digits` is beyond every limit: the range check
    // after reading gives the limit.
    std::size_t first = text->find_first_not_of('0');
    const std::string significant = first == std::string::npos ? "0" : text->substr(first);
    if (significant.size() > static_cast<std::size_t>(digits)) return -1;  // out of range, reported by the caller
    return std::stoi(significant);
}

// "a, b and c".
std::string listed(const std::vector<std::string>& names) {
    std::string text;
    for (std::size_t k = 0; k < names.size(); ++k)
        text += (k == 0 ? "" : k + 1 == names.size() ? " and " : ", ") + names[k];
    return text;
}

}  // namespace

QueryParameters query_parameters(const std::string& target, const std::vector<std::string>& known) {
    QueryParameters parameters;
    for (const QueryPair& pair : query_pairs_as_sent(target)) {
        if (pair.name == "token") continue;
        const std::string name = printable(shortened(pair.name, 40));  // as a message shows it
        if (std::find(known.begin(), known.end(), pair.name) == known.end())
            throw ParameterError(name, "unknown parameter " + shown(pair.name) + "; this address reads " +
                                           (known.empty() ? "only token" : listed(known) + " (and token)"));
        if (pair.equals_in_value)
            throw ParameterError(name, name + " has a '=' in its value as sent (" + shown(pair.value) +
                                           "): a value is one, and a '=' in it is written %3D");
        if (parameters.count(pair.name) > 0) throw ParameterError(name, name + " is given more than once");
        parameters.emplace(pair.name, pair.value);
    }
    return parameters;
}

std::optional<double> parse_plain_number(const std::string& text) {
    static const std::regex plain(R"([-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?)");
    if (text.size() > 64 || !std::regex_match(text, plain)) return std::nullopt;
    errno = 0;
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (end != text.c_str() + text.size() || !std::isfinite(value)) return std::nullopt;
    if (errno == ERANGE && std::fabs(value) > 1) return std::nullopt;  // overflow (underflow reads as ~0)
    return value;
}

ViewQuery parse_view_query(const QueryParameters& query) {
    ViewQuery view;
    view.eye = read_vector(query, "eye");
    view.lookat = read_vector(query, "lookat");
    view.up = read_vector(query, "up");
    if (const std::optional<std::string> fov = single(query, "fov")) {
        view.fov_degrees = parse_plain_number(*fov);
        if (!view.fov_degrees) throw ParameterError("fov", "fov must be a finite number of degrees, got " + shown(*fov));
    }
    if (const std::optional<std::string> size = single(query, "size")) {
        // The command line's --size form, WIDTHxHEIGHT with positive integers.
        static const std::regex pattern(R"((\d{1,6})[xX](\d{1,6}))");
        std::smatch match;
        if (!std::regex_match(*size, match, pattern) || std::stoi(match[1]) < 1 || std::stoi(match[2]) < 1)
            throw ParameterError("size", "size must be WIDTHxHEIGHT with positive integers, got " + shown(*size));
        view.width = std::stoi(match[1]);
        view.height = std::stoi(match[2]);
    }
    view.samples_per_pixel = read_whole(query, "spp", 9, "a whole number of samples per pixel");
    if (view.samples_per_pixel && (*view.samples_per_pixel < 1 || *view.samples_per_pixel > kMaxSamplesPerPixel))
        throw ParameterError("spp", "spp must be from 1 to " + std::to_string(kMaxSamplesPerPixel) + " (as --spp)");
    view.frame = read_whole(query, "frame", 9, "a frame number from 0");
    if (view.frame && (*view.frame < 0 || *view.frame >= kMaxAnimationFrames))
        throw ParameterError("frame", "frame must be a frame of the scene's animation, from 0");
    return view;
}

PixelQuery parse_pixel_query(const QueryParameters& query) {
    PixelQuery pixel;
    for (const char* name : {"x", "y"}) {
        const std::optional<int> value = read_whole(query, name, 6, "a whole number from 0 (a pixel's column or row)");
        if (!value) throw ParameterError(name, std::string(name) + " is required: the pixel's column (x) and row (y)");
        if (*value < 0) throw ParameterError(name, std::string(name) + " is beyond every image's size");
        (name[0] == 'x' ? pixel.x : pixel.y) = *value;
    }
    return pixel;
}

}  // namespace clr
