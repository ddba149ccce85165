// The images a scene names, each distinct file read and decoded once however many billboards
// and impostor views show it, all of them within one memory budget (scene/image_budget.h).
// Files are told apart by device and inode, not by name: "a.png", "./a.png", "../s/a.png"
// and a link to it are one file.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/image.h"
#include "scene/scene.h"
#include "scene/image_budget.h"
#include "scene/image_cache.h"
#include "scene/image_loader.h"
#include "scene/json_reader.h"

namespace clr {

class ImageLibrary {
public:
    // Relative file names are taken from the folder of `scene_path`. With `placeholders`, an
    // image that cannot be read becomes make_placeholder_image() and a warning.
    // With `decode` false (--check) images are checked from their headers only: image_for
    // returns null for a readable header, and a corrupt raster goes unnoticed.
    ImageLibrary(const std::string& scene_path, bool placeholders, std::uint64_t memory_limit, bool decode = true);

    // Reads and decodes every distinct image the "filename" values name, on all cores at once:
    // decoding large PNGs is most of the time it takes to load a course scene. First every
    // header is read and the decoding costs are summed in the order given: the first image
    // that takes the sum past the memory limit fails (a SceneError at the first value naming
    // it) before any image is decoded.
    void read_all(const std::vector<Node>& filenames);

    // The image a "filename" value names (read now if read_all did not), or its placeholder;
    // fails at the value when the image cannot be read and there are no placeholders.
    std::shared_ptr<const Image> image_for(const Node& filename);

    // Each distinct file read, in the order first named, as its header describes it.
    std::vector<ImageFileInfo> files() const;

private:
    struct Entry {
        std::shared_ptr<const Image> image;
        std::string failure;  // empty when the image was read
        std::string path;     // as first named
        std::optional<ImageHeader> header;
    };

    std::string path_of(const Node& filename) const;
    // Takes the image's decoding cost from the budget, or fails at `filename`.
    void reserve_memory(const std::optional<ImageHeader>& header, const Node& filename);
    Entry read(const std::string& path, const std::optional<ImageHeader>& header) const;
    Entry read_header_only(const std::string& path, const std::optional<ImageHeader>& header) const;

    std::filesystem::path scene_folder_;
    bool placeholders_;
    bool decode_;
    ImageCache cache_;  // decoded large images from earlier runs (a warm start skips decoding)
    ImageMemoryBudget budget_;
    std::map<std::string, Entry> entries_;  // by file identity (device and inode)
    std::vector<std::string> order_;        // identities in the order first named
};

}  // namespace clr
