#include "device/device_context.h"

#include "core/errors.h"
#include "device/cl_errors.h"

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
    cl::Program program(context_, source);
    try {
        program.build({entry_.device}, options.c_str());
    } catch (const cl::Error& error) {
        std::string log;
        try {
            log = program.getBuildInfo<CL_PROGRAM_BUILD_LOG>(entry_.device);
        } catch (const cl::Error&) {
            log = "(no build log available)";
        }
        throw DeviceError(describe_cl_error(error, "building the OpenCL program for '" + entry_.device_name + "'") +
                          "\nbuild options: " + options + "\nbuild log:\n" + log);
    }
    return program;
}

}  // namespace clr
