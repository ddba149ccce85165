#include "support/opencl_test_device.h"

#include <cstdlib>
#include <memory>

namespace clr::testing {

DeviceContext& test_device() {
    static std::unique_ptr<DeviceContext> device = [] {
        const char* selector = std::getenv("CLRENDER_DEVICE");
        return std::make_unique<DeviceContext>(select_device(list_devices(), selector ? selector : ""));
    }();
    return *device;
}

}  // namespace clr::testing
