// Finding OpenCL devices: the list that --list-devices prints, and the choice made by
// --device or CLRENDER_DEVICE.
#pragma once

#include <string>
#include <vector>

#include "device/opencl.h"

namespace clr {

struct DeviceEntry {
    int index = 0;           // position in the flat list of every device on every platform
    int platform_index = 0;  // position of its platform
    int device_index = 0;    // position within its platform
    std::string platform_name;
    std::string device_name;
    std::string type;     // "CPU", "GPU", "accelerator", ...
    std::string version;  // the device's OpenCL version string
    cl::Device device;
};

// Every device of every platform, in platform order. Empty when no OpenCL driver is
// installed.
std::vector<DeviceEntry> list_devices();

// The human-readable listing printed by --list-devices, one line each (without line breaks;
// names from the driver escaped), and the same lines joined with a newline after each.
std::vector<std::string> device_list_lines(const std::vector<DeviceEntry>& devices);
std::string format_device_list(const std::vector<DeviceEntry>& devices);

// Picks a device. `selector` is empty (the first CPU device, else the first device), "cpu" or
// "gpu" (the first device of that type, any case; DeviceError when there is none), a
// flat index ("0"), "platform:device" ("0:1"), or a case-insensitive substring of the
// device or platform name (the first match wins). Throws DeviceError naming the selector
// and listing the devices when nothing matches.
DeviceEntry select_device(const std::vector<DeviceEntry>& devices, const std::string& selector);

// The device's compute units (CL_DEVICE_MAX_COMPUTE_UNITS).
int compute_units(const DeviceEntry& entry);

// `entry` with `units` compute units (-t): itself when it has that many already (PoCL, told by
// limit_cpu_threads()), else its first sub-device of that many (clCreateSubDevices,
// CL_DEVICE_PARTITION_EQUALLY). Throws DeviceError when the device has fewer or cannot be
// partitioned (most GPUs).
DeviceEntry select_compute_units(const DeviceEntry& entry, int units);

}  // namespace clr
