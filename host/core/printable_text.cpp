#include "core/printable_text.h"

#include <vector>

namespace clr {
namespace {

// Length of the valid UTF-8 sequence starting at text[at], or 0 when it is not valid
// (a stray continuation byte, a truncated or overlong sequence, a surrogate, > U+10FFFF).
std::size_t utf8_sequence_length(const std::string& text, std::size_t at, char32_t& code_point) {
    const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
    const unsigned char lead = byte(at);
    std::size_t length = 0;
    if (lead < 0x80) {
        code_point = lead;
        return 1;
    }
    if (lead >= 0xC2 && lead <= 0xDF) length = 2, code_point = lead & 0x1F;
    else if (lead >= 0xE0 && lead <= 0xEF) length = 3, code_point = lead & 0x0F;
    else if (lead >= 0xF0 && lead <= 0xF4) length = 4, code_point = lead & 0x07;
    else return 0;
    if (at + length > text.size()) return 0;
    for (std::size_t i = 1; i < length; ++i) {
        if ((byte(at + i) & 0xC0) != 0x80) return 0;
        code_point = (code_point << 6) | (byte(at + i) & 0x3F);
    }
    const char32_t smallest[] = {0, 0, 0x80, 0x800, 0x10000};
    if (code_point < smallest[length] || code_point > 0x10FFFF) return 0;  // overlong, too large
    if (code_point >= 0xD800 && code_point <= 0xDFFF) return 0;            // surrogate
    return length;
}

bool is_unsafe(char32_t c) {
    const bool control = c < 0x20 || (c >= 0x7F && c <= 0x9F);
    const bool bidi = c == 0x061C || c == 0x200E || c == 0x200F || (c >= 0x202A && c <= 0x202E) ||
                      (c >= 0x2066 && c <= 0x2069);
    // Invisible format characters: a name holding one looks like another name, or like none.
    const bool invisible = c == 0x00AD || c == 0x180E || (c >= 0x200B && c <= 0x200D) || (c >= 0x2060 && c <= 0x2064) ||
                           c == 0xFEFF;
    return control || bidi || invisible;
}

void append_escaped(std::string& out, const std::string& text, std::size_t at, std::size_t count) {
    static const char kHex[] = "0123456789ABCDEF";
    for (std::size_t i = at; i < at + count; ++i) {
        const auto byte = static_cast<unsigned char>(text[i]);
        out += "\\x";
        out += kHex[byte >> 4];
        out += kHex[byte & 15];
    }
}

// Byte offsets at which each character of (valid or not) UTF-8 text starts.
std::vector<std::size_t> character_starts(const std::string& text) {
    std::vector<std::size_t> starts;
    for (std::size_t at = 0; at < text.size();) {
        starts.push_back(at);
        char32_t code_point = 0;
        const std::size_t length = utf8_sequence_length(text, at, code_point);
        at += length == 0 ? 1 : length;
    }
    return starts;
}

}  // namespace

std::string printable(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    for (std::size_t at = 0; at < text.size();) {
        char32_t code_point = 0;
        const std::size_t length = utf8_sequence_length(text, at, code_point);
        if (length == 0) {
            append_escaped(out, text, at, 1);
            at += 1;
            continue;
        }
        if (is_unsafe(code_point)) append_escaped(out, text, at, length);
        else out.append(text, at, length);
        at += length;
    }
    return out;
}

std::string shortened(const std::string& text, std::size_t most) {
    static const std::string kGap = " ... ";
    if (text.size() <= most) return text;  // bytes >= characters
    const std::vector<std::size_t> starts = character_starts(text);
    if (starts.size() <= most) return text;
    const std::size_t kept = most > kGap.size() ? most - kGap.size() : 0;
    const std::size_t head = kept - kept / 3, tail = kept / 3;
    return text.substr(0, starts[head]) + kGap + text.substr(starts[starts.size() - tail]);
}

}  // namespace clr
