// Choosing an OpenCL device by index, platform:device or name, and naming OpenCL errors.
#include <gtest/gtest.h>

#include "core/errors.h"
#include "device/cl_errors.h"
#include "device/device_selection.h"
#include "render/renderer.h"
#include "support/opencl_test_device.h"
#include "support/random_scene.h"

namespace clr {
namespace {

DeviceEntry entry(int index, int platform, int device, const std::string& platform_name, const std::string& name,
                  const std::string& type) {
    DeviceEntry e;
    e.index = index;
    e.platform_index = platform;
    e.device_index = device;
    e.platform_name = platform_name;
    e.device_name = name;
    e.type = type;
    e.version = "OpenCL 1.2";
    return e;
}

// Two platforms: a GPU first, then two CPU devices.
std::vector<DeviceEntry> fake_devices() {
    return {entry(0, 0, 0, "NVIDIA CUDA", "NVIDIA H100", "GPU"),
            entry(1, 1, 0, "Portable Computing Language", "pthread-skylake", "CPU"),
            entry(2, 1, 1, "Portable Computing Language", "cpu-other", "CPU")};
}

TEST(DeviceSelection, DefaultIsTheFirstCpuDevice) {
    EXPECT_EQ(select_device(fake_devices(), "").index, 1);
    auto gpus_only = fake_devices();
    gpus_only.resize(1);
    EXPECT_EQ(select_device(gpus_only, "").index, 0) << "without a CPU device, the first device";
}

TEST(DeviceSelection, ByFlatIndexAndByPlatformColonDevice) {
    EXPECT_EQ(select_device(fake_devices(), "0").device_name, "NVIDIA H100");
    EXPECT_EQ(select_device(fake_devices(), "2").device_name, "cpu-other");
    EXPECT_EQ(select_device(fake_devices(), "1:1").device_name, "cpu-other");
    EXPECT_EQ(select_device(fake_devices(), "1:0").device_name, "pthread-skylake");
}

TEST(DeviceSelection, ByCaseInsensitiveNameOrPlatformSubstring) {
    EXPECT_EQ(select_device(fake_devices(), "h100").index, 0);
    EXPECT_EQ(select_device(fake_devices(), "SKYLAKE").index, 1);
    EXPECT_EQ(select_device(fake_devices(), "portable").index, 1) << "the first match wins";
}

// PoCL names its CPU device after the processor: "Intel" names PoCL's device and Intel's
// platform, and chose PoCL's where Intel's runtime was meant.
TEST(DeviceSelection, ANameOfDevicesOnTwoPlatformsIsRefusedListingThem) {
    const std::vector<DeviceEntry> both = {
        entry(0, 0, 0, "Portable Computing Language", "pthread-skylake-avx512-Intel(R) Xeon(R) Processor", "CPU"),
        entry(1, 1, 0, "Intel(R) OpenCL", "Intel(R) Xeon(R) Processor", "CPU")};
    try {
        select_device(both, "intel");
        ADD_FAILURE() << "'intel' chose one of two platforms' devices";
    } catch (const DeviceError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("more than one platform"), std::string::npos) << message;
        EXPECT_NE(message.find("Intel(R) OpenCL"), std::string::npos) << message;
        EXPECT_EQ(error.code(), kExitDevice);
    }
    EXPECT_EQ(select_device(both, "Intel(R) OpenCL").index, 1);
    EXPECT_EQ(select_device(both, "pthread").index, 0);
}

TEST(DeviceSelection, CpuAndGpuSelectTheFirstDeviceOfThatType) {
    EXPECT_EQ(select_device(fake_devices(), "cpu").index, 1);
    EXPECT_EQ(select_device(fake_devices(), "GPU").index, 0);
    std::vector<DeviceEntry> gpu_named_cpu = {entry(0, 0, 0, "Portable Computing Language", "gpu-emulation", "CPU"),
                                              entry(1, 1, 0, "NVIDIA CUDA", "NVIDIA H100", "GPU")};
    EXPECT_EQ(select_device(gpu_named_cpu, "gpu").index, 1) << "the type, not a name substring";
}

TEST(DeviceSelection, MissingTypeIsADeviceErrorListingWhatExists) {
    auto cpus_only = fake_devices();
    cpus_only.erase(cpus_only.begin());
    try {
        select_device(cpus_only, "gpu");
        ADD_FAILURE() << "gpu was accepted without a GPU";
    } catch (const DeviceError& error) {
        std::string message = error.what();
        EXPECT_NE(message.find("no OpenCL GPU device"), std::string::npos) << message;
        EXPECT_NE(message.find("pthread-skylake"), std::string::npos) << message;
        EXPECT_EQ(error.code(), kExitDevice);
    }
}

TEST(DeviceSelection, UnknownSelectorsAreDeviceErrorsListingTheDevices) {
    for (const char* selector : {"3", "2:0", "0:5", "quantum", "1:x"}) {
        try {
            select_device(fake_devices(), selector);
            ADD_FAILURE() << selector << " was accepted";
        } catch (const DeviceError& error) {
            std::string message = error.what();
            EXPECT_NE(message.find(std::string("'") + selector + "'"), std::string::npos) << message;
            EXPECT_NE(message.find("NVIDIA H100"), std::string::npos) << message;
            EXPECT_EQ(error.code(), kExitDevice);
        }
    }
    EXPECT_THROW(select_device({}, ""), DeviceError);
}

TEST(DeviceSelection, ListingShowsIndicesAndPlatforms) {
    std::string listing = format_device_list(fake_devices());
    EXPECT_NE(listing.find("Platform 0: NVIDIA CUDA"), std::string::npos) << listing;
    EXPECT_NE(listing.find("Platform 1: Portable Computing Language"), std::string::npos) << listing;
    EXPECT_NE(listing.find("[2] 1:1  cpu-other (CPU"), std::string::npos) << listing;
    EXPECT_NE(format_device_list({}).find("No OpenCL devices"), std::string::npos);
}

TEST(DeviceSelection, AnErrorCarriesTheListingAsLinesWithTheDriversNamesEscaped) {
    auto devices = fake_devices();
    devices[2].device_name = "cpu\nforged";
    try {
        select_device(devices, "quantum");
        FAIL() << "accepted";
    } catch (const DeviceError& error) {
        EXPECT_EQ(error.headline(), "unknown OpenCL device 'quantum'; available devices:");
        const std::vector<std::string> expected = {"Platform 0: NVIDIA CUDA", "  [0] 0:0  NVIDIA H100 (GPU, OpenCL 1.2)",
                                                   "Platform 1: Portable Computing Language",
                                                   "  [1] 1:0  pthread-skylake (CPU, OpenCL 1.2)",
                                                   "  [2] 1:1  cpu\\x0Aforged (CPU, OpenCL 1.2)"};
        EXPECT_EQ(error.lines(), expected);
    }
}

// -t on a driver that is not told the thread count by the environment: a sub-device of that
// many compute units, which renders the same bytes.
TEST(DeviceSelection, ASubDeviceOfOneComputeUnitRendersTheSameBytes) {
    const DeviceEntry& whole = testing::test_device().entry();
    const int units = compute_units(whole);
    EXPECT_EQ(select_compute_units(whole, units).device(), whole.device()) << "as many as it has: the device itself";
    EXPECT_THROW(select_compute_units(whole, units + 1), DeviceError);
    if (units < 2) GTEST_SKIP() << "one compute unit: nothing to divide";
    DeviceEntry part;
    try {
        part = select_compute_units(whole, 1);
    } catch (const DeviceError& error) {
        GTEST_SKIP() << "the driver cannot divide the device: " << error.what();
    }
    EXPECT_EQ(compute_units(part), 1);

    Scene scene = testing::make_random_scene(5, 6, 6);
    scene.camera_path = {{{3, 5, 30}, {0, 0, 0}}};
    scene.width = 64;
    scene.height = 48;
    scene.sampling.samples_per_pixel = 4;
    Renderer on_whole(testing::test_device(), scene);
    DeviceContext part_context(part);
    Renderer on_part(part_context, scene);
    EXPECT_TRUE(on_part.render(scene.camera_path.front()).rgba == on_whole.render(scene.camera_path.front()).rgba);
}

TEST(DeviceSelection, RealDevicesAreListed) {
    auto devices = list_devices();
    ASSERT_FALSE(devices.empty()) << "the tests need an OpenCL device (pocl-opencl-icd)";
    for (std::size_t i = 0; i < devices.size(); ++i) {
        EXPECT_EQ(devices[i].index, static_cast<int>(i));
        EXPECT_FALSE(devices[i].device_name.empty());
    }
}

TEST(ClErrors, NamesErrorCodes) {
    EXPECT_EQ(cl_error_name(CL_SUCCESS), "CL_SUCCESS");
    EXPECT_EQ(cl_error_name(-5), "CL_OUT_OF_RESOURCES");
    EXPECT_EQ(cl_error_name(-11), "CL_BUILD_PROGRAM_FAILURE");
    EXPECT_EQ(cl_error_name(-46), "CL_INVALID_KERNEL_NAME");
    EXPECT_EQ(cl_error_name(-1001), "CL_PLATFORM_NOT_FOUND_KHR");
    EXPECT_EQ(cl_error_name(-12345), "unknown OpenCL error -12345");
}

}  // namespace
}  // namespace clr
