#include "core/cache_entry_folder.h"

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <ctime>
#include <vector>

#include "core/open_file.h"
#include "core/cache_folder.h"
#include "core/replacement_file.h"

namespace clr {
namespace {

// Opens an existing file for reading only if it is a regular file: never through a symlink
// (O_NOFOLLOW), and without blocking on a FIFO planted under an entry's name (O_NONBLOCK).
int open_regular_file(const std::string& path) {
    const int descriptor = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK);
    struct stat info;
    if (descriptor >= 0 && (::fstat(descriptor, &info) != 0 || !S_ISREG(info.st_mode))) {
        ::close(descriptor);
        return -1;
    }
    return descriptor;
}

bool is_hex_digest(const std::string& text) {
    return text.size() == 64 &&
           std::all_of(text.begin(), text.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)) || (c >= 'a' && c <= 'f'); });
}

bool is_number(const std::string& text) {
    return !text.empty() && text.size() <= 20 &&
           std::all_of(text.begin(), text.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
}

enum class NameKind { Foreign, Entry, Temporary };

// Which of our patterns `name` follows: `<digest>.<ext>` or `<digest>.<ext>.tmp-<pid>-<n>`.
NameKind classify(const std::string& name, const std::string& extension) {
    const std::string suffix = "." + extension;
    if (name.size() < 64 + suffix.size() || !is_hex_digest(name.substr(0, 64)) ||
        name.compare(64, suffix.size(), suffix) != 0)
        return NameKind::Foreign;
    const std::string rest = name.substr(64 + suffix.size());
    if (rest.empty()) return NameKind::Entry;
    const std::string::size_type dash = rest.find('-', 5);
    if (rest.compare(0, 5, ".tmp-") == 0 && dash != std::string::npos && is_number(rest.substr(5, dash - 5)) &&
        is_number(rest.substr(dash + 1)))
        return NameKind::Temporary;
    return NameKind::Foreign;
}

std::string temporary_name_for(const std::string& entry_name) {
    static std::atomic<unsigned> counter{0};  // threads of one process decode images in parallel
    return entry_name + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter.fetch_add(1));
}

struct OwnFile {
    std::string path;
    struct timespec last_used;
    std::uint64_t size;
};

bool older(const struct timespec& a, const struct timespec& b) {
    return a.tv_sec != b.tv_sec ? a.tv_sec < b.tv_sec : a.tv_nsec < b.tv_nsec;
}

}  // namespace

CacheEntryFolder::CacheEntryFolder(std::string root, std::string subfolder, CacheEntryKind kind, std::uint64_t size_limit)
    : root_(std::move(root)), subfolder_(std::move(subfolder)), kind_(std::move(kind)), size_limit_(size_limit) {}

std::string CacheEntryFolder::path(const Sha256Digest& key) const {
    return folder() + "/" + to_hex(key) + "." + kind_.extension;
}

std::optional<CacheEntry> CacheEntryFolder::load(const Sha256Digest& key) const {
    if (usable_cache_subfolder(root_, subfolder_, /*create=*/false).empty()) return std::nullopt;
    OpenFile file(open_regular_file(path(key)));
    if (file.get() < 0) return std::nullopt;
    CacheEntry entry;
    switch (read_cache_entry(file.get(), kind_, key, entry)) {
        case EntryCheck::Good:
            ::futimens(file.get(), nullptr);  // just used: eviction keeps it longest (best effort)
            return entry;
        case EntryCheck::Bad:
            ::unlink(path(key).c_str());  // ours (name, regular file, magic) and useless
            return std::nullopt;
        case EntryCheck::Foreign:
            break;
    }
    return std::nullopt;
}

std::optional<CacheEntry> CacheEntryFolder::borrow(const Sha256Digest& key, std::string& aside) const {
    const std::string folder = usable_cache_subfolder(root_, subfolder_, /*create=*/false);
    if (folder.empty()) return std::nullopt;
    const std::string entry_path = path(key);
    OpenFile file(open_regular_file(entry_path));
    struct stat opened, moved;
    if (file.get() < 0 || !starts_with_magic(file.get(), kind_, /*allow_short=*/false) ||
        ::fstat(file.get(), &opened) != 0)
        return std::nullopt;  // none, or not ours: left as it is
    aside = folder + "/" + temporary_name_for(to_hex(key) + "." + kind_.extension);
    if (::rename(entry_path.c_str(), aside.c_str()) != 0) return std::nullopt;  // another run took it first
    if (::lstat(aside.c_str(), &moved) != 0 || moved.st_ino != opened.st_ino || moved.st_dev != opened.st_dev) {
        ::rename(aside.c_str(), entry_path.c_str());  // replaced between open and rename: not what was checked
        return std::nullopt;
    }
    ::futimens(file.get(), nullptr);  // held now: evict() takes it for stale only if this run dies
    CacheEntry entry;
    if (read_cache_entry(file.get(), kind_, key, entry) != EntryCheck::Good) {
        ::unlink(aside.c_str());
        return std::nullopt;
    }
    return entry;
}

void CacheEntryFolder::give_back(const Sha256Digest& key, const std::string& aside) const {
    if (::rename(aside.c_str(), path(key).c_str()) != 0) ::unlink(aside.c_str());
}

void CacheEntryFolder::discard(const std::string& aside) const { ::unlink(aside.c_str()); }

void CacheEntryFolder::remove(const Sha256Digest& key) const {
    if (usable_cache_subfolder(root_, subfolder_, /*create=*/false).empty()) return;
    OpenFile file(open_regular_file(path(key)));
    if (file.get() >= 0 && starts_with_magic(file.get(), kind_, /*allow_short=*/false)) ::unlink(path(key).c_str());
}

void CacheEntryFolder::store(const Sha256Digest& key, const std::array<std::uint32_t, 2>& detail,
                             const unsigned char* payload, std::size_t size) const {
    const std::string folder = usable_cache_subfolder(root_, subfolder_, /*create=*/true);
    if (folder.empty() || size > kind_.largest_payload) return;
    ReplacementFile file(folder + "/" + temporary_name_for(to_hex(key) + "." + kind_.extension), 0600);
    if (!file.created()) return;
    // Renamed only when whole: a full disk leaves no partial entry under a final name. Not
    // synced: a cache entry lost in a crash is only a miss, and its checksum catches a torn one.
    const bool written = write_cache_entry(file.descriptor(), kind_, key, detail, payload, size);
    if (!file.close(/*sync=*/false) || !written || !file.rename_onto(path(key))) return;
    evict();
}

void CacheEntryFolder::evict() const {
    const std::string folder = usable_cache_subfolder(root_, subfolder_, /*create=*/false);
    if (folder.empty()) return;
    DIR* listing = ::opendir(folder.c_str());
    if (!listing) return;
    std::vector<OwnFile> entries;
    std::uint64_t total = 0;
    const std::time_t stale_before = std::time(nullptr) - 60 * kStaleTemporaryMinutes;
    while (const struct dirent* item = ::readdir(listing)) {
        const std::string name = item->d_name;
        const NameKind name_kind = classify(name, kind_.extension);
        if (name_kind == NameKind::Foreign) continue;
        const std::string file_path = folder + "/" + name;
        OpenFile file(open_regular_file(file_path));
        struct stat info;
        if (file.get() < 0 || ::fstat(file.get(), &info) != 0) continue;  // gone meanwhile, a symlink, a folder
        const bool temporary = name_kind == NameKind::Temporary;
        if (!starts_with_magic(file.get(), kind_, /*allow_short=*/temporary)) continue;  // not ours
        if (temporary) {
            // Another run may be writing it right now; only one left behind long ago goes.
            if (info.st_mtim.tv_sec < stale_before) ::unlink(file_path.c_str());
            continue;
        }
        total += static_cast<std::uint64_t>(info.st_size);
        entries.push_back({file_path, info.st_mtim, static_cast<std::uint64_t>(info.st_size)});
    }
    ::closedir(listing);
    if (total <= size_limit_) return;
    std::sort(entries.begin(), entries.end(), [](const OwnFile& a, const OwnFile& b) { return older(a.last_used, b.last_used); });
    for (const OwnFile& entry : entries) {
        if (total <= size_limit_) break;
        ::unlink(entry.path.c_str());  // another run may have removed it first: the space is free either way
        total -= entry.size;
    }
}

}  // namespace clr
