#include "device/kernel_sources.h"

#include <fstream>
#include <optional>
#include <set>
#include <sstream>

#include "core/errors.h"

namespace clr {
namespace {

// The includes are resolved here rather than by the OpenCL compiler: the sources are strings
// embedded in the binary, not files the compiler could open, and OpenCL 1.2's way of handing
// it headers (clCompileProgram with input headers, then clLinkProgram) would change how
// programs are built and how their binaries are cached (device/program_cache.h). One
// self-contained source keeps clBuildProgram, and the cache key hashes all of it.

std::optional<std::string> embedded_text(const std::string& relative_path) {
    for (const EmbeddedKernelFile& file : embedded_kernel_files())
        if (relative_path == file.path) return std::string(file.text);
    return std::nullopt;
}

std::optional<std::string> file_text(const std::string& kernel_dir, const std::string& relative_path) {
    if (kernel_dir.empty()) return embedded_text(relative_path);
    std::ifstream in(kernel_dir + "/" + relative_path, std::ios::binary);
    if (!in) return std::nullopt;
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// The file named by a line `#include "name"` (spaces allowed around '#' and before the
// name); nothing for any other line, including `#include <...>` (host headers that the
// shared files include only outside OpenCL C).
std::optional<std::string> quoted_include(const std::string& line) {
    std::size_t at = line.find_first_not_of(" \t");
    if (at == std::string::npos || line[at] != '#') return std::nullopt;
    at = line.find_first_not_of(" \t", at + 1);
    const std::string directive = "include";
    if (at == std::string::npos || line.compare(at, directive.size(), directive) != 0) return std::nullopt;
    at = line.find_first_not_of(" \t", at + directive.size());
    if (at == std::string::npos || line[at] != '"') return std::nullopt;
    std::size_t end = line.find('"', at + 1);
    if (end == std::string::npos) return std::nullopt;
    return line.substr(at + 1, end - at - 1);
}

std::string line_marker(int line, const std::string& relative_path) {
    return "#line " + std::to_string(line) + " \"kernels/" + relative_path + "\"\n";
}

class SourceAssembler {
public:
    explicit SourceAssembler(const std::string& kernel_dir) : kernel_dir_(kernel_dir) {}

    std::string assemble(const std::string& entry) {
        std::optional<std::string> text = file_text(kernel_dir_, entry);
        if (!text) throw DeviceError("cannot read kernel source '" + display_path(entry) + "'");
        append_file(entry, *text);
        return std::move(source_);
    }

private:
    void append_file(const std::string& relative_path, const std::string& text) {
        included_.insert(relative_path);
        source_ += line_marker(1, relative_path);
        std::istringstream lines(text);
        std::string line;
        for (int number = 1; std::getline(lines, line); ++number) {
            std::optional<std::string> include = quoted_include(line);
            if (!include) {
                source_ += line + "\n";
            } else if (included_.count(*include)) {
                source_ += "\n";  // already in the program: the line count stays right
            } else {
                append_include(relative_path, number, *include);
            }
        }
    }

    void append_include(const std::string& from, int line, const std::string& include) {
        std::optional<std::string> text = file_text(kernel_dir_, include);
        if (!text)
            throw DeviceError("kernels/" + from + ":" + std::to_string(line) + ": #include \"" + include +
                              "\" names no kernel source (looked for '" + display_path(include) + "')");
        append_file(include, *text);
        source_ += line_marker(line + 1, from);
    }

    std::string display_path(const std::string& relative_path) const {
        return (kernel_dir_.empty() ? "kernels (embedded)" : kernel_dir_) + "/" + relative_path;
    }

    const std::string& kernel_dir_;
    std::set<std::string> included_;
    std::string source_;
};

}  // namespace

std::string assemble_program_source(const std::string& entry, const std::string& kernel_dir) {
    return SourceAssembler(kernel_dir).assemble(entry);
}

}  // namespace clr
