#include "device/program_cache.h"

#include <algorithm>

#include "core/cache_folder.h"

namespace clr {
namespace {

CacheEntryKind program_entries(std::uint64_t size_limit) {
    return {"clbin", {'c', 'l', 'r', 'p', 'r', 'o', 'g', 'm'}, ProgramCache::kFormatVersion, size_limit};
}

}  // namespace

ProgramCache ProgramCache::from_environment() { return ProgramCache(cache_folder_from_environment()); }

ProgramCache::ProgramCache(std::string cache_folder, std::uint64_t size_limit)
    : entries_(std::move(cache_folder), "programs", program_entries(size_limit), size_limit) {}

ProgramCache::Key ProgramCache::key(const cl::Device& device, const std::string& source, const std::string& options) {
    cl::Platform platform(device.getInfo<CL_DEVICE_PLATFORM>());
    Sha256 hash;
    hash.add_field(std::string("clrender program binary")).add_number(kFormatVersion);
    for (const std::string& part :
         {device.getInfo<CL_DEVICE_NAME>(), device.getInfo<CL_DEVICE_VERSION>(), device.getInfo<CL_DRIVER_VERSION>(),
          platform.getInfo<CL_PLATFORM_NAME>(), platform.getInfo<CL_PLATFORM_VERSION>(), options, source})
        hash.add_field(part);
    return hash.finish();
}

std::optional<std::vector<unsigned char>> ProgramCache::load(const Key& key) const {
    std::optional<CacheEntry> entry = entries_.load(key);
    if (!entry || entry->payload.empty()) return std::nullopt;
    return std::move(entry->payload);
}

std::optional<std::vector<unsigned char>> ProgramCache::borrow(const Key& key, const std::string& driver_magic,
                                                              std::string& aside) const {
    std::optional<CacheEntry> entry = entries_.borrow(key, aside);
    if (!entry) return std::nullopt;
    std::vector<unsigned char>& binary = entry->payload;
    if (binary.size() <= driver_magic.size() || !std::equal(driver_magic.begin(), driver_magic.end(), binary.begin())) {
        entries_.discard(aside);
        return std::nullopt;
    }
    return std::move(binary);
}

std::string ProgramCache::driver_magic(const cl::Device& device) {
    cl::Platform platform(device.getInfo<CL_DEVICE_PLATFORM>());
    // PoCL's binaries start with this id (lib/CL/pocl_binary.c, POCLCC_STRING_ID).
    if (platform.getInfo<CL_PLATFORM_NAME>().find("Portable Computing Language") != std::string::npos)
        return std::string("poclbin", 8);
    return "";
}

void ProgramCache::store(const Key& key, const std::vector<unsigned char>& binary) const {
    if (!enabled() || binary.empty()) return;
    entries_.store(key, {0, 0}, binary.data(), binary.size());
}

}  // namespace clr
