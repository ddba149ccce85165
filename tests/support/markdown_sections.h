// The headings of a Markdown document, and whether a section name that a comment cites names
// one of them. A citation names a heading by its title ("Numeric ranges"), by the part of the
// title before a colon ("Impostors" for "Impostors: billboards that face the camera"), or by
// a path of such names from an outer heading to one nested under it, joined by ": "
// ("Conventions: Camera" for the "Camera" subsection of "Conventions"), which tells apart
// two subsections of the same title under different sections.
#pragma once

#include <string>
#include <vector>

namespace clr::testing {

struct MarkdownHeading {
    int level = 0;      // 1 for "#", 2 for "##", ...
    std::string title;  // without the #s and surrounding spaces
};

// The ATX headings ("## Title") of a Markdown text, in order; lines inside ``` fences (shell
// comments in examples) are not headings.
std::vector<MarkdownHeading> markdown_headings(const std::string& markdown);

// Whether `section` names a heading of `headings`, by the rules above.
bool names_a_heading(const std::vector<MarkdownHeading>& headings, const std::string& section);

}  // namespace clr::testing
