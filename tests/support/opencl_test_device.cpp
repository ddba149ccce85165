#include "support/opencl_test_device.h"

#include <cstdlib>

namespace clr::testing {

// Never released: a static destructor runs after the OpenCL implementation's own statics may
// be gone (Oclgrind's clReleaseContext at exit aborts inside LLVM's torn-down state), and the
// process is ending anyway.
DeviceContext& test_device() {
    static DeviceContext* device = [] {
        const char* selector = std::getenv("CLRENDER_DEVICE");
        return new DeviceContext(select_device(list_devices(), selector ? selector : ""));
    }();
    return *device;
}

}  // namespace clr::testing
