// The OpenCL C sources of clrender, embedded into the binary at build time
// (cmake/embed_kernels.cmake) or read from a folder for kernel development, and assembled
// into one program source per program.
#pragma once

#include <string>
#include <vector>

namespace clr {

struct EmbeddedKernelFile {
    const char* path;  // relative to kernels/, e.g. "intersect.cl"
    const char* text;
};

// Every file under kernels/, in no particular order.
const std::vector<EmbeddedKernelFile>& embedded_kernel_files();

// The programs clrender builds, each from one entry file under kernels/programs/ that
// includes what its kernels use (docs/architecture.md, Kernel files and programs).
struct KernelProgram {
    const char* entry;   // relative to kernels/
    const char* kernel;  // the kernel the renderer runs from it (test programs: one of several)
};
// render_packets: what the command line renders with.
inline constexpr KernelProgram kRenderTilesProgram{"programs/render_tiles.cl", "render_packets"};
// render: every pixel tests every object (the tests' reference; RendererOptions::screen_tiles off).
inline constexpr KernelProgram kRenderBruteForceProgram{"programs/render_brute_force.cl", "render"};
// The stage kernels raygen, intersect, shade and struct_layout, for the tests.
inline constexpr KernelProgram kTestStagesProgram{"programs/test_stages.cl", "raygen"};

// The program source of `entry` (relative to kernels/): the file with each `#include "..."`
// line replaced by the named file (relative to kernels/), itself resolved the same way.
// Each file goes in once, at its first include; later includes of it become empty lines.
// #line markers keep compiler messages naming kernels/<file> and its real line numbers.
// With a non-empty `kernel_dir`, files are read from that folder instead of the embedded
// copies. Throws DeviceError naming the file and line of an include that names no file.
std::string assemble_program_source(const std::string& entry, const std::string& kernel_dir = "");

}  // namespace clr
