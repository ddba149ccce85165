#include "app/version_text.h"

#include <cctype>
#include <sstream>
#include <vector>

#include "app/build_commit.h"
#include "core/printable_text.h"
#include "device/cl_errors.h"
#include "device/opencl.h"

namespace clr {
namespace {

// Platform strings come with the C terminator or trailing blanks on some drivers.
std::string trimmed(std::string text) {
    while (!text.empty() && (text.back() == '\0' || std::isspace(static_cast<unsigned char>(text.back()))))
        text.pop_back();
    return text;
}

std::string platform_lines() {
    std::vector<cl::Platform> platforms;
    try {
        cl::Platform::get(&platforms);
    } catch (const cl::Error& error) {
        if (error.err() == -1001) return "OpenCL platforms: none\n";  // the ICD loader found no driver
        return "OpenCL platforms: none (" + describe_cl_error(error, "listing OpenCL platforms") + ")\n";
    }
    if (platforms.empty()) return "OpenCL platforms: none\n";
    std::ostringstream out;
    out << "OpenCL platforms:\n";
    for (const cl::Platform& platform : platforms) {
        out << "  " << printable(trimmed(platform.getInfo<CL_PLATFORM_NAME>())) << " ("
            << printable(trimmed(platform.getInfo<CL_PLATFORM_VERSION>())) << ")\n";
    }
    return out.str();
}

}  // namespace

std::string version_text() {
    std::string text = std::string("clrender ") + CLRENDER_VERSION + "\ncommit: " + build_commit() + "\n";
    try {
        text += platform_lines();
    } catch (const cl::Error& error) {  // a driver failing to describe its platform
        text += "OpenCL platforms: unknown (" + describe_cl_error(error, "describing OpenCL platforms") + ")\n";
    }
    text.pop_back();
    return text;
}

}  // namespace clr
