#include "device/device_context.h"

#include <iostream>

#include "core/errors.h"
#include "device/cl_errors.h"
#include "device/program_cache.h"
#include "device/stderr_capture.h"

namespace clr {

DeviceContext::DeviceContext(const DeviceEntry& device) : entry_(device) {
    try {
        context_ = cl::Context(entry_.device);
        queue_ = cl::CommandQueue(context_, entry_.device, CL_QUEUE_PROFILING_ENABLE);
    } catch (const cl::Error& error) {
        throw DeviceError(describe_cl_error(error, "opening OpenCL device '" + entry_.device_name + "'"));
    }
}

cl::Program DeviceContext::build_program(const std::string& source, const std::string& options) const {
    // A binary from an earlier run first (device/program_cache.h); a binary the driver
    // refuses is a miss like any other.
    const ProgramCache cache = ProgramCache::from_environment();
    std::string key;
    if (cache.enabled()) {
        try {
            key = ProgramCache::key(entry_.device, source, options);
            if (auto binary = cache.load(key)) {
                cl::Program cached(context_, {entry_.device}, cl::Program::Binaries{*binary});
                cached.build({entry_.device}, options.c_str());
                ++cache_hits_;
                return cached;
            }
        } catch (const cl::Error&) {
        }
    }
    cl::Program program(context_, source);
    // The compiler's own output waits until clrender's error line, if any, is out.
    StderrCapture compiler_output;
    try {
        program.build({entry_.device}, options.c_str());
        std::cerr << compiler_output.finish();
    } catch (const cl::Error& error) {
        const std::string printed = compiler_output.finish();
        std::string log;
        try {
            log = program.getBuildInfo<CL_PROGRAM_BUILD_LOG>(entry_.device);
        } catch (const cl::Error&) {
            log = "(no build log available)";
        }
        throw DeviceError(describe_cl_error(error, "building the OpenCL program for '" + entry_.device_name + "'") +
                          "\nbuild options: " + options + "\nbuild log:\n" + log +
                          (printed.empty() ? "" : "\ncompiler output:\n" + printed));
    }
    // Asking PoCL for the binary compiles every kernel of the program (0.8 s cold): that is
    // left to store_built_programs(), after the frames are written.
    if (!key.empty()) to_store_.push_back({cache.folder(), key, program});
    return program;
}

void DeviceContext::store_built_programs() {
    for (const PendingEntry& entry : to_store_) {
        try {
            std::vector<std::vector<unsigned char>> binaries = entry.program.getInfo<CL_PROGRAM_BINARIES>();
            if (binaries.size() == 1) ProgramCache(entry.folder).store(entry.key, binaries.front());
        } catch (const cl::Error&) {  // best effort: the next run builds from source again
        }
    }
    to_store_.clear();
}

}  // namespace clr
