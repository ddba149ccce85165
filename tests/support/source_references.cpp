#include "support/source_references.h"

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

namespace clr::testing {
namespace {

namespace fs = std::filesystem;

const std::vector<std::string> kScannedFolders = {"host",  "kernels", "bench", "tests", "scripts",
                                                  "fuzz",  "cmake",   "docs",  ".ci"};
const std::vector<std::string> kScannedTopLevelFiles = {"CMakeLists.txt", "README.md"};
const std::set<std::string> kTextExtensions = {".c",  ".cc",   ".cpp", ".h",    ".hpp",  ".cl", ".cmake",
                                               ".sh", ".py",   ".txt", ".dict", ".md",   ".json", ".supp"};

std::string read_text(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// Source by extension, or an extensionless script (`.ci/run`).
bool is_scanned_text(const fs::path& path) {
    if (kTextExtensions.count(path.extension().string()) > 0) return true;
    return path.extension().empty() && read_text(path).rfind("#!", 0) == 0;
}

// A line without its indentation and the comment markers that start it (//, /*, *, #).
std::string comment_body(const std::string& line) {
    std::size_t start = line.find_first_not_of(" \t");
    if (start == std::string::npos) return "";
    if (line.compare(start, 2, "//") == 0 || line.compare(start, 2, "/*") == 0) {
        start = line.find_first_not_of("/*", start);
    } else if (line[start] == '#' || (line[start] == '*' && line.compare(start, 2, "*/") != 0)) {
        start = line.find_first_not_of(line[start], start);
    }
    if (start == std::string::npos) return "";
    start = line.find_first_not_of(" \t", start);
    return start == std::string::npos ? "" : line.substr(start);
}

// The document a reference's "NAME.md" ends at `md_end` in `text`: "docs/NAME.md" or
// "README.md" standing alone (not "fuzz/README.md"), else empty.
std::string cited_doc(const std::string& text, std::size_t md_end) {
    std::size_t start = md_end;
    while (start > 0 && (std::isalnum(static_cast<unsigned char>(text[start - 1])) || text[start - 1] == '/' ||
                         text[start - 1] == '-' || text[start - 1] == '_' || text[start - 1] == '.'))
        --start;
    const std::string token = text.substr(start, md_end - start);
    static const std::regex doc_name(R"(docs/[A-Za-z0-9_-]+\.md|README\.md)");
    return std::regex_match(token, doc_name) ? token : "";
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

}  // namespace

std::vector<SourceText> repository_texts(const fs::path& root) {
    std::vector<SourceText> files;
    auto add = [&](const fs::path& path) {
        files.push_back({fs::relative(path, root).generic_string(), read_text(path)});
    };
    for (const std::string& folder : kScannedFolders) {
        if (!fs::is_directory(root / folder)) continue;
        for (const auto& entry : fs::recursive_directory_iterator(root / folder)) {
            if (entry.is_regular_file() && is_scanned_text(entry.path())) add(entry.path());
        }
    }
    for (const std::string& name : kScannedTopLevelFiles) {
        if (fs::is_regular_file(root / name)) add(root / name);
    }
    std::sort(files.begin(), files.end(), [](const SourceText& a, const SourceText& b) { return a.path < b.path; });
    return files;
}

std::vector<std::string> numbered_citations(const SourceText& file) {
    static const std::regex citation(R"(\bSPEC ?[0-9]|\bSPEC\.md\b|\b[Ii]ssue #?[0-9])");
    static const std::regex another_projects_issue(R"([A-Za-z0-9_.-]+/[A-Za-z0-9_.-]+ issue #?[0-9])");
    std::vector<std::string> found;
    const std::vector<std::string> lines = lines_of(file.text);
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const std::string unnamed = std::regex_replace(lines[i], another_projects_issue, "");
        if (std::regex_search(unnamed, citation))
            found.push_back(file.path + ":" + std::to_string(i + 1) + ": " + lines[i]);
    }
    return found;
}

std::vector<DocReference> doc_references(const SourceText& file) {
    // The comment text of every line joined by spaces, and where each line starts in it.
    std::string joined;
    std::vector<std::size_t> line_starts;
    for (const std::string& line : lines_of(file.text)) {
        line_starts.push_back(joined.size());
        joined += comment_body(line) + " ";
    }
    // The section: in double quotes, or from a capital letter up to the ')' or ';' that ends
    // the reference, without a comma or full stop (then it was a sentence, not a reference).
    static const std::regex section_then_end(R"(("[^"]+"|[A-Z][^(),;."]*)[);])");
    std::vector<DocReference> found;
    const std::string separator = ".md, ";
    for (std::size_t at = joined.find(separator); at != std::string::npos; at = joined.find(separator, at + 1)) {
        const std::string doc = cited_doc(joined, at + 3);
        std::smatch match;
        const auto after = joined.cbegin() + static_cast<std::ptrdiff_t>(at + separator.size());
        if (doc.empty() || !std::regex_search(after, joined.cend(), match, section_then_end,
                                              std::regex_constants::match_continuous))
            continue;
        std::string section = match[1].str();
        if (section.front() == '"') section = section.substr(1, section.size() - 2);
        section = std::regex_replace(section, std::regex(R"(\s+)"), " ");
        section.erase(section.find_last_not_of(' ') + 1);
        const auto line = std::upper_bound(line_starts.begin(), line_starts.end(), at) - line_starts.begin();
        found.push_back({file.path, static_cast<int>(line), doc, section});
    }
    return found;
}

}  // namespace clr::testing
