// Build options that make a device's float division and square root exact.
#pragma once

#include <string>

#include "device/opencl.h"

namespace clr {

// `options` with -cl-fp32-correctly-rounded-divide-sqrt added where the device offers correctly
// rounded float division and sqrt (CL_DEVICE_SINGLE_FP_CONFIG). OpenCL lets a device round them
// within 2.5 and 3 ulp unless a program asks; a GPU's driver does, and then the mean of three
// samples came out 1/255 off PoCL's in up to 14% of the pixels (docs/opencl-devices.md, A GPU).
// PoCL's CPU device divides exactly either way. Every build of a program goes through this.
std::string with_exact_arithmetic(const cl::Device& device, const std::string& options);

}  // namespace clr
