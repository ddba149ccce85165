#include "device/kernel_sources.h"

#include <fstream>
#include <sstream>

#include "core/errors.h"

namespace clr {
namespace {

std::string read_kernel_file(const std::string& kernel_dir, const std::string& relative_path) {
    std::string path = kernel_dir + "/" + relative_path;
    std::ifstream in(path, std::ios::binary);
    if (!in) throw DeviceError("cannot read kernel source '" + path + "'");
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

}  // namespace

std::string assemble_program_source(const std::string& kernel_dir) {
    std::string source;
    for (const EmbeddedKernelFile& file : embedded_kernel_files()) {
        std::string text = kernel_dir.empty() ? file.text : read_kernel_file(kernel_dir, file.path);
        // The marker makes compiler messages name kernels/<file> and its real line numbers.
        source += "#line 1 \"kernels/" + std::string(file.path) + "\"\n";
        source += text;
        source += "\n";
    }
    return source;
}

}  // namespace clr
