#include "scene/text_encoding.h"

namespace clr {
namespace {

bool starts_with(std::string_view text, std::string_view prefix) { return text.substr(0, prefix.size()) == prefix; }

// Whether byte `i` of `text` is NUL: the pattern of an ASCII character in a wide encoding.
bool is_nul(std::string_view text, std::size_t i) { return i < text.size() && text[i] == '\0'; }
// A character a JSON text can start with: printable ASCII or whitespace.
bool is_ascii(std::string_view text, std::size_t i) {
    if (i >= text.size()) return false;
    const auto byte = static_cast<unsigned char>(text[i]);
    return (byte >= 0x20 && byte < 0x7F) || byte == '\t' || byte == '\n' || byte == '\r';
}

}  // namespace

std::optional<std::string> wide_unicode_encoding(std::string_view text) {
    using namespace std::string_view_literals;
    // UTF-32's marks first: little-endian UTF-32's begins with UTF-16's.
    if (starts_with(text, "\0\0\xFE\xFF"sv)) return "UTF-32 (big-endian)";
    if (starts_with(text, "\xFF\xFE\0\0"sv)) return "UTF-32 (little-endian)";
    if (starts_with(text, "\xFE\xFF"sv)) return "UTF-16 (big-endian)";
    if (starts_with(text, "\xFF\xFE"sv)) return "UTF-16 (little-endian)";
    if (is_nul(text, 0) && is_nul(text, 1) && is_nul(text, 2) && is_ascii(text, 3)) return "UTF-32 (big-endian)";
    if (is_ascii(text, 0) && is_nul(text, 1) && is_nul(text, 2) && is_nul(text, 3)) return "UTF-32 (little-endian)";
    if (is_nul(text, 0) && is_ascii(text, 1)) return "UTF-16 (big-endian)";
    if (is_ascii(text, 0) && is_nul(text, 1)) return "UTF-16 (little-endian)";
    return std::nullopt;
}

std::string saved_text_problem(std::string_view text) {
    if (const auto encoding = wide_unicode_encoding(text))
        return "it is " + *encoding + " text; save it as UTF-8 (clrender reads only UTF-8)";
    if (text.size() >= 2 && text[0] == '\x1F' && text[1] == '\x8B') return "it is gzip-compressed; decompress it first";
    return "";
}

}  // namespace clr
