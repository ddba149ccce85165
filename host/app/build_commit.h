// The source's git commit at build time (`git describe --always --dirty`), or "unknown" when
// it was not built from a git checkout. Defined in a file that cmake/write_version.cmake
// writes at every build (docs/command-line.md, Version).
#pragma once

namespace clr {

const char* build_commit();

}  // namespace clr
