// Which build of clrender, or of a library it uses, holds a function: for the caches' keys, so
// that a new build (a rebuild, an install, an upgrade) changes every key its code could change.
#pragma once

#include <string>

namespace clr {

// The file the code of `function` was loaded from, with its size and modification time. The
// main program is the file that runs (/proc/self/exe), whatever name it was started by: the
// system names it by its argv[0], which is no path when a shell found it through PATH
// ("clrender") and may lead to another file once a new build is put under its name.
// "unknown" when the system does not say.
std::string code_file_identity(const void* function);

}  // namespace clr
