// The references in the repository's code, scripts and docs lead somewhere a newcomer can
// follow: no numbered SPEC section or issue (documents outside the repository), and every
// "(docs/<name>.md, <Section>)" names a document and a heading that exist, so that renaming a
// section without updating what cites it fails here.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "support/markdown_sections.h"
#include "support/source_references.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using testing::doc_references;
using testing::markdown_headings;
using testing::MarkdownHeading;
using testing::names_a_heading;
using testing::numbered_citations;
using testing::repository_texts;
using testing::SourceText;

const fs::path kRoot = CLRENDER_SOURCE_DIR;

// The numbered citations of `text`, as a file named x.cpp.
std::vector<std::string> citations_in(const std::string& text) { return numbered_citations({"x.cpp", text}); }

// The headings of each cited document, read once.
class DocHeadings {
public:
    const std::vector<MarkdownHeading>* of(const std::string& doc) {
        auto found = cache_.find(doc);
        if (found == cache_.end()) {
            const fs::path path = kRoot / doc;
            std::optional<std::vector<MarkdownHeading>> headings;
            if (fs::is_regular_file(path)) {
                std::ifstream in(path);
                headings = markdown_headings(std::string(std::istreambuf_iterator<char>(in), {}));
            }
            found = cache_.emplace(doc, headings).first;
        }
        return found->second ? &*found->second : nullptr;
    }

private:
    std::map<std::string, std::optional<std::vector<MarkdownHeading>>> cache_;
};

TEST(SourceReferences, TheScanReadsTheRepositorysCodeScriptsAndDocs) {
    const std::vector<SourceText> files = repository_texts(kRoot);
    auto has = [&](const std::string& path) {
        return std::any_of(files.begin(), files.end(), [&](const SourceText& file) { return file.path == path; });
    };
    for (const char* path : {"host/app/main.cpp", "kernels/raygen.cl", "kernels/shared/clr_samples.h",
                             "bench/embree_peer.cpp", "scripts/fuzz.sh", "fuzz/scene_fuzzer.cpp",
                             "cmake/embed_kernels.cmake", "docs/scene-format.md", "tests/scripts/source_references_test.cpp",
                             ".ci/run", "README.md", "CMakeLists.txt"})
        EXPECT_TRUE(has(path)) << path;
    EXPECT_FALSE(has("scenes/demo/checker.png"));
}

TEST(SourceReferences, NoCommentCitesASpecOrIssueNumber) {
    std::vector<std::string> found;
    for (const SourceText& file : repository_texts(kRoot)) {
        for (const std::string& citation : numbered_citations(file)) found.push_back(citation);
    }
    for (const std::string& citation : found)
        ADD_FAILURE() << citation << "\n  cite the docs section instead, e.g. (docs/scene-format.md, Conventions: Camera)";
}

TEST(SourceReferences, EveryCitedDocsSectionExists) {
    DocHeadings docs;
    int checked = 0;
    for (const SourceText& file : repository_texts(kRoot)) {
        for (const testing::DocReference& reference : doc_references(file)) {
            ++checked;
            const std::string where = reference.path + ":" + std::to_string(reference.line) + ": (" + reference.doc +
                                      ", " + reference.section + ")";
            const std::vector<MarkdownHeading>* headings = docs.of(reference.doc);
            if (!headings) {
                ADD_FAILURE() << where << ": there is no " << reference.doc;
            } else if (!names_a_heading(*headings, reference.section)) {
                ADD_FAILURE() << where << ": " << reference.doc << " has no heading '" << reference.section << "'";
            }
        }
    }
    EXPECT_GT(checked, 20) << "the references in the code were not found";
}

// The scanner itself, on text whose answer is known.

TEST(SourceReferences, FindsNumberedCitationsWithTheirLine) {
    const std::string spec = std::string("SPEC") + " 2";
    const std::string issue = std::string("issue") + " 5";
    EXPECT_EQ(citations_in("int a;\n// the camera (" + spec + ", Camera)\n"),
              std::vector<std::string>{"x.cpp:2: // the camera (" + spec + ", Camera)"});
    EXPECT_EQ(citations_in("/* " + issue + " */\n").size(), 1u);
    EXPECT_EQ(citations_in("# " + std::string("Issue") + " #6\n").size(), 1u);
    EXPECT_EQ(citations_in("// ../shared/" + std::string("SPEC") + ".md says\n").size(), 1u);
    EXPECT_TRUE(citations_in("// SPECTRUM 2, tissue 5, an issue with 3 frames\n").empty());
    // Another project's issue, named with its repository, can be looked up.
    EXPECT_TRUE(citations_in("// a heap overflow (nothings/stb " + std::string("issue") + " #1289)\n").empty());
    EXPECT_EQ(citations_in("// nothings/stb " + std::string("issue") + " #1289 and " + issue + "\n").size(), 1u);
}

TEST(SourceReferences, FindsDocsReferencesAcrossCommentLines) {
    const SourceText file{"a.cpp",
                          "// one (docs/scene-format.md, Conventions: Camera) and\n"
                          "    // another (docs/benchmarks.md, Figures behind design\n"
                          "    // choices); a third in docs/command-line.md, Exit codes; README.md, Using it)\n"
                          "# docs/scene-format.md, and every key, variant (a sentence, not a reference)\n"
                          "/* (docs/scene-format.md, \"Impostors: billboards that face the camera\") */\n"
                          "// fuzz/README.md, Targets) is another README\n"};
    const std::vector<testing::DocReference> found = doc_references(file);
    ASSERT_EQ(found.size(), 5u);
    EXPECT_EQ(found[0].line, 1);
    EXPECT_EQ(found[0].doc, "docs/scene-format.md");
    EXPECT_EQ(found[0].section, "Conventions: Camera");
    EXPECT_EQ(found[1].line, 2);
    EXPECT_EQ(found[1].section, "Figures behind design choices");
    EXPECT_EQ(found[2].doc, "docs/command-line.md");
    EXPECT_EQ(found[2].section, "Exit codes");
    EXPECT_EQ(found[3].doc, "README.md");
    EXPECT_EQ(found[3].section, "Using it");
    EXPECT_EQ(found[4].line, 5);
    EXPECT_EQ(found[4].section, "Impostors: billboards that face the camera");
}

TEST(SourceReferences, SectionsNameHeadingsByTitleShortTitleOrPath) {
    const std::vector<MarkdownHeading> headings = markdown_headings(
        "# Scene format\n## Keys\n### Billboards\n## Conventions\n### Camera\n### Billboards\n"
        "```sh\n# Camera path\n```\n## Impostors: billboards that face the camera\n### Placement\n");
    ASSERT_EQ(headings.size(), 8u);
    EXPECT_TRUE(names_a_heading(headings, "Keys"));
    EXPECT_TRUE(names_a_heading(headings, "Conventions: Camera"));
    EXPECT_TRUE(names_a_heading(headings, "Conventions: Billboards"));
    EXPECT_TRUE(names_a_heading(headings, "Keys: Billboards"));
    EXPECT_TRUE(names_a_heading(headings, "Impostors"));
    EXPECT_TRUE(names_a_heading(headings, "Impostors: billboards that face the camera"));
    EXPECT_TRUE(names_a_heading(headings, "Impostors: Placement"));
    EXPECT_FALSE(names_a_heading(headings, "Keys: Camera"));        // Camera is not under Keys
    EXPECT_FALSE(names_a_heading(headings, "Conventions: Mirrors"));
    EXPECT_FALSE(names_a_heading(headings, "Camera path"));          // a shell comment in a fence
    EXPECT_FALSE(names_a_heading(headings, "Impost"));
}

}  // namespace
}  // namespace clr
