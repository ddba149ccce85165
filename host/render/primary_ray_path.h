// Which way a device traces primary rays by default (RendererOptions::per_pixel): one
// work-item a pixel through the BVH on a GPU, whose lanes each follow one ray, and 16-ray packets
// in screen tiles on a CPU, whose vector units take a packet (docs/opencl-devices.md, A GPU).
#pragma once

#include "device/opencl.h"

namespace clr {

// Whether a device of `type` (CL_DEVICE_TYPE) traces per pixel: one that says it is a GPU and
// not a CPU. Oclgrind's simulator says it is every type at once and runs one work-item at a
// time; it keeps the packets, which are the kernels it is there to check.
bool traces_per_pixel(cl_device_type type);

}  // namespace clr
