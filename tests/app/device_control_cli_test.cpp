// -t/--threads and -d cpu|gpu through the real binary (docs/command-line.md, Threads; Options):
// one thread gives the same bytes and says so in the device line and --stats; a device type
// that the machine lacks is an OpenCL error listing what exists.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "device/device_selection.h"
#include "support/command.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

using testing::read_bytes;
using testing::run_clrender;
using testing::TempFolder;

const char* kScene = R"({
  "eye": [0, 2, 12], "lookat": [0, 1, 0], "up": [0, 1, 0], "fov_angle": 60, "width": 96, "height": 64,
  "SunLocation": [20, 40, 30], "clrender": {"spp": 4},
  "spheres": [{"center": [-2, 1, 0], "radius": 1.5, "ambient": [0.9, 0.3, 0.2], "IsMirror": 1},
              {"center": [2.5, 1, -1], "radius": 1.2, "ambient": [0.2, 0.4, 0.9]}],
  "billboards": [{"UpperLeft": [-10, -1, -10], "LowerLeft": [-10, -1, 10], "UpperRight": [10, -1, -10], "ambient": [0.5, 0.5, 0.5]}]
})";

int stats_compute_units(const TempFolder& folder, const std::string& name) {
    return nlohmann::json::parse(read_bytes(folder.file(name))).at("compute_units").get<int>();
}

TEST(DeviceControlCli, OneThreadGivesTheSameBytesAndReportsOneComputeUnit) {
    TempFolder folder;
    folder.write("scene.json", kScene);
    auto all = run_clrender("scene.json -o all.png --stats all.json", folder.path());
    ASSERT_EQ(all.exit_code, 0) << all.output;
    auto one = run_clrender("scene.json -t 1 -o one.png --stats one.json", folder.path());
    ASSERT_EQ(one.exit_code, 0) << one.output;
    EXPECT_EQ(read_bytes(folder.file("one.png")), read_bytes(folder.file("all.png")));
    EXPECT_NE(one.output.find("(compute units: 1)"), std::string::npos) << one.output;
    EXPECT_EQ(stats_compute_units(folder, "one.json"), 1);
    EXPECT_GE(stats_compute_units(folder, "all.json"), 1);
    EXPECT_NE(all.output.find("(compute units: " + std::to_string(stats_compute_units(folder, "all.json")) + ")"),
              std::string::npos)
        << all.output;
}

TEST(DeviceControlCli, TwoThreadsWhereTheDeviceHasThem) {
    TempFolder folder;
    folder.write("scene.json", kScene);
    auto result = run_clrender("scene.json -q -t 2 -o two.png --stats two.json", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_EQ(stats_compute_units(folder, "two.json"), 2);
}

TEST(DeviceControlCli, DashDCpuSelectsTheCpuDevice) {
    TempFolder folder;
    folder.write("scene.json", kScene);
    auto result = run_clrender("scene.json -d cpu -o cpu.png", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    std::string cpu_name;
    for (const DeviceEntry& entry : list_devices())
        if (entry.type == "CPU" && cpu_name.empty()) cpu_name = entry.device_name;
    ASSERT_FALSE(cpu_name.empty()) << "the tests need a CPU device (PoCL)";
    EXPECT_NE(result.output.find("clrender: device " + cpu_name), std::string::npos) << result.output;
}

TEST(DeviceControlCli, DashDGpuWithoutAGpuIsADeviceErrorListingTheDevices) {
    for (const DeviceEntry& entry : list_devices())
        if (entry.type == "GPU") GTEST_SKIP() << "this machine has a GPU: " << entry.device_name;
    TempFolder folder;
    folder.write("scene.json", kScene);
    auto result = run_clrender("scene.json -d gpu -o gpu.png", folder.path());
    EXPECT_EQ(result.exit_code, 3) << result.output;
    EXPECT_EQ(result.output.rfind("clrender: error: no OpenCL GPU device; available devices:", 0), 0u) << result.output;
    EXPECT_NE(result.output.find("[0] 0:0"), std::string::npos) << result.output;
    EXPECT_EQ(folder.entry_count(), 1) << "nothing written";
}

// The listing under a device error is lines, as --list-devices prints them, not one line
// with escaped line breaks.
TEST(DeviceControlCli, AnUnknownDeviceListsTheDevicesOnLinesOfTheirOwn) {
    TempFolder folder;
    folder.write("scene.json", kScene);
    auto result = run_clrender("scene.json -d no-such-device -o out.png", folder.path());
    EXPECT_EQ(result.exit_code, 3) << result.output;
    EXPECT_EQ(result.output.find("\\x0A"), std::string::npos) << result.output;
    EXPECT_EQ(result.output.rfind("clrender: error: unknown OpenCL device 'no-such-device'; available devices:\n", 0), 0u)
        << result.output;
    for (const DeviceEntry& entry : list_devices()) {
        const std::string line = "[" + std::to_string(entry.index) + "] " + std::to_string(entry.platform_index) + ":" +
                                 std::to_string(entry.device_index) + "  " + entry.device_name;
        const std::size_t at = result.output.find(line);
        ASSERT_NE(at, std::string::npos) << result.output;
        EXPECT_EQ(result.output.rfind('\n', at), result.output.find_last_not_of(' ', at - 1)) << "a line of its own";
    }
    EXPECT_EQ(folder.entry_count(), 1) << "nothing written";
}

}  // namespace
}  // namespace clr
