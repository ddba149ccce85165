#include "device/device_selection.h"

#include <algorithm>
#include <cctype>
#include <optional>
#include <sstream>

#include "core/errors.h"
#include "core/printable_text.h"
#include "device/cl_errors.h"
#include "device/driver_limits.h"
#include "device/driver_settings.h"

namespace clr {
namespace {

// Before main(), so before any thread and any driver: every OpenCL user lists devices first,
// so this file is always linked.
[[maybe_unused]] const bool kDriverSettingsApplied = (apply_driver_settings(), true);

std::string device_type_name(cl_device_type type) {
    if (type & CL_DEVICE_TYPE_GPU) return "GPU";
    if (type & CL_DEVICE_TYPE_CPU) return "CPU";
    if (type & CL_DEVICE_TYPE_ACCELERATOR) return "accelerator";
    return "other";
}

std::string lower(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
    return text;
}

// The bindings return strings with the C terminator included on some drivers.
std::string trimmed(std::string text) {
    while (!text.empty() && (text.back() == '\0' || std::isspace(static_cast<unsigned char>(text.back()))))
        text.pop_back();
    return text;
}

std::optional<int> parse_index(const std::string& text) {
    if (text.empty() || text.size() > 6 || !std::all_of(text.begin(), text.end(), ::isdigit)) return std::nullopt;
    return std::stoi(text);
}

}  // namespace

std::vector<DeviceEntry> list_devices() {
    std::vector<cl::Platform> platforms;
    try {
        cl::Platform::get(&platforms);
    } catch (const cl::Error& error) {
        if (error.err() == -1001) return {};  // the ICD loader found no driver at all
        throw DeviceError(describe_cl_error(error, "listing OpenCL platforms"));
    }
    std::vector<DeviceEntry> entries;
    for (std::size_t p = 0; p < platforms.size(); ++p) {
        std::vector<cl::Device> devices;
        try {
            platforms[p].getDevices(CL_DEVICE_TYPE_ALL, &devices);
        } catch (const cl::Error&) {
            continue;  // a platform without devices reports CL_DEVICE_NOT_FOUND
        }
        for (std::size_t d = 0; d < devices.size(); ++d) {
            DeviceEntry entry;
            entry.index = static_cast<int>(entries.size());
            entry.platform_index = static_cast<int>(p);
            entry.device_index = static_cast<int>(d);
            entry.platform_name = trimmed(platforms[p].getInfo<CL_PLATFORM_NAME>());
            entry.device_name = trimmed(devices[d].getInfo<CL_DEVICE_NAME>());
            entry.type = device_type_name(devices[d].getInfo<CL_DEVICE_TYPE>());
            entry.version = trimmed(devices[d].getInfo<CL_DEVICE_VERSION>());
            entry.device = devices[d];
            entries.push_back(entry);
        }
    }
    return entries;
}

std::vector<std::string> device_list_lines(const std::vector<DeviceEntry>& devices) {
    if (devices.empty()) {
        // What keeps an installed driver from starting, when something visibly does.
        if (std::optional<Error> trouble = driver_trouble("no OpenCL device started")) return {trouble->what()};
        return {"No OpenCL devices found (is an OpenCL driver such as pocl-opencl-icd installed?)"};
    }
    // The names come from the driver: escaped, so that one cannot break or forge a line.
    std::vector<std::string> lines;
    std::string platform;
    for (const DeviceEntry& entry : devices) {
        if (entry.platform_name != platform || entry.device_index == 0) {
            platform = entry.platform_name;
            lines.push_back("Platform " + std::to_string(entry.platform_index) + ": " + printable(platform));
        }
        std::ostringstream line;
        line << "  [" << entry.index << "] " << entry.platform_index << ":" << entry.device_index << "  "
             << printable(entry.device_name) << " (" << entry.type << ", " << printable(entry.version) << ")";
        lines.push_back(line.str());
    }
    return lines;
}

std::string format_device_list(const std::vector<DeviceEntry>& devices) {
    std::string text;
    for (const std::string& line : device_list_lines(devices)) text += line + "\n";
    return text;
}

DeviceEntry select_device(const std::vector<DeviceEntry>& devices, const std::string& selector) {
    if (devices.empty()) {
        if (std::optional<Error> trouble = driver_trouble("no OpenCL device started")) throw *trouble;
        throw DeviceError("no OpenCL device found; install an OpenCL driver (for the CPU: pocl-opencl-icd)");
    }
    if (selector.empty()) {
        auto cpu = std::find_if(devices.begin(), devices.end(), [](const DeviceEntry& e) { return e.type == "CPU"; });
        return cpu != devices.end() ? *cpu : devices.front();
    }
    // "cpu" and "gpu" name a kind of device, not a name substring: on a machine with a GPU
    // and PoCL, "-d gpu" must not fall back to whatever device has "gpu" in its name, nor to
    // the CPU (docs/command-line.md, Options).
    if (const std::string kind = lower(selector); kind == "cpu" || kind == "gpu") {
        const std::string type = kind == "cpu" ? "CPU" : "GPU";
        auto found = std::find_if(devices.begin(), devices.end(), [&](const DeviceEntry& e) { return e.type == type; });
        if (found != devices.end()) return *found;
        throw DeviceError("no OpenCL " + type + " device; available devices:", device_list_lines(devices));
    }
    if (auto index = parse_index(selector)) {
        if (*index < static_cast<int>(devices.size())) return devices[*index];
    } else if (auto colon = selector.find(':'); colon != std::string::npos) {
        auto platform = parse_index(selector.substr(0, colon));
        auto device = parse_index(selector.substr(colon + 1));
        for (const DeviceEntry& entry : devices)
            if (platform && device && entry.platform_index == *platform && entry.device_index == *device) return entry;
    }
    if (!parse_index(selector)) {
        // A name on two platforms is refused: PoCL names its CPU device after the processor
        // ("pthread-...-Intel(R) Xeon(R) Processor"), so "Intel" chose PoCL where Intel's runtime
        // was meant. On one platform the first device wins ("nvidia" of several GPUs).
        const std::string wanted = lower(selector);
        std::vector<DeviceEntry> named;
        for (const DeviceEntry& entry : devices)
            if (lower(entry.device_name).find(wanted) != std::string::npos ||
                lower(entry.platform_name).find(wanted) != std::string::npos)
                named.push_back(entry);
        const auto elsewhere = [&](const DeviceEntry& e) { return e.platform_index != named.front().platform_index; };
        if (std::any_of(named.begin(), named.end(), elsewhere))
            throw DeviceError("OpenCL device '" + selector + "' names devices of more than one platform; choose one " +
                              "by its index, platform:device or a longer name:", device_list_lines(devices));
        if (!named.empty()) return named.front();
    }
    throw DeviceError("unknown OpenCL device '" + selector + "'; available devices:", device_list_lines(devices));
}

int compute_units(const DeviceEntry& entry) {
    try {
        return static_cast<int>(entry.device.getInfo<CL_DEVICE_MAX_COMPUTE_UNITS>());
    } catch (const cl::Error& error) {
        throw DeviceError(describe_cl_error(error, "asking '" + entry.device_name + "' for its compute units"));
    }
}

DeviceEntry select_compute_units(const DeviceEntry& entry, int units) {
    const int available = compute_units(entry);
    if (available == units) return entry;
    if (available < units)
        throw DeviceError("--threads " + std::to_string(units) + ": '" + entry.device_name + "' has only " +
                          std::to_string(available) + " compute units");
    std::vector<cl::Device> parts;
    try {
        const cl_device_partition_property equally[] = {CL_DEVICE_PARTITION_EQUALLY,
                                                        static_cast<cl_device_partition_property>(units), 0};
        cl::Device whole = entry.device;  // the bindings' createSubDevices is not const
        whole.createSubDevices(equally, &parts);
    } catch (const cl::Error& error) {
        throw DeviceError(describe_cl_error(error, "--threads " + std::to_string(units) + ": dividing '" +
                                                       entry.device_name + "' into devices of that many compute units"));
    }
    if (parts.empty())
        throw DeviceError("--threads " + std::to_string(units) + ": '" + entry.device_name + "' gave no sub-device");
    DeviceEntry part = entry;
    part.device = parts.front();
    return part;
}

}  // namespace clr
