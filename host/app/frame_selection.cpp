// Frame patterns are expanded here by hand rather than handed to printf: a user's file name
// must never become a format string.
#include "app/frame_selection.h"

#include <algorithm>
#include <cstddef>
#include <limits>
#include <optional>
#include <stdexcept>

#include "core/errors.h"

namespace clr {
namespace {

std::string trimmed(const std::string& text) {
    const std::size_t first = text.find_first_not_of(" \t");
    if (first == std::string::npos) return "";
    const std::size_t last = text.find_last_not_of(" \t");
    return text.substr(first, last - first + 1);
}

std::vector<std::string> split_on_commas(const std::string& text) {
    std::vector<std::string> items;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = text.find(',', start);
        items.push_back(trimmed(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
        if (comma == std::string::npos) return items;
        start = comma + 1;
    }
}

UsageError bad_item(const std::string& list, const std::string& item) {
    const std::string what = item.empty() ? "an empty item" : "'" + item + "' is not a frame number or range";
    return UsageError("--frames '" + list + "': " + what + " (expected frames like 7, ranges like 10-20, joined by commas)");
}

// A frame number: decimal digits only (no sign). Values past int's range saturate, so that
// they are reported as out of range rather than wrapping around.
std::optional<long long> parse_number(const std::string& digits) {
    if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos) return std::nullopt;
    const long long limit = std::numeric_limits<int>::max() + 1LL;
    long long value = 0;
    for (char digit : digits) value = std::min(limit, value * 10 + (digit - '0'));
    return value;
}

void check_in_range(long long frame, int frame_count) {
    if (frame < frame_count) return;
    const std::string frames = frame_count == 1 ? "1 frame (0)"
                                                : std::to_string(frame_count) + " frames (0-" +
                                                      std::to_string(frame_count - 1) + ")";
    // parse_number() saturates at INT_MAX + 1: a larger frame is named by that bound, not by a
    // number the user did not type.
    const std::string named = frame > std::numeric_limits<int>::max()
                                  ? "a frame past " + std::to_string(std::numeric_limits<int>::max())
                                  : "frame " + std::to_string(frame);
    throw UsageError(named + " is out of range: the animation has " + frames);
}

// A frame-number placeholder within a path.
struct Placeholder {
    std::size_t position = 0;  // of its first character
    std::size_t length = 0;    // characters it spans
    int width = 0;             // pad to this many digits with zeros; 0: no padding
};

// A '%' that starts "%d" or "%<digits>d" at `percent`. Widths beyond two digits are not
// taken as placeholders: nobody means a 100-digit frame number.
std::optional<Placeholder> printf_placeholder_at(const std::string& path, std::size_t percent) {
    std::size_t end = percent + 1;
    int width = 0;
    while (end < path.size() && end - percent <= 2 && path[end] >= '0' && path[end] <= '9') {
        width = width * 10 + (path[end] - '0');
        ++end;
    }
    if (end >= path.size() || path[end] != 'd') return std::nullopt;
    return Placeholder{percent, end + 1 - percent, width};
}

// The first placeholder in the file-name part of `path` (folders may contain '#' or '%').
std::optional<Placeholder> find_placeholder(const std::string& path) {
    const std::size_t slash = path.find_last_of('/');
    for (std::size_t i = slash == std::string::npos ? 0 : slash + 1; i < path.size(); ++i) {
        if (path[i] == '#') {
            const std::size_t end = std::min(path.find_first_not_of('#', i), path.size());
            return Placeholder{i, end - i, static_cast<int>(end - i)};
        }
        if (path[i] == '%') {
            if (auto placeholder = printf_placeholder_at(path, i)) return placeholder;
        }
    }
    return std::nullopt;
}

}  // namespace

std::vector<int> parse_frame_list(const std::string& text, int frame_count) {
    if (trimmed(text).empty()) throw UsageError("--frames: the frame list is empty");
    std::vector<int> frames;
    for (const std::string& item : split_on_commas(text)) {
        const std::size_t dash = item.find('-');
        const std::optional<long long> first = parse_number(trimmed(item.substr(0, dash)));
        const std::optional<long long> last =
            dash == std::string::npos ? first : parse_number(trimmed(item.substr(dash + 1)));
        if (!first || !last) throw bad_item(text, item);
        if (*last < *first) {
            throw UsageError("--frames '" + text + "': the range " + item + " runs backwards (write " +
                             std::to_string(*last) + "-" + std::to_string(*first) + ")");
        }
        // The end is checked first: it is the larger, and checking it bounds the loop below.
        check_in_range(*last, frame_count);
        for (long long frame = *first; frame <= *last; ++frame) frames.push_back(static_cast<int>(frame));
    }
    std::sort(frames.begin(), frames.end());
    frames.erase(std::unique(frames.begin(), frames.end()), frames.end());
    return frames;
}

bool is_frame_pattern(const std::string& path) { return find_placeholder(path).has_value(); }

std::string frame_path(const std::string& pattern, int frame) {
    if (frame < 0) throw std::invalid_argument("frame_path: negative frame " + std::to_string(frame));
    const std::optional<Placeholder> placeholder = find_placeholder(pattern);
    if (!placeholder) {
        throw UsageError("'" + pattern + "' has no frame-number placeholder (use %04d or #### in the file name)");
    }
    std::string number = std::to_string(frame);
    if (static_cast<int>(number.size()) < placeholder->width) number.insert(0, placeholder->width - number.size(), '0');
    std::string path = pattern;
    path.replace(placeholder->position, placeholder->length, number);
    return path;
}

}  // namespace clr
