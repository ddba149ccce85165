#include "scene/image_cache.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>

#include "core/cache_folder.h"
#include "scene/image_loader.h"

namespace clr {
namespace {

namespace fs = std::filesystem;

constexpr char kMagic[8] = {'c', 'l', 'r', 'i', 'm', 'a', 'g', 'e'};

// The fixed-size start of an entry, followed by width * height * 4 bytes of RGBA. Numbers are in
// the host's byte order: a cache folder is not shared between machines, and a foreign order
// would fail the version check anyway.
struct EntryHeader {
    char magic[8];
    std::uint32_t version;
    std::uint32_t width;
    std::uint32_t height;
    std::uint32_t unused;  // 0; keeps the 64-bit fields aligned
    std::uint64_t content_hash;
    std::uint64_t byte_size;
};
static_assert(sizeof(EntryHeader) == 40, "the header is written and read as raw bytes");

// FNV-1a taken a 64-bit word at a time (eight times fewer multiplies than byte by byte: about
// 0.5 ms for a course scene's 2 MB of PNG), with a rotation so that differences in high bits
// reach the low ones instead of cancelling. For cache keys only, not security: the cache is the
// user's own, and a collision could only show the wrong picture.
std::uint64_t content_hash(const unsigned char* data, std::size_t size) {
    constexpr std::uint64_t kPrime = 1099511628211ull;
    std::uint64_t hash = 1469598103934665603ull;
    std::size_t at = 0;
    for (; at + 8 <= size; at += 8) {
        std::uint64_t word;
        std::memcpy(&word, data + at, 8);
        hash = (hash ^ word) * kPrime;
        hash = (hash << 29) | (hash >> 35);
    }
    for (; at < size; ++at) hash = (hash ^ data[at]) * kPrime;
    return hash;
}

// Closes a file descriptor when it goes out of scope.
class OpenFile {
public:
    explicit OpenFile(int descriptor) : descriptor_(descriptor) {}
    ~OpenFile() {
        if (descriptor_ >= 0) ::close(descriptor_);
    }
    OpenFile(const OpenFile&) = delete;
    OpenFile& operator=(const OpenFile&) = delete;
    int get() const { return descriptor_; }
    // Closes now, reporting whether the last writes reached the file.
    bool close() {
        const int descriptor = descriptor_;
        descriptor_ = -1;
        return ::close(descriptor) == 0;
    }

private:
    int descriptor_;
};

bool read_exactly(int descriptor, void* destination, std::size_t size) {
    auto* bytes = static_cast<unsigned char*>(destination);
    while (size > 0) {
        const ssize_t got = ::read(descriptor, bytes, size);
        if (got < 0 && errno == EINTR) continue;
        if (got <= 0) return false;
        bytes += got;
        size -= static_cast<std::size_t>(got);
    }
    return true;
}

bool write_exactly(int descriptor, const void* source, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(source);
    while (size > 0) {
        const ssize_t put = ::write(descriptor, bytes, size);
        if (put < 0 && errno == EINTR) continue;
        if (put <= 0) return false;
        bytes += put;
        size -= static_cast<std::size_t>(put);
    }
    return true;
}

// The bytes of pixels an entry's header announces; 0 when the header is not for `key`.
std::uint64_t pixel_bytes_if_valid(const EntryHeader& header, const ImageCache::Key& key) {
    if (std::memcmp(header.magic, kMagic, sizeof kMagic) != 0 || header.version != ImageCache::kFormatVersion ||
        header.content_hash != key.content_hash || header.byte_size != key.byte_size)
        return 0;
    // Image sizes are ints; this also keeps the product below from overflowing.
    constexpr std::uint32_t kLargestSide = 1u << 30;
    if (header.width == 0 || header.height == 0 || header.width > kLargestSide || header.height > kLargestSide)
        return 0;
    return std::uint64_t(header.width) * header.height * 4;
}

std::string temporary_path_for(const std::string& final_path) {
    static std::atomic<unsigned> counter{0};  // threads of one process decode images in parallel
    return final_path + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter.fetch_add(1));
}

bool write_entry(const std::string& path, const EntryHeader& header, const std::vector<std::uint8_t>& rgba) {
    OpenFile file(::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644));
    if (file.get() < 0) return false;
    return write_exactly(file.get(), &header, sizeof header) && write_exactly(file.get(), rgba.data(), rgba.size()) &&
           file.close();
}

}  // namespace

ImageCache ImageCache::from_environment() {
    const std::string folder = cache_folder_from_environment();
    return ImageCache(folder.empty() ? folder : folder + "/images");
}

ImageCache::Key ImageCache::key(const std::vector<unsigned char>& file_bytes) {
    return {content_hash(file_bytes.data(), file_bytes.size()), file_bytes.size()};
}

std::string ImageCache::path(const Key& key) const {
    char name[64];
    std::snprintf(name, sizeof name, "%016llx-%llx-v%u.rgba", static_cast<unsigned long long>(key.content_hash),
                  static_cast<unsigned long long>(key.byte_size), static_cast<unsigned>(kFormatVersion));
    return folder_ + "/" + name;
}

std::shared_ptr<const Image> ImageCache::load(const Key& key, const std::string& source_path) const {
    if (!enabled()) return nullptr;
    OpenFile file(::open(path(key).c_str(), O_RDONLY | O_CLOEXEC));
    if (file.get() < 0) return nullptr;
    EntryHeader header;
    if (!read_exactly(file.get(), &header, sizeof header)) return nullptr;
    const std::uint64_t pixel_bytes = pixel_bytes_if_valid(header, key);
    // The size is checked before allocating, so a damaged header cannot claim gigabytes.
    struct stat info;
    if (pixel_bytes == 0 || ::fstat(file.get(), &info) != 0 ||
        static_cast<std::uint64_t>(info.st_size) != sizeof header + pixel_bytes)
        return nullptr;
    auto image = std::make_shared<Image>();
    image->path = source_path;
    image->width = static_cast<int>(header.width);
    image->height = static_cast<int>(header.height);
    image->rgba.resize(pixel_bytes);
    if (!read_exactly(file.get(), image->rgba.data(), pixel_bytes)) return nullptr;
    ::futimens(file.get(), nullptr);  // just used: eviction keeps it longest (best effort)
    return image;
}

void ImageCache::store(const Key& key, const Image& image) const {
    const std::size_t pixel_bytes = static_cast<std::size_t>(image.width) * image.height * 4;
    if (!enabled() || pixel_bytes < kSmallestStoredBytes || image.rgba.size() != pixel_bytes) return;
    std::error_code error;
    fs::create_directories(folder_, error);
    if (error) return;
    EntryHeader header{};
    std::memcpy(header.magic, kMagic, sizeof kMagic);
    header.version = kFormatVersion;
    header.width = static_cast<std::uint32_t>(image.width);
    header.height = static_cast<std::uint32_t>(image.height);
    header.content_hash = key.content_hash;
    header.byte_size = key.byte_size;
    const std::string final_path = path(key);
    const std::string temporary_path = temporary_path_for(final_path);
    // Written aside and renamed: a reader sees no entry or a whole one, never a partial one.
    if (!write_entry(temporary_path, header, image.rgba) || ::rename(temporary_path.c_str(), final_path.c_str()) != 0) {
        ::unlink(temporary_path.c_str());
        return;
    }
    evict_least_recently_used();
}

// Every regular file counts, temporary ones too: a write cut short by a crash leaves one behind,
// and as the oldest it goes first.
void ImageCache::evict_least_recently_used() const {
    struct File {
        fs::path path;
        fs::file_time_type last_used;
        std::uintmax_t size;
    };
    std::vector<File> files;
    std::uintmax_t total = 0;
    std::error_code error;
    for (fs::directory_iterator it(folder_, error), end; !error && it != end; it.increment(error)) {
        std::error_code file_error;
        File file{it->path(), it->last_write_time(file_error), 0};
        if (!file_error && it->is_regular_file(file_error) && !file_error) file.size = it->file_size(file_error);
        if (file_error || file.size == 0) continue;  // gone meanwhile, or not a file
        total += file.size;
        files.push_back(std::move(file));
    }
    if (total <= size_limit_) return;
    std::sort(files.begin(), files.end(), [](const File& a, const File& b) { return a.last_used < b.last_used; });
    for (const File& file : files) {
        if (total <= size_limit_) break;
        std::error_code ignored;
        fs::remove(file.path, ignored);  // another process may have removed it first: the space is free either way
        total -= file.size;
    }
}

std::shared_ptr<const Image> load_image_through_cache(const std::string& path, const ImageCache& cache) {
    if (!cache.enabled()) return load_image(path);
    // The file is read once: its bytes are both the key and, on a miss, what is decoded.
    const std::vector<unsigned char> bytes = read_image_file(path);
    const ImageCache::Key key = ImageCache::key(bytes);
    if (std::shared_ptr<const Image> cached = cache.load(key, path)) return cached;
    std::shared_ptr<const Image> image = load_image_from_bytes(bytes, path);
    cache.store(key, *image);
    return image;
}

}  // namespace clr
