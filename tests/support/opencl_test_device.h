// The OpenCL device every test shares (CLRENDER_DEVICE, else the first CPU device), opened
// once per test binary.
#pragma once

#include "device/device_context.h"

namespace clr::testing {

DeviceContext& test_device();

}  // namespace clr::testing
