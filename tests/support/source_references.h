// What the repository's text files cite: numbered references to documents outside it (a
// section of a "SPEC" or an "issue" followed by its number), which a reader of the repository
// cannot look up, and references to sections of its own docs ("(docs/scene-format.md,
// Conventions: Camera)"), which must keep naming a heading that exists
// (support/markdown_sections.h says how a section is named).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace clr::testing {

struct SourceText {
    std::string path;  // relative to the repository root, with '/'
    std::string text;
};

// The text files of the repository's code, scripts and documentation: host/, kernels/,
// bench/, tests/, scripts/, fuzz/, cmake/, docs/, .ci/, and the top-level CMakeLists.txt and
// README.md. Build folders and the scenes' images are not among them.
std::vector<SourceText> repository_texts(const std::filesystem::path& root);

// "PATH:LINE: the line" for every line that cites a numbered SPEC section, the SPEC file or a
// numbered issue. An issue of another project, named with its repository ("nothings/stb issue
// #<number>"), can be looked up and is not counted.
std::vector<std::string> numbered_citations(const SourceText& file);

struct DocReference {
    std::string path;     // the citing file
    int line = 0;         // where the reference starts, from 1
    std::string doc;      // "docs/scene-format.md"
    std::string section;  // "Conventions: Camera"
};

// Every "docs/<name>.md, <Section>" (or "README.md, <Section>") ended by ')' or ';', the form
// comments cite sections in. Comment markers at the start of lines are dropped and lines are
// joined first, so a reference may wrap onto the next comment line. A section starts with a
// capital letter, or is in double quotes, so that "docs/x.md, and ..." in a sentence is not
// taken for one.
std::vector<DocReference> doc_references(const SourceText& file);

}  // namespace clr::testing
