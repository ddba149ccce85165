#include "scene/image_library.h"

#include <functional>

#include <sys/stat.h>

#include "core/interruption.h"
#include "core/parallel_for.h"
#include "core/usable_cpus.h"
#include "scene/bounded_file.h"
#include "scene/file_names.h"

namespace clr {
namespace {

namespace fs = std::filesystem;

// Runs work(0) .. work(count - 1) on all cores (core/parallel_for.h), each first checking for
// Ctrl-C: while many images decode, stop after those under way.
void for_each_in_parallel(std::size_t count, const std::function<void(std::size_t)>& work) {
    parallel_for(count, static_cast<std::size_t>(usable_cpu_count()), [&](std::size_t i) {
        throw_if_interrupted();
        work(i);
    });
}

// The header of the image file at `path`; nullopt when the file or its header cannot be
// read, which decoding reports later. The file is read whole (JPEG's size can come after
// large metadata) and read again to decode: the operating system's cache makes the second
// read cheap, and no file's bytes are held while the budget is checked.
std::optional<ImageHeader> header_of_file(const std::string& path) {
    try {
        return read_image_header(read_image_file(path));
    } catch (const ImageError&) {
        return std::nullopt;
    }
}

// Which file `path` names: its device and inode, so that two names of one file are read
// once; the name itself when there is no such file (reading it then fails, under that name).
std::string file_identity(const std::string& path) {
    struct stat status {};
    if (::stat(path.c_str(), &status) != 0) return "name " + path;
    return "file " + std::to_string(status.st_dev) + ":" + std::to_string(status.st_ino);
}

}  // namespace

ImageLibrary::ImageLibrary(const std::string& scene_path, bool placeholders, std::uint64_t memory_limit, bool decode)
    : scene_folder_(fs::path(scene_path).parent_path()),
      placeholders_(placeholders),
      decode_(decode),
      cache_(ImageCache::from_environment()),
      budget_(memory_limit) {}

void ImageLibrary::read_all(const std::vector<Node>& filenames) {
    std::vector<std::string> paths, identities;
    std::vector<const Node*> named_by;  // the first value naming each file, for messages
    for (const Node& filename : filenames) {
        std::string path = path_of(filename);
        std::string identity = file_identity(path);
        if (entries_.try_emplace(identity).second) {
            order_.push_back(identity);
            paths.push_back(std::move(path));
            identities.push_back(std::move(identity));
            named_by.push_back(&filename);
        }
    }
    std::vector<std::optional<ImageHeader>> headers(paths.size());
    for_each_in_parallel(paths.size(), [&](std::size_t i) { headers[i] = header_of_file(paths[i]); });
    for (std::size_t i = 0; i < paths.size(); ++i) reserve_memory(headers[i], *named_by[i]);

    std::vector<Entry> results(paths.size());
    for_each_in_parallel(paths.size(), [&](std::size_t i) { results[i] = read(paths[i], headers[i]); });
    for (std::size_t i = 0; i < paths.size(); ++i) entries_[identities[i]] = std::move(results[i]);
}

std::shared_ptr<const Image> ImageLibrary::image_for(const Node& filename) {
    const std::string path = path_of(filename);
    const std::string identity = file_identity(path);
    auto [entry, is_new] = entries_.try_emplace(identity);
    if (is_new) {
        order_.push_back(identity);
        const std::optional<ImageHeader> header = header_of_file(path);
        reserve_memory(header, filename);
        entry->second = read(path, header);
    }
    const Entry& image = entry->second;
    if (!image.failure.empty()) {
        const std::string problem = "cannot read image '" + path + "': " + image.failure;
        if (!placeholders_) filename.fail(problem);
        filename.warn(problem + "; rendering a placeholder instead");
    }
    return image.image;
}

// Relative to the scene file's folder (scene/file_names.h). A NUL (JSON "\u0000") would end
// the name early for the file system, which would then open another file than the one named.
std::string ImageLibrary::path_of(const Node& filename) const {
    const std::string name = filename.string();
    if (name.find('\0') != std::string::npos)
        filename.fail("filename contains a NUL character (\\u0000), which no file name can hold");
    return path_in_folder(scene_folder_, name);
}

// The cost is taken whether or not the cache holds the image, so that whether a scene loads
// never depends on what earlier runs left behind. Placeholders do not lift the limit: they
// stand in for images that cannot be read, not for images too large to hold.
void ImageLibrary::reserve_memory(const std::optional<ImageHeader>& header, const Node& filename) {
    if (!header || budget_.reserve(header->decoding_bytes)) return;
    const std::uint64_t total = budget_.used() + header->decoding_bytes;
    const std::string size = std::to_string(header->width) + " x " + std::to_string(header->height) +
                             (header->sixteen_bit ? ", 16-bit" : "");
    const std::string together = total > header->decoding_bytes
                                     ? ", and the scene's images up to this one need " + describe_bytes(total) + " together"
                                     : "";
    filename.fail("image '" + path_of(filename) + "' (" + size + ") needs " + describe_bytes(header->decoding_bytes) +
                  " to decode" + together + ", more than the limit of " + describe_bytes(budget_.limit()) +
                  " for a scene's decoded images (set " + kImageMemoryVariable + " to raise it)");
}

ImageLibrary::Entry ImageLibrary::read(const std::string& path, const std::optional<ImageHeader>& header) const {
    if (!decode_) return read_header_only(path, header);
    try {
        return {load_image_through_cache(path, cache_), "", path, header};
    } catch (const ImageError& error) {
        const std::string reason = *error.what() ? error.what() : "unknown error";
        return {placeholders_ ? make_placeholder_image(path) : nullptr, reason, path, header};
    }
}

// A readable header passes. Without one, the image is decoded for the reason it fails: the
// decoder stops at what the header reader could not read, so that costs little.
ImageLibrary::Entry ImageLibrary::read_header_only(const std::string& path, const std::optional<ImageHeader>& header) const {
    if (header) return {nullptr, "", path, header};
    try {
        load_image(path);
        return {nullptr, "", path, header};
    } catch (const ImageError& error) {
        const std::string reason = *error.what() ? error.what() : "unknown error";
        return {placeholders_ ? make_placeholder_image(path) : nullptr, reason, path, header};
    }
}

std::vector<ImageFileInfo> ImageLibrary::files() const {
    std::vector<ImageFileInfo> files;
    for (const std::string& identity : order_) {
        const Entry& entry = entries_.at(identity);
        if (entry.header) {
            files.push_back({entry.path, entry.header->format, entry.header->width, entry.header->height,
                             entry.header->alpha_channel});
        } else if (entry.image) {  // a placeholder
            files.push_back({entry.path, "placeholder", entry.image->width, entry.image->height, false});
        }
    }
    return files;
}

}  // namespace clr
