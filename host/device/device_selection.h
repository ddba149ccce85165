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

// The human-readable listing printed by --list-devices.
std::string format_device_list(const std::vector<DeviceEntry>& devices);

// Picks a device. `selector` is empty (the first CPU device, else the first device), a
// flat index ("0"), "platform:device" ("0:1"), or a case-insensitive substring of the
// device or platform name (the first match wins). Throws DeviceError naming the selector
// and listing the devices when nothing matches.
DeviceEntry select_device(const std::vector<DeviceEntry>& devices, const std::string& selector);

}  // namespace clr
