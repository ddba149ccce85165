// What `clrender --version` prints (docs/command-line.md, Version): the version, the git
// commit it was built from, and the OpenCL platforms this machine offers, so that a bug
// report carries all three.
#pragma once

#include <string>

namespace clr {

// "clrender 0.1.0\ncommit: f99bf4e\nOpenCL platforms:\n  NAME (VERSION)", the last line
// "OpenCL platforms: none" when no OpenCL driver is installed; no final newline (CLI11 adds
// it). Never throws for OpenCL's sake: a failing ICD loader is reported in the text, since
// --version must always answer.
std::string version_text();

}  // namespace clr
