#include "scene/image_cache.h"

#include <stb_image.h>

#include <stdexcept>

#include "core/cache_folder.h"
#include "core/code_file.h"
#include "scene/image_loader.h"
#include "scene/jpeg_decoder.h"

namespace clr {
namespace {

constexpr std::uint32_t kLargestSide = 1u << 30;  // image sizes are ints

CacheEntryKind image_entries(std::uint64_t size_limit) {
    // An entry larger than the whole cache could never be kept: a header claiming one is refused.
    return {"rgba", {'c', 'l', 'r', 'i', 'm', 'a', 'g', 'e'}, ImageCache::kFormatVersion, size_limit};
}

// stb_image decodes PNG, libjpeg-turbo JPEG (scene/jpeg_decoder.h); the build of each library
// (core/code_file.h) is in the key: a library update may decode some file differently.
const std::string& decoder_identity() {
    static const std::string identity =
        "stb: " + code_file_identity(reinterpret_cast<const void*>(&stbi_load_from_memory)) + "; libjpeg-turbo " +
        jpeg_decoder_version() + ": " + code_file_identity(jpeg_decoder_entry_point());
    return identity;
}

}  // namespace

void ImageCache::prepare_keys() noexcept {
    try {
        decoder_identity();
        Sha256().finish();
    } catch (const std::exception&) {
    }
}

ImageCache ImageCache::from_environment() { return ImageCache(cache_folder_from_environment()); }

ImageCache::ImageCache(std::string cache_folder, std::uint64_t size_limit)
    : entries_(std::move(cache_folder), "images", image_entries(size_limit), size_limit) {}

ImageCache::Key ImageCache::key(const std::vector<unsigned char>& file_bytes) {
    const std::string& decoder = decoder_identity();
    return Sha256()
        .add_field(std::string("clrender decoded image"))
        .add_number(kFormatVersion)
        .add_field(decoder)
        .add_field(file_bytes.data(), file_bytes.size())
        .finish();
}

std::shared_ptr<const Image> ImageCache::load(const Key& key, const std::string& source_path) const {
    std::optional<CacheEntry> entry = entries_.load(key);
    if (!entry) return nullptr;
    const std::uint32_t width = entry->detail[0], height = entry->detail[1];
    if (width == 0 || height == 0 || width > kLargestSide || height > kLargestSide ||
        entry->payload.size() != std::uint64_t(width) * height * 4) {
        entries_.remove(key);  // a verified entry cannot say this; ours all the same, and useless
        return nullptr;
    }
    auto image = std::make_shared<Image>();
    image->path = source_path;
    image->width = static_cast<int>(width);
    image->height = static_cast<int>(height);
    image->rgba = std::move(entry->payload);
    return image;
}

void ImageCache::store(const Key& key, const Image& image) const {
    const std::size_t pixel_bytes = static_cast<std::size_t>(image.width) * image.height * 4;
    if (!enabled() || pixel_bytes < kSmallestStoredBytes || image.rgba.size() != pixel_bytes) return;
    entries_.store(key, {static_cast<std::uint32_t>(image.width), static_cast<std::uint32_t>(image.height)},
                   image.rgba.data(), image.rgba.size());
}

std::shared_ptr<const Image> load_image_through_cache(const std::string& path, const ImageCache& cache) {
    if (!cache.enabled()) return load_image(path);
    // The file is read once: its bytes are both the key and, on a miss, what is decoded.
    const std::vector<unsigned char> bytes = read_image_file(path);
    std::optional<ImageCache::Key> key;
    try {
        key = ImageCache::key(bytes);
        if (std::shared_ptr<const Image> cached = cache.load(*key, path)) return cached;
    } catch (const std::exception&) {  // no hashing (libcrypto refused), or no memory for the entry: no caching
        key.reset();
    }
    std::shared_ptr<const Image> image = load_image_from_bytes(bytes, path);
    if (key) {
        try {
            cache.store(*key, *image);
        } catch (const std::exception&) {  // best effort
        }
    }
    return image;
}

}  // namespace clr
