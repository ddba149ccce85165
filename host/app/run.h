// The program once its options are parsed: load, render, write. Returns the exit code;
// errors are thrown as clr::Error and mapped to exit codes by main().
#pragma once

#include "app/options.h"

namespace clr {

int run(const Options& options);

}  // namespace clr
