// The OpenCL C sources of clrender, embedded into the binary at build time
// (cmake/embed_kernels.cmake) or read from a folder for kernel development.
#pragma once

#include <string>
#include <vector>

namespace clr {

struct EmbeddedKernelFile {
    const char* path;  // relative to kernels/, e.g. "intersect.cl"
    const char* text;
};

// Every kernel file, in the order in which they form one program.
const std::vector<EmbeddedKernelFile>& embedded_kernel_files();

// The program source: every kernel file in order, each preceded by a #line marker naming
// it. With a non-empty `kernel_dir`, the files are read from that folder instead of the
// embedded copies (throws DeviceError if one is missing).
std::string assemble_program_source(const std::string& kernel_dir = "");

}  // namespace clr
