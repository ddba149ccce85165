#include "device/program_cache.h"

#include <atomic>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <system_error>
#include <unistd.h>

#include "core/cache_folder.h"

namespace clr {
namespace {

namespace fs = std::filesystem;

constexpr char kMagic[] = "clrender program cache 1\n";

// FNV-1a, 64 bits: stable across runs and builds (std::hash is not), for file names only;
// the whole key is stored in the entry and compared on load.
std::uint64_t fnv1a(const std::string& text) {
    std::uint64_t hash = 1469598103934665603ull;
    for (unsigned char c : text) hash = (hash ^ c) * 1099511628211ull;
    return hash;
}

void put_size(std::string& out, std::uint64_t size) { out.append(reinterpret_cast<const char*>(&size), sizeof size); }

bool get_size(const std::string& in, std::size_t& at, std::uint64_t& size) {
    if (in.size() - at < sizeof size) return false;
    std::copy(in.begin() + at, in.begin() + at + sizeof size, reinterpret_cast<char*>(&size));
    at += sizeof size;
    return true;
}

}  // namespace

// Programs live at the top of the cache folder; other caches use sub-folders of it.
ProgramCache ProgramCache::from_environment() { return ProgramCache(cache_folder_from_environment()); }

std::string ProgramCache::key(const cl::Device& device, const std::string& source, const std::string& options) {
    cl::Platform platform(device.getInfo<CL_DEVICE_PLATFORM>());
    std::string key;
    for (const std::string& part :
         {device.getInfo<CL_DEVICE_NAME>(), device.getInfo<CL_DEVICE_VERSION>(), device.getInfo<CL_DRIVER_VERSION>(),
          platform.getInfo<CL_PLATFORM_NAME>(), platform.getInfo<CL_PLATFORM_VERSION>(), options, source}) {
        put_size(key, part.size());
        key += part;
    }
    return key;
}

std::string ProgramCache::path(const std::string& key) const {
    char name[32];
    std::snprintf(name, sizeof name, "%016llx.bin", static_cast<unsigned long long>(fnv1a(key)));
    return folder_ + "/" + name;
}

std::optional<std::vector<unsigned char>> ProgramCache::load(const std::string& key) const {
    if (!enabled()) return std::nullopt;
    std::string entry;
    try {
        std::error_code error;
        if (!fs::is_regular_file(path(key), error)) return std::nullopt;
        std::ifstream in(path(key), std::ios::binary);
        if (!in) return std::nullopt;
        entry.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    } catch (const std::exception&) {
        return std::nullopt;  // unreadable: a miss
    }
    const std::string magic(kMagic);
    std::size_t at = magic.size();
    std::uint64_t key_size = 0, binary_size = 0;
    if (entry.compare(0, magic.size(), magic) != 0 || !get_size(entry, at, key_size) || entry.size() - at < key_size ||
        entry.compare(at, key_size, key) != 0 || key_size != key.size())
        return std::nullopt;
    at += key_size;
    if (!get_size(entry, at, binary_size) || binary_size == 0 || entry.size() - at != binary_size) return std::nullopt;
    return std::vector<unsigned char>(entry.begin() + at, entry.end());
}

void ProgramCache::store(const std::string& key, const std::vector<unsigned char>& binary) const {
    if (!enabled() || binary.empty()) return;
    std::error_code error;
    fs::create_directories(folder_, error);
    static std::atomic<unsigned> counter{0};
    const std::string final_path = path(key);
    const std::string temp_path =
        final_path + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter.fetch_add(1));
    std::string entry(kMagic);
    put_size(entry, key.size());
    entry += key;
    put_size(entry, binary.size());
    entry.append(binary.begin(), binary.end());
    {
        std::ofstream out(temp_path, std::ios::binary | std::ios::trunc);
        if (!out) return;
        out.write(entry.data(), static_cast<std::streamsize>(entry.size()));
        if (!out.flush()) {
            out.close();
            fs::remove(temp_path, error);
            return;
        }
    }
    fs::rename(temp_path, final_path, error);  // atomic: readers see the old entry or the new one
    if (error) fs::remove(temp_path, error);
}

}  // namespace clr
