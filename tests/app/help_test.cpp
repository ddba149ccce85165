// The end of --help (docs/command-line.md, Environment; docs/command-line.md, Exit codes):
// every environment variable the sources read is listed, and the exit codes are the
// documented ones, so that neither can drift from the code or the docs unnoticed.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "support/command.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using testing::read_bytes;
using testing::run_clrender;

// The lines of --help's section `heading` ("Environment:") up to the next empty line.
std::vector<std::string> help_section(const std::string& help, const std::string& heading) {
    std::istringstream lines(help);
    std::vector<std::string> section;
    bool inside = false;
    for (std::string line; std::getline(lines, line);) {
        if (line == heading) {
            inside = true;
        } else if (inside) {
            if (line.empty()) break;
            section.push_back(line);
        }
    }
    return section;
}

// The first word of each entry of a section (continuation lines, indented deeper, have none).
std::set<std::string> section_keys(const std::vector<std::string>& section) {
    std::set<std::string> keys;
    static const std::regex entry(R"(^  (\S+)( .*)?$)");
    std::smatch match;
    for (const std::string& line : section) {
        if (std::regex_match(line, match, entry)) keys.insert(match[1]);
    }
    return keys;
}

// The variables host/ reads with getenv: named by a literal, or by a constant defined in host/
// as a literal. A getenv whose variable cannot be told is reported as "?<argument>".
std::set<std::string> variables_read_by_the_sources() {
    std::string all;
    for (const auto& entry : fs::recursive_directory_iterator(fs::path(CLRENDER_SOURCE_DIR) / "host")) {
        const std::string extension = entry.path().extension().string();
        if (entry.is_regular_file() && (extension == ".cpp" || extension == ".h")) all += read_bytes(entry.path());
    }
    std::map<std::string, std::string> constants;
    static const std::regex constant(R"re(\b(k[A-Za-z0-9_]*)\s*=\s*"([A-Za-z_][A-Za-z0-9_]*)")re");
    for (std::sregex_iterator it(all.begin(), all.end(), constant), end; it != end; ++it)
        constants[(*it)[1]] = (*it)[2];
    std::set<std::string> variables;
    static const std::regex call(R"re(getenv\(\s*(?:"([^"]*)"|([A-Za-z_][A-Za-z0-9_:]*))\s*\))re");
    for (std::sregex_iterator it(all.begin(), all.end(), call), end; it != end; ++it) {
        if ((*it)[1].matched) {
            variables.insert((*it)[1]);
        } else {
            const auto found = constants.find((*it)[2]);
            variables.insert(found != constants.end() ? found->second : "?" + std::string((*it)[2]));
        }
    }
    return variables;
}

TEST(Help, ListsEveryEnvironmentVariableTheSourcesRead) {
    const auto help = run_clrender("--help");
    ASSERT_EQ(help.exit_code, 0) << help.output;
    const std::set<std::string> listed = section_keys(help_section(help.output, "Environment:"));
    std::set<std::string> read = variables_read_by_the_sources();
    EXPECT_GE(read.size(), 7u) << "the scan found too few getenv calls to be right";
    // Every program reads these two, and --help names them within other entries.
    read.erase("PATH");
    read.erase("HOME");
    EXPECT_EQ(listed, read) << "--help's Environment section and the getenv calls in host/ differ";
}

// The codes of docs/command-line.md's Exit codes table: "0", ..., "6", "128 + signal".
std::set<std::string> documented_exit_codes() {
    const std::string doc = read_bytes(fs::path(CLRENDER_SOURCE_DIR) / "docs/command-line.md");
    const std::string table = doc.substr(doc.find("## Exit codes"));
    std::set<std::string> codes;
    static const std::regex row(R"(\n\| ([0-9][^|]*?) \|)");
    for (std::sregex_iterator it(table.begin(), table.end(), row), end; it != end; ++it) codes.insert((*it)[1]);
    return codes;
}

TEST(Help, ListsTheDocumentedExitCodes) {
    const auto help = run_clrender("--help");
    std::set<std::string> listed = section_keys(help_section(help.output, "Exit status:"));
    if (listed.erase("128+N") == 1) listed.insert("128 + signal");
    EXPECT_EQ(listed, documented_exit_codes());
    EXPECT_EQ(listed.size(), 9u);
}

TEST(Help, EndsWithExamplesThatRunClrender) {
    const auto help = run_clrender("--help");
    const auto examples = help_section(help.output, "Examples:");
    int commands = 0;
    for (const std::string& line : examples) commands += line.rfind("  clrender ", 0) == 0;
    EXPECT_EQ(commands, 4) << help.output;
}

// --placeholders stands in for unreadable meshes too, and the help must say so (CLI11 may wrap
// the text: the words are searched with any whitespace between them).
TEST(Help, SaysThatPlaceholdersCoverMeshes) {
    const auto help = run_clrender("--help");
    std::string words;
    std::istringstream stream(help.output);
    for (std::string word; stream >> word;) words += word + " ";
    EXPECT_NE(words.find("--placeholders Render a magenta checkerboard for billboard images, and a unit cube for OBJ meshes,"),
              std::string::npos)
        << help.output;
}

TEST(Help, KeepsTheCompletionWordsOptionHidden) {
    const auto help = run_clrender("--help");
    EXPECT_EQ(help.output.find("--completion-words"), std::string::npos);
    const auto words = run_clrender("--completion-words");
    EXPECT_EQ(words.exit_code, 0);
    // Each option with a value says its type; flags say nothing.
    EXPECT_NE(words.output.find("\n--precision TEXT:{float,double}\n"), std::string::npos) << words.output;
    EXPECT_NE(words.output.find("\n--quiet\n"), std::string::npos) << words.output;
    EXPECT_NE(words.output.find("\n-o TEXT\n"), std::string::npos) << words.output;
}

}  // namespace
}  // namespace clr
