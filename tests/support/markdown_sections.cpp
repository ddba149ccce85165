#include "support/markdown_sections.h"

#include <cstddef>
#include <sstream>

namespace clr::testing {
namespace {

bool starts_with(const std::string& text, const std::string& prefix) { return text.rfind(prefix, 0) == 0; }

std::string trimmed(const std::string& text) {
    const std::size_t first = text.find_first_not_of(" \t\r");
    if (first == std::string::npos) return "";
    return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

// "Impostors" for "Impostors: billboards that face the camera".
bool title_matches(const std::string& title, const std::string& name) {
    return title == name || starts_with(title, name + ": ");
}

std::vector<std::string> split_path(const std::string& section) {
    std::vector<std::string> parts;
    std::size_t start = 0;
    for (std::size_t colon; (colon = section.find(": ", start)) != std::string::npos; start = colon + 2)
        parts.push_back(section.substr(start, colon - start));
    parts.push_back(section.substr(start));
    return parts;
}

// Whether parts[part..] name a chain of headings nested inside the heading at `parent`: the
// headings after it of a deeper level, up to the next one of its level or above.
bool path_below(const std::vector<MarkdownHeading>& headings, std::size_t parent, const std::vector<std::string>& parts,
                std::size_t part) {
    if (part == parts.size()) return true;
    for (std::size_t i = parent + 1; i < headings.size() && headings[i].level > headings[parent].level; ++i) {
        if (title_matches(headings[i].title, parts[part]) && path_below(headings, i, parts, part + 1)) return true;
    }
    return false;
}

}  // namespace

std::vector<MarkdownHeading> markdown_headings(const std::string& markdown) {
    std::vector<MarkdownHeading> headings;
    std::istringstream lines(markdown);
    bool in_fence = false;
    for (std::string line; std::getline(lines, line);) {
        if (starts_with(trimmed(line), "```")) in_fence = !in_fence;
        if (in_fence) continue;
        const std::size_t hashes = line.find_first_not_of('#');
        if (hashes == 0 || hashes == std::string::npos || hashes > 6 || line[hashes] != ' ') continue;
        headings.push_back({static_cast<int>(hashes), trimmed(line.substr(hashes))});
    }
    return headings;
}

bool names_a_heading(const std::vector<MarkdownHeading>& headings, const std::string& section) {
    const std::vector<std::string> parts = split_path(section);
    for (std::size_t i = 0; i < headings.size(); ++i) {
        if (headings[i].title == section) return true;
        if (title_matches(headings[i].title, parts.front()) && path_below(headings, i, parts, 1)) return true;
    }
    return false;
}

}  // namespace clr::testing
