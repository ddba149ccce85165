#include "scene/obj_text_checks.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "core/parallel_for.h"
#include "core/printable_text.h"
#include "core/usable_cpus.h"
#include "scene/value_ranges.h"

namespace clr {
namespace {

// find_first_of() and find_first_not_of() with a set of characters call memchr() on the set
// for every character of the text: on a 1M-triangle OBJ that was a third of the loading
// time. These loops test the two characters directly.
bool is_blank(char c) { return c == ' ' || c == '\t'; }

std::size_t find_blank(std::string_view text, std::size_t from) {
    for (std::size_t i = from; i < text.size(); ++i)
        if (is_blank(text[i])) return i;
    return std::string_view::npos;
}

std::size_t find_not_blank(std::string_view text, std::size_t from) {
    for (std::size_t i = from; i < text.size(); ++i)
        if (!is_blank(text[i])) return i;
    return std::string_view::npos;
}

std::size_t find_line_end(std::string_view text, std::size_t from) {
    for (std::size_t i = from; i < text.size(); ++i)
        if (text[i] == '\r' || text[i] == '\n') return i;
    return std::string_view::npos;
}

// Calls `visit(line_number, line)` for each line; a line ends at "\n", "\r\n" or a lone "\r",
// as tinyobjloader ends them. Stops when `visit` returns false.
template <typename Visit>
void for_each_line(std::string_view text, Visit&& visit) {
    std::uint64_t number = 0;
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = find_line_end(text, start);
        if (end == std::string_view::npos) end = text.size();
        if (!visit(++number, text.substr(start, end - start))) return;
        start = end;
        if (start < text.size() && text[start] == '\r') ++start;
        if (start < text.size() && text[start] == '\n') ++start;
    }
}

// The first `most` words of `line`: a line may be a whole file of words, which a list of
// them all would take about 17 times the file's size to hold.
std::vector<std::string_view> tokens_of(std::string_view line, std::size_t most) {
    std::vector<std::string_view> tokens;
    std::size_t at = 0;
    while (at < line.size() && tokens.size() < most) {
        at = find_not_blank(line, at);
        if (at == std::string_view::npos) break;
        std::size_t end = find_blank(line, at);
        if (end == std::string_view::npos) end = line.size();
        tokens.push_back(line.substr(at, end - at));
        at = end;
    }
    return tokens;
}

std::uint64_t token_count(std::string_view line) {
    std::uint64_t count = 0;
    for (std::size_t at = find_not_blank(line, 0); at != std::string_view::npos; at = find_not_blank(line, at)) {
        ++count;
        at = find_blank(line, at);
        if (at == std::string_view::npos) break;
    }
    return count;
}

// The most words a `v`, `vn`, `vt` or `f` statement may have: its keyword and kMaxFaceCorners
// corners (a position's numbers are far fewer).
constexpr std::size_t kMaxStatementWords = kMaxFaceCorners + 1;

// A leading '+' ("+1", "1/+2"), which from_chars refuses and tinyobjloader's readers (its own
// number parser, atoi) accept; "+-1" keeps its '+' and stays refused.
std::string_view without_plus(std::string_view token) {
    if (token.size() > 1 && token[0] == '+' && token[1] != '+' && token[1] != '-') token.remove_prefix(1);
    return token;
}

bool parse_number(std::string_view token, double& value) {
    token = without_plus(token);
    const char* end = token.data() + token.size();
    const auto result = std::from_chars(token.data(), end, value);
    return result.ec == std::errc() && result.ptr == end && std::isfinite(value);
}

// Whether `token` is a number too close to zero for a double ("1e-400"): from_chars refuses it
// as it refuses one too large, but it is finite. Read as a long double, of a wider range.
bool underflows_double(std::string_view token) {
    token = without_plus(token);
    const char* end = token.data() + token.size();
    double unused = 0;
    if (std::from_chars(token.data(), end, unused).ec != std::errc::result_out_of_range) return false;
    long double value = 0;
    const auto wide = std::from_chars(token.data(), end, value);
    return wide.ec == std::errc() && wide.ptr == end && std::fabs(value) < 1.0L;
}

// tinyobjloader computes a number as mantissa * 5^e * 2^e from its digits, which gives NaN or
// infinity for finite numbers such as "0e500" (0 * infinity) or a 400-digit "1000...0e-400".
// Within kMaxNumberCharacters and an exponent of at most kMaxNumberExponent in magnitude,
// neither product can overflow for a number that from_chars reads as finite.
constexpr std::size_t kMaxNumberCharacters = 64;
constexpr long kMaxNumberExponent = 300;

bool within_reader_limits(std::string_view token) {
    if (token.size() > kMaxNumberCharacters) return false;
    const std::size_t e = token.find_first_of("eE");
    if (e == std::string_view::npos) return true;
    long exponent = 0;
    std::string_view digits = token.substr(e + 1);
    if (!digits.empty() && digits[0] == '+') digits.remove_prefix(1);  // from_chars reads "-" only
    const auto result = std::from_chars(digits.data(), digits.data() + digits.size(), exponent);
    return result.ec == std::errc() && std::labs(exponent) <= kMaxNumberExponent;
}

std::string number_limits_text() {
    return "clrender reads numbers of at most " + std::to_string(kMaxNumberCharacters) +
           " characters with an exponent from -" + std::to_string(kMaxNumberExponent) + " to " +
           std::to_string(kMaxNumberExponent);
}

// A token of the file as messages show it: its first 40 bytes, escaped as every message escapes
// text (a NUL as \x00, not as a '?' that the file may hold itself or not at all).
std::string quoted(std::string_view token) {
    constexpr std::size_t kShown = 40;
    return "'" + printable(std::string(token.substr(0, kShown))) + (token.size() > kShown ? "...'" : "'");
}

// The numbers of a `v`, `vn` or `vt` line: at least `least`, each finite; the first three of
// a position within the coordinate range.
std::string check_numbers(const std::vector<std::string_view>& tokens, std::size_t least, bool position) {
    const std::string_view keyword = tokens[0];
    if (tokens.size() - 1 < least) {
        return "'" + std::string(keyword) + "' needs " + std::to_string(least) + " numbers, the line has " +
               std::to_string(tokens.size() - 1);
    }
    for (std::size_t i = 1; i < tokens.size(); ++i) {
        double value = 0;
        const bool read = parse_number(tokens[i], value);
        const bool underflows = !read && underflows_double(tokens[i]);  // read again only where the first read failed
        if (!read && !underflows) {
            return "'" + std::string(keyword) + "': " + quoted(tokens[i]) + " is not a finite number";
        }
        if (underflows || !within_reader_limits(tokens[i])) {
            return "'" + std::string(keyword) + "': " + quoted(tokens[i]) + " is too long or its exponent too large (" +
                   number_limits_text() + ")";
        }
        if (position && i <= 3 && std::fabs(value) > kMaxCoordinate) {
            return "'v': " + quoted(tokens[i]) + " is out of range: " + position_range_text();
        }
    }
    return {};
}

// One index of a corner: non-zero; positive counts from the file's first entry, negative back
// from the latest entry before this line. `defined` entries precede the line, `total` are in
// the file.
std::string check_index(std::string_view token, const char* what, std::uint64_t defined, std::uint64_t total) {
    long long index = 0;
    const std::string_view digits = without_plus(token);
    const char* end = digits.data() + digits.size();
    const auto result = std::from_chars(digits.data(), end, index);
    if (result.ec != std::errc() || result.ptr != end) return quoted(token) + " is not a " + std::string(what) + " index";
    if (index == 0) return std::string(what) + " index 0: indices count from 1 (or back from -1)";
    if (index > 0 && static_cast<std::uint64_t>(index) > total) {
        return std::string(what) + " index " + std::to_string(index) + " is out of range: the file has " +
               std::to_string(total);
    }
    if (index < 0 && static_cast<std::uint64_t>(-(index + 1)) >= defined) {
        return std::string(what) + " index " + std::to_string(index) + " is out of range: " + std::to_string(defined) +
               " precede this line";
    }
    return {};
}

// A face corner "p", "p/t", "p//n" or "p/t/n".
std::string check_corner(std::string_view corner, const ObjTextCounts& before, const ObjTextCounts& total) {
    std::string_view parts[3];
    int count = 0;
    std::size_t start = 0;
    while (count < 3) {
        const std::size_t slash = corner.find('/', start);
        parts[count++] = corner.substr(start, slash == std::string_view::npos ? std::string_view::npos : slash - start);
        if (slash == std::string_view::npos) break;
        start = slash + 1;
        if (count == 3) return quoted(corner) + " is not a corner (p, p/t, p//n or p/t/n)";
    }
    // "p/" names no texture coordinate after its slash (tinyobjloader refuses it without a line).
    if (count == 2 && parts[1].empty()) return quoted(corner) + " is not a corner (p, p/t, p//n or p/t/n)";
    std::string problem = check_index(parts[0], "position", before.positions, total.positions);
    if (problem.empty() && count >= 2 && !parts[1].empty()) {
        problem = check_index(parts[1], "texture coordinate", before.texcoords, total.texcoords);
    }
    if (problem.empty() && count == 3) problem = check_index(parts[2], "normal", before.normals, total.normals);
    return problem;
}

// The entries each keyword adds, counted in a first pass so that a face may name a position
// defined after it, as tinyobjloader allows; `line`: the whole line, comment included.
void count_entry(std::string_view keyword, std::string_view line, ObjTextCounts& counts) {
    if (keyword == "v") ++counts.positions;
    else if (keyword == "vn") ++counts.normals;
    else if (keyword == "vt") ++counts.texcoords;
    else if (keyword == "o" || keyword == "g" || keyword == "usemtl" || keyword == "mtllib") ++counts.named_statements;
    if (keyword == "o" || keyword == "g" || keyword == "s" || keyword == "usemtl" || keyword == "mtllib")
        counts.grouping_statement_bytes += line.size();
}

// Whether `keyword` starts a statement of the OBJ format (vertex data, elements, grouping,
// display attributes, free-form geometry) or tinyobjloader's tags (`t`): all but these are
// typos or damage, which a warning names.
bool is_obj_statement(std::string_view keyword) {
    static constexpr std::string_view kStatements[] = {
        "v",    "vn",   "vt",     "f",        "o",        "g",          "s",          "usemtl", "mtllib",
        "vp",   "l",    "p",      "mg",       "usemap",   "maplib",     "cstype",     "deg",    "bmat",
        "step", "curv", "curv2",  "surf",     "parm",     "trim",       "hole",       "scrv",   "sp",
        "end",  "con",  "lod",    "ctech",    "stech",    "bevel",      "c_interp",   "d_interp",
        "call", "csh",  "res",    "trace_obj", "shadow_obj", "t"};
    for (const std::string_view statement : kStatements)
        if (keyword == statement) return true;
    return false;
}

// The statement of a line: the text before a '#' that starts a word ("f 1 2 3 # tri"), which
// starts a comment. A '#' inside a word is part of it: old MSVC runtimes write infinity and NaN
// as "1.#INF" and "-1.#IND", which cut at the '#' were read as 1 and -1 and drawn so.
std::string_view statement_of(std::string_view line) {
    for (std::size_t at = line.find('#'); at != std::string_view::npos; at = line.find('#', at + 1))
        if (at == 0 || is_blank(line[at - 1])) return line.substr(0, at);
    return line;
}

// Statements of numbers only, whose trailing comment tinyobjloader would read as one more
// corner (a zero index, refused) or number: it gets them without the comment. Names (`usemtl`,
// `mtllib`, `newmtl`) are the library's to read whole.
bool is_numeric_statement(std::string_view keyword) {
    return keyword == "v" || keyword == "vn" || keyword == "vt" || keyword == "f" || keyword == "Kd";
}

// The first word of a line ("" for a blank one).
std::string_view keyword_of(std::string_view line) {
    const std::size_t at = find_not_blank(line, 0);
    if (at == std::string_view::npos) return {};
    const std::size_t end = find_blank(line, at);
    return line.substr(at, end == std::string_view::npos ? std::string_view::npos : end - at);
}

template <typename Keep>
std::string statements_kept(std::string_view text, Keep&& keep) {
    text = without_byte_order_mark(text);
    std::string kept;
    kept.reserve(text.size() + 1);
    for_each_line(text, [&](std::uint64_t, std::string_view line) {
        const std::string_view statement = statement_of(line);
        const std::string_view keyword = keyword_of(statement);
        if (keep(keyword)) kept.append(is_numeric_statement(keyword) ? statement : line);
        kept.push_back('\n');
        return true;
    });
    return kept;
}

}  // namespace

std::string_view without_byte_order_mark(std::string_view text) {
    constexpr std::string_view kUtf8ByteOrderMark = "\xEF\xBB\xBF";
    if (text.substr(0, kUtf8ByteOrderMark.size()) == kUtf8ByteOrderMark) text.remove_prefix(kUtf8ByteOrderMark.size());
    return text;
}

void for_each_keyword(std::string_view text,
                      const std::function<void(std::uint64_t, std::string_view, std::string_view)>& visit) {
    for_each_line(without_byte_order_mark(text), [&](std::uint64_t number, std::string_view line) {
        if (const std::string_view keyword = keyword_of(line); !keyword.empty()) visit(number, keyword, line);
        return true;
    });
}

void for_each_statement(std::string_view text, std::string_view keyword,
                        const std::function<void(std::uint64_t, std::string_view)>& visit) {
    for_each_keyword(text, [&](std::uint64_t number, std::string_view first_word, std::string_view line) {
        if (first_word == keyword) visit(number, line);
    });
}

std::string obj_statements_used(std::string_view text) {
    return statements_kept(text, [](std::string_view keyword) {
        return keyword == "v" || keyword == "vn" || keyword == "vt" || keyword == "f" || keyword == "o" ||
               keyword == "g" || keyword == "s";
    });
}

namespace {

// The longest path the system opens (PATH_MAX): a longer rest of a line names no file.
constexpr std::size_t kLongestLibraryName = 4096;

// The rest of an `mtllib` statement after its keyword, without the blanks around it, where it
// holds a space (it would be cut into names) and may be a file's name; "" otherwise.
std::string whole_library_name(std::string_view rest) {
    const auto blank = [](char c) { return c == ' ' || c == '\t'; };
    std::size_t first = 0, end = rest.size();
    while (first < end && blank(rest[first])) ++first;
    while (end > first && blank(rest[end - 1])) --end;
    const std::string_view whole = rest.substr(first, end - first);
    if (whole.find(' ') == std::string_view::npos || whole.size() > kLongestLibraryName) return {};
    return std::string(whole);
}

// Calls `visit(name)` for each name of `mtllib` statement `line`, as tinyobjloader cuts them: the
// text after "mtllib" and one blank, cut at spaces, a backslash keeping the next character;
// empty names dropped. Stops when `visit` returns false, and then returns false.
template <typename Visit>
bool visit_library_names(std::string_view line, Visit&& visit, const LibraryFileExists& exists) {
    const std::size_t at = line.find("mtllib") + 6;
    if (at >= line.size()) return true;  // "mtllib" alone
    if (std::string whole = whole_library_name(line.substr(at)); !whole.empty() && exists && exists(whole))
        return visit(std::move(whole));
    std::string name;
    bool escaped = false;
    for (const char c : line.substr(at + 1)) {
        if (!escaped && c == '\\') {
            escaped = true;
            continue;
        }
        if (!escaped && c == ' ') {
            if (!name.empty() && !visit(std::move(name))) return false;
            name.clear();
            continue;
        }
        escaped = false;
        name += c;
    }
    return name.empty() || visit(std::move(name));
}

// The material name of a `usemtl` statement, as tinyobjloader reads it: its first word.
std::string used_material_name(std::string_view statement) {
    const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
    std::size_t at = statement.find("usemtl") + 6;
    while (at < statement.size() && blank(statement[at])) ++at;
    std::size_t end = at;
    while (end < statement.size() && !blank(statement[end])) ++end;
    return std::string(statement.substr(at, end - at));
}

// The whole material name of a `usemtl` statement: the rest of it, without its comment and the
// blanks around it.
std::string whole_material_name(std::string_view statement) {
    const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
    statement = statement_of(statement);
    std::size_t at = statement.find("usemtl") + 6, end = statement.size();
    while (at < end && blank(statement[at])) ++at;
    while (end > at && blank(statement[end - 1])) --end;
    return std::string(statement.substr(at, end - at));
}

// Adds the names of `mtllib` statement `line` (line `number`) that `seen` does not hold yet.
void add_new_library_names(std::string_view line, std::uint64_t number, std::unordered_set<std::string>& seen,
                           std::vector<ObjLibraryName>& libraries, const LibraryFileExists& exists) {
    visit_library_names(
        line,
        [&](std::string name) {
            if (seen.insert(name).second) libraries.push_back({std::move(name), number});
            return true;
        },
        exists);
}

}  // namespace

// Each name once, however many lines repeat it: a file of millions of `usemtl` or `mtllib`
// lines holds one entry per name.
ObjMaterialStatements material_statements(std::string_view text, const LibraryFileExists& exists) {
    ObjMaterialStatements found;
    std::unordered_set<std::string> libraries;
    std::unordered_map<std::string, std::size_t> uses;  // a name's entry in found.uses
    bool faces_begun = false;
    for_each_line(without_byte_order_mark(text), [&](std::uint64_t number, std::string_view line) {
        const std::string_view keyword = keyword_of(line);
        if (keyword == "mtllib") {
            add_new_library_names(line, number, libraries, found.libraries, exists);
        } else if (keyword == "usemtl") {
            std::string name = used_material_name(line), whole = whole_material_name(line);
            if (!faces_begun) found.first_face_material = name, found.first_face_whole = whole;
            const auto [entry, added] = uses.try_emplace(whole, found.uses.size());
            if (added) found.uses.push_back({std::move(name), std::move(whole), number, 0});
            ++found.uses[entry->second].lines;
        } else if (keyword == "f") {
            faces_begun = true;
        }
        return true;
    });
    return found;
}

void for_each_library_name(std::string_view text, const std::function<bool(std::uint64_t, std::string)>& visit,
                           const LibraryFileExists& exists) {
    for_each_line(without_byte_order_mark(text), [&](std::uint64_t number, std::string_view line) {
        if (keyword_of(line) != "mtllib") return true;
        return visit_library_names(line, [&](std::string name) { return visit(number, std::move(name)); }, exists);
    });
}

std::string mtl_statements_used(std::string_view text) {
    return statements_kept(text, [](std::string_view keyword) { return keyword == "newmtl" || keyword == "Kd"; });
}

std::uint64_t first_colour_without_material(std::string_view text) {
    std::uint64_t found = 0;
    bool named = false;
    for_each_line(without_byte_order_mark(text), [&](std::uint64_t number, std::string_view line) {
        const std::string_view keyword = keyword_of(line);
        if (keyword == "Kd" && found == 0) found = number;
        named = keyword == "newmtl";
        return !named;
    });
    return named ? found : 0;
}

ObjTextProblem check_mtl_text(std::string_view text) {
    ObjTextProblem problem;
    for_each_line(without_byte_order_mark(text), [&](std::uint64_t number, std::string_view line) {
        const std::string_view statement = statement_of(line);
        const std::vector<std::string_view> tokens = tokens_of(statement, 5);
        if (tokens.empty() || tokens[0] != "Kd") return true;
        std::string detail;
        if (tokens.size() != 4) {
            detail = "'Kd' needs 3 numbers (r g b), the line has " + std::to_string(token_count(statement) - 1);
        } else {
            detail = check_numbers(tokens, 3, false);
        }
        for (std::size_t i = 1; detail.empty() && i < tokens.size(); ++i) {
            double value = 0;
            parse_number(tokens[i], value);
            if (std::fabs(value) > kMaxMaterialColor) {
                detail = "'Kd': " + quoted(tokens[i]) + " is out of range: a colour lies from " +
                         number_text(-kMaxMaterialColor) + " to " + number_text(kMaxMaterialColor);
            }
        }
        if (detail.empty()) return true;
        problem = {number, detail};
        return false;
    });
    return problem;
}

namespace {

// Texts this long are checked in parts, one per usable CPU (a 1M-triangle OBJ is about 38 MB:
// 0.45 s on one core).
constexpr std::size_t kPartedBytes = 4u << 20;

// `text` cut into about `parts` pieces, each ending just after a "\n" (or at the text's end):
// every "\n" ends a line, so the lines of the pieces are the lines of the text.
std::vector<std::string_view> cut_at_lines(std::string_view text, std::size_t parts) {
    std::vector<std::string_view> pieces;
    std::size_t start = 0;
    for (std::size_t part = 1; part < parts && start < text.size(); ++part) {
        const std::size_t newline = text.find('\n', std::max(start, text.size() * part / parts));
        if (newline == std::string_view::npos) break;
        pieces.push_back(text.substr(start, newline + 1 - start));
        start = newline + 1;
    }
    if (start < text.size() || pieces.empty()) pieces.push_back(text.substr(start));
    return pieces;
}

// What a piece holds: its lines, and the entries, faces and triangles of its lines (every `f`
// line of three corners or more counted, as the check counts them when the line is good).
struct PieceCounts {
    std::uint64_t lines = 0;
    ObjTextCounts entries;
};

PieceCounts count_piece(std::string_view piece) {
    PieceCounts counts;
    for_each_line(piece, [&](std::uint64_t, std::string_view whole_line) {
        ++counts.lines;
        const std::string_view line = statement_of(whole_line);
        const std::string_view keyword = keyword_of(line);
        count_entry(keyword, whole_line, counts.entries);
        if (!keyword.empty() && !is_obj_statement(keyword) && counts.entries.unknown_statements++ == 0) {
            counts.entries.first_unknown_line = counts.lines;  // within the piece
            counts.entries.first_unknown_keyword = std::string(keyword.substr(0, 64));
        }
        if (keyword == "v" && token_count(line) > 5 && counts.entries.coloured_positions++ == 0)
            counts.entries.first_coloured_line = counts.lines;  // within the piece
        if (keyword == "f") {
            const std::uint64_t tokens = token_count(line);
            if (tokens >= 4) {
                ++counts.entries.faces;
                counts.entries.triangles += tokens - 3;
            }
        }
        return true;
    });
    return counts;
}

// Checks the lines of `piece`, which follow `lines_before` lines holding the entries, faces
// and triangles of `counts`; `total`: the whole text's entries. The first problem, or line 0.
ObjTextProblem check_piece(std::string_view piece, std::uint64_t lines_before, ObjTextCounts counts,
                           const ObjTextCounts& total, std::uint64_t max_triangles) {
    ObjTextProblem problem;
    for_each_line(piece, [&](std::uint64_t number, std::string_view line) {
        const std::string_view statement = statement_of(line);
        const std::vector<std::string_view> tokens = tokens_of(statement, kMaxStatementWords + 1);
        if (tokens.empty()) return true;
        const std::string_view keyword = tokens[0];
        std::string detail;
        if (tokens.size() > kMaxStatementWords && (keyword == "v" || keyword == "vn" || keyword == "vt")) {
            detail = "'" + std::string(keyword) + "' has at most " + std::to_string(kMaxStatementWords - 1) +
                     " numbers, this line has " + std::to_string(token_count(statement) - 1);
        } else if (keyword == "v") detail = check_numbers(tokens, 3, true);
        else if (keyword == "vn") detail = check_numbers(tokens, 3, false);
        else if (keyword == "vt") detail = check_numbers(tokens, 1, false);
        else if (keyword == "f") {
            if (tokens.size() < 4) {
                detail = "a face needs 3 corners or more, this one has " + std::to_string(tokens.size() - 1);
            } else if (tokens.size() > kMaxStatementWords) {
                detail = "a face has at most " + std::to_string(kMaxFaceCorners) + " corners (tinyobjloader's limit), "
                         "this one has " + std::to_string(token_count(statement) - 1) + ": split it into smaller faces";
            }
            for (std::size_t i = 1; detail.empty() && i < tokens.size(); ++i) {
                detail = check_corner(tokens[i], counts, total);
                if (!detail.empty()) detail = "corner " + std::to_string(i) + ": " + detail;
            }
            if (detail.empty()) {
                ++counts.faces;
                counts.triangles += tokens.size() - 3;
                if (counts.triangles > max_triangles) {
                    detail = "the faces up to this line make " + std::to_string(counts.triangles) +
                             " triangles, more than the limit of " + std::to_string(max_triangles);
                }
            }
        }
        if (!detail.empty()) {
            problem = {lines_before + number, detail};
            return false;
        }
        count_entry(keyword, line, counts);
        return true;
    });
    return problem;
}

void add(ObjTextCounts& sum, const ObjTextCounts& more) {
    sum.positions += more.positions;
    sum.normals += more.normals;
    sum.texcoords += more.texcoords;
    sum.faces += more.faces;
    sum.triangles += more.triangles;
    sum.named_statements += more.named_statements;
    sum.grouping_statement_bytes += more.grouping_statement_bytes;
    sum.unknown_statements += more.unknown_statements;
    sum.coloured_positions += more.coloured_positions;
}

}  // namespace

// Two passes over the text, each over its pieces in parallel: the first counts each piece's
// lines and entries, so that the second can check each piece knowing what precedes it and what
// the whole file holds. The first problem is the one of the earliest piece that has one: any
// earlier line with a problem would be in that piece or an earlier one, so the counts the
// piece starts from (which count every line) are what a single pass would have reached.
ObjTextCounts check_obj_text(std::string_view text, std::uint64_t max_triangles, ObjTextProblem& problem) {
    problem = {};
    text = without_byte_order_mark(text);
    const std::size_t parts = text.size() >= kPartedBytes ? static_cast<std::size_t>(usable_cpu_count()) : 1;
    const std::vector<std::string_view> pieces = cut_at_lines(text, parts);
    std::vector<PieceCounts> counted(pieces.size());
    parallel_for(pieces.size(), parts, [&](std::size_t i) { counted[i] = count_piece(pieces[i]); });
    std::vector<PieceCounts> before(pieces.size());  // what precedes each piece
    ObjTextCounts total;
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        if (i > 0) {
            before[i] = before[i - 1];
            before[i].lines += counted[i - 1].lines;
            add(before[i].entries, counted[i - 1].entries);
        }
        add(total, counted[i].entries);
        if (total.first_unknown_line == 0 && counted[i].entries.first_unknown_line != 0) {
            total.first_unknown_line = before[i].lines + counted[i].entries.first_unknown_line;
            total.first_unknown_keyword = counted[i].entries.first_unknown_keyword;
        }
        if (total.first_coloured_line == 0 && counted[i].entries.first_coloured_line != 0)
            total.first_coloured_line = before[i].lines + counted[i].entries.first_coloured_line;
    }
    std::vector<ObjTextProblem> problems(pieces.size());
    parallel_for(pieces.size(), parts, [&](std::size_t i) {
        problems[i] = check_piece(pieces[i], before[i].lines, before[i].entries, total, max_triangles);
    });
    for (const ObjTextProblem& found : problems) {
        if (found.line != 0) {
            problem = found;
            break;
        }
    }
    return total;
}

}  // namespace clr
