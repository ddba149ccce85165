#include "scene/text_encoding.h"

#include <utility>

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
    using namespace std::string_view_literals;
    if (const auto encoding = wide_unicode_encoding(text))
        return "it is " + *encoding + " text; save it as UTF-8 (clrender reads only UTF-8)";
    // Each format's magic number, as its tools write it: a model downloaded or kept compressed
    // and named .obj. Read as text, such a file was "no faces", or an error at a line of its
    // bytes where a stored block happened to hold an OBJ line ("line 2: 'v': 'f' is not a
    // finite number" for a zstd file).
    static constexpr std::pair<std::string_view, std::string_view> kCompressed[] = {
        {"\x1F\x8B"sv, "gzip-compressed"},
        {"\x28\xB5\x2F\xFD"sv, "zstd-compressed"},
        {"\xFD" "7zXZ\0"sv, "xz-compressed"},
        {"BZh"sv, "bzip2-compressed"},
        {"\x04\x22\x4D\x18"sv, "LZ4-compressed"},
        {"7z\xBC\xAF\x27\x1C"sv, "a 7-Zip archive"},
        {"PK\x03\x04"sv, "a ZIP archive"},
    };
    for (const auto& [magic, format] : kCompressed) {
        if (!starts_with(text, magic)) continue;
        // "BZh" may begin a line of text: bzip2's block size digit and its first block's magic
        // ("1AY&SY", from the digits of pi) follow it.
        if (magic == "BZh"sv && (text.size() < 4 || text[3] < '1' || text[3] > '9' || text.substr(4, 6) != "1AY&SY"sv))
            continue;
        const bool archive = format.substr(0, 2) == "a ";
        return "it is " + std::string(format) + (archive ? "; extract the file first" : "; decompress it first");
    }
    return "";
}

}  // namespace clr
