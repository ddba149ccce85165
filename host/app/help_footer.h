// The end of `clrender --help`: the environment variables clrender reads, its exit codes and
// a few examples (docs/command-line.md, Environment; docs/command-line.md, Exit codes). The man page is made
// from --help, so this is also its ENVIRONMENT, EXIT STATUS and EXAMPLES.
#pragma once

#include <string>

namespace clr {

std::string help_footer();

}  // namespace clr
