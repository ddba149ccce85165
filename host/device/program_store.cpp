#include "device/program_store.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "core/open_file.h"
#include "core/cache_entry.h"
#include "device/exact_arithmetic.h"

namespace clr {
namespace {

namespace fs = std::filesystem;

// The program cache's entries (device/program_cache.cpp), so that either can hold the other's.
CacheEntryKind program_entries() {
    return {"clbin", {'c', 'l', 'r', 'p', 'r', 'o', 'g', 'm'}, ProgramCache::kFormatVersion,
            ProgramCache::kDefaultSizeLimit};
}

// A regular file, opened without blocking on a FIFO under an entry's name. Symlinks are
// followed: the store is part of the install, which packagers may lay out with links.
int open_regular_file(const std::string& path) {
    const int descriptor = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    struct stat info;
    if (descriptor >= 0 && (::fstat(descriptor, &info) != 0 || !S_ISREG(info.st_mode))) {
        ::close(descriptor);
        return -1;
    }
    return descriptor;
}

std::string running_executable() {
    std::error_code error;
    const fs::path executable = fs::read_symlink("/proc/self/exe", error);
    return error ? std::string() : executable.string();
}

}  // namespace

ProgramStore ProgramStore::from_environment() {
    if (const char* chosen = std::getenv("CLRENDER_PROGRAM_STORE")) {
        const std::string folder = chosen;
        return ProgramStore(folder == "off" ? "" : folder);
    }
    const std::string executable = running_executable();
    if (executable.empty()) return ProgramStore();
    for (const std::string& folder : folders_beside(executable)) {
        std::error_code error;
        if (fs::is_directory(folder, error)) return ProgramStore(folder);
    }
    return ProgramStore();
}

std::vector<std::string> ProgramStore::folders_beside(const std::string& executable) {
    const fs::path bin = fs::path(executable).parent_path();
    return {(bin / ".." / "share" / "clrender" / "programs").lexically_normal().string(),
            (bin / "share" / "clrender" / "programs").lexically_normal().string()};
}

std::string ProgramStore::path(const ProgramCache::Key& key) const {
    return folder_ + "/" + to_hex(key) + "." + program_entries().extension;
}

std::optional<std::vector<unsigned char>> ProgramStore::load(const ProgramCache::Key& key,
                                                             const std::string& driver_magic) const {
    if (!enabled()) return std::nullopt;
    OpenFile file(open_regular_file(path(key)));
    if (file.get() < 0) return std::nullopt;
    CacheEntry entry;
    if (read_cache_entry(file.get(), program_entries(), key, entry) != EntryCheck::Good) return std::nullopt;
    std::vector<unsigned char>& binary = entry.payload;
    if (binary.size() <= driver_magic.size() || !std::equal(driver_magic.begin(), driver_magic.end(), binary.begin()))
        return std::nullopt;
    return std::move(binary);
}

bool ProgramStore::write(const ProgramCache::Key& key, const std::vector<unsigned char>& binary) const {
    if (!enabled() || binary.empty()) return false;
    const std::string final_path = path(key);
    const std::string temporary = final_path + ".tmp-" + std::to_string(::getpid());
    // 0644: the installed store is read by every user of the install.
    const int descriptor = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (descriptor < 0) return false;
    bool written = write_cache_entry(descriptor, program_entries(), key, {0, 0}, binary.data(), binary.size());
    written = (::close(descriptor) == 0) && written;
    if (!written || std::rename(temporary.c_str(), final_path.c_str()) != 0) {
        std::remove(temporary.c_str());
        return false;
    }
    return true;
}

std::optional<cl::Program> build_from_store(const ProgramStore& store, const cl::Context& context,
                                            const cl::Device& device, const ProgramCache::Key& key,
                                            const std::string& options) {
    std::optional<std::vector<unsigned char>> binary;
    try {
        binary = store.load(key, ProgramCache::driver_magic(device));
    } catch (const std::exception&) {  // e.g. no memory for the entry: a miss
    }
    if (!binary) return std::nullopt;
    try {
        cl::Program stored(context, {device}, cl::Program::Binaries{*binary});
        stored.build({device}, with_exact_arithmetic(device, options).c_str());
        return stored;
    } catch (const cl::Error&) {  // refused by the driver: built from source instead
        return std::nullopt;
    }
}

}  // namespace clr
