#include "scene/image_library.h"

#include <algorithm>
#include <exception>
#include <thread>

#include "scene/bounded_file.h"

namespace clr {

namespace fs = std::filesystem;

ImageLibrary::ImageLibrary(const std::string& scene_path, bool placeholders, std::uint64_t memory_limit)
    : scene_folder_(fs::path(scene_path).parent_path()),
      placeholders_(placeholders),
      cache_(ImageCache::from_environment()),
      budget_(memory_limit) {}

void ImageLibrary::read_all(const std::vector<Node>& filenames) {
    std::vector<std::string> paths;
    std::vector<const Node*> named_by;  // the first value naming each path, for messages
    for (const Node& filename : filenames) {
        std::string path = path_of(filename);
        if (entries_.try_emplace(path).second) {
            paths.push_back(std::move(path));
            named_by.push_back(&filename);
        }
    }
    std::vector<Entry> results(paths.size());
    std::vector<std::exception_ptr> errors(paths.size());
    std::atomic<std::size_t> next{0};
    auto worker = [&] {
        for (std::size_t i; (i = next++) < paths.size();) {
            try {
                results[i] = read(paths[i]);
            } catch (...) {
                errors[i] = std::current_exception();  // e.g. out of memory: rethrown below
            }
        }
    };
    std::size_t thread_count = std::min<std::size_t>(std::max(1u, std::thread::hardware_concurrency()), paths.size());
    std::vector<std::thread> helpers;
    for (std::size_t t = 1; t < thread_count; ++t) helpers.emplace_back(worker);
    worker();
    for (std::thread& helper : helpers) helper.join();
    for (const std::exception_ptr& error : errors) {
        if (error) std::rethrow_exception(error);
    }
    check_budget(results, named_by);
    for (std::size_t i = 0; i < paths.size(); ++i) entries_[paths[i]] = std::move(results[i]);
}

std::shared_ptr<const Image> ImageLibrary::image_for(const Node& filename) {
    const std::string path = path_of(filename);
    auto [entry, is_new] = entries_.try_emplace(path);
    if (is_new) {
        entry->second = read(path);
        if (entry->second.over_budget) fail_over_budget(filename, entry->second, 0);
    }
    const Entry& image = entry->second;
    if (!image.failure.empty()) {
        const std::string problem = "cannot read image '" + path + "': " + image.failure;
        if (!placeholders_) filename.fail(problem);
        filename.warn(problem + "; rendering a placeholder instead");
    }
    return image.image;
}

// Relative to the scene file's folder; lexically normal, so that "./a.png" and "a.png" are
// one file. A NUL (JSON "\u0000") would end the name early for the file system, which would
// then open another file than the one named.
std::string ImageLibrary::path_of(const Node& filename) const {
    const std::string name = filename.string();
    if (name.find('\0') != std::string::npos)
        filename.fail("filename contains a NUL character (\\u0000), which no file name can hold");
    const fs::path path(name);
    return (path.is_absolute() ? path : scene_folder_ / path).lexically_normal().string();
}

// The cost of decoding comes from the header and is taken from the budget before anything is
// decoded. It is taken whether or not the cache holds the image, so that whether a scene
// loads never depends on what earlier runs left behind.
ImageLibrary::Entry ImageLibrary::read(const std::string& path) {
    Entry entry;
    try {
        const std::vector<unsigned char> bytes = read_image_file(path);
        entry.header = read_image_header(bytes);
        if (entry.header && (budget_exceeded_ || !budget_.reserve(entry.header->decoding_bytes))) {
            budget_exceeded_ = true;
            entry.over_budget = true;
            return entry;
        }
        entry.image = decode_through_cache(bytes, path);
    } catch (const ImageError& error) {
        entry.failure = *error.what() ? error.what() : "unknown error";
        if (placeholders_) entry.image = make_placeholder_image(path);
    }
    return entry;
}

// load_image_through_cache() for bytes already read: the header had to be read first.
std::shared_ptr<const Image> ImageLibrary::decode_through_cache(const std::vector<unsigned char>& bytes,
                                                                const std::string& path) const {
    if (!cache_.enabled()) return load_image_from_bytes(bytes, path);
    const ImageCache::Key key = ImageCache::key(bytes);
    if (std::shared_ptr<const Image> cached = cache_.load(key, path)) return cached;
    std::shared_ptr<const Image> image = load_image_from_bytes(bytes, path);
    cache_.store(key, *image);
    return image;
}

// Images were decoded in parallel, so which one found the budget spent depends on timing.
// The one reported does not: the first, in the scene's order, that takes the sum past it.
void ImageLibrary::check_budget(const std::vector<Entry>& entries, const std::vector<const Node*>& named_by) const {
    if (!budget_exceeded_) return;
    std::uint64_t total = 0;
    for (std::size_t i = 0; i < entries.size(); ++i) {
        if (!entries[i].header) continue;
        total += entries[i].header->decoding_bytes;
        if (total > budget_.limit()) fail_over_budget(*named_by[i], entries[i], total);
    }
}

void ImageLibrary::fail_over_budget(const Node& filename, const Entry& entry, std::uint64_t total) const {
    const ImageHeader& header = *entry.header;
    const std::string size = std::to_string(header.width) + " x " + std::to_string(header.height) +
                             (header.sixteen_bit ? ", 16-bit" : "");
    const std::string together = total > header.decoding_bytes
                                     ? ", and the scene's images up to this one need " + describe_bytes(total) + " together"
                                     : "";
    filename.fail("image '" + path_of(filename) + "' (" + size + ") needs " + describe_bytes(header.decoding_bytes) +
                  " to decode" + together + ", more than the limit of " + describe_bytes(budget_.limit()) +
                  " for a scene's decoded images (set " + kImageMemoryVariable + " to raise it)");
}

}  // namespace clr
