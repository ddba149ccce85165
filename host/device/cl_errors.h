// OpenCL error codes by name, and the conversion of the bindings' exceptions into
// clrender's DeviceError so every OpenCL failure is reported with its name.
#pragma once

#include <string>

#include "device/opencl.h"

namespace clr {

// "CL_OUT_OF_RESOURCES" for -5, and so on; "unknown OpenCL error <code>" otherwise.
std::string cl_error_name(cl_int code);

// "<what>: <OpenCL call> failed with CL_..." for an exception thrown by the bindings.
std::string describe_cl_error(const cl::Error& error, const std::string& what);

}  // namespace clr
