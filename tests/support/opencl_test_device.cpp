#include "support/opencl_test_device.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

namespace clr::testing {
namespace {

DeviceContext* opened_device = nullptr;

// With CLRENDER_CACHE_DIR naming a folder, the programs a test built from source go into the
// program cache when it ends, as clrender stores them once its frames are written: a later test,
// or another shard, takes the binary rather than compile the same program again. Intel's CPU
// runtime keeps no kernel cache of its own, and scripts/second-opencl.sh's tests compiled each
// program anew in every test (6 tests of Lights, about 5 minutes). Without the variable nothing
// is stored: asking PoCL for a binary compiles every kernel of the program once more.
class StoreBuiltPrograms : public ::testing::EmptyTestEventListener {
    void OnTestEnd(const ::testing::TestInfo&) override {
        if (opened_device) opened_device->store_built_programs();
    }
};

bool cache_folder_named() {
    const char* folder = std::getenv("CLRENDER_CACHE_DIR");
    return folder && *folder && std::string(folder) != "off";
}

const bool stores_built_programs = [] {
    if (!cache_folder_named()) return false;
    ::testing::UnitTest::GetInstance()->listeners().Append(new StoreBuiltPrograms);
    return true;
}();

}  // namespace

// Never released: a static destructor runs after the OpenCL implementation's own statics may
// be gone (Oclgrind's clReleaseContext at exit aborts inside LLVM's torn-down state), and the
// process is ending anyway.
DeviceContext& test_device() {
    static DeviceContext* device = [] {
        const char* selector = std::getenv("CLRENDER_DEVICE");
        return opened_device = new DeviceContext(select_device(list_devices(), selector ? selector : ""));
    }();
    return *device;
}

}  // namespace clr::testing
