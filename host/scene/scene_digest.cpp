#include "scene/scene_digest.h"

#include <exception>

#include "core/sha256.h"
#include "scene/image_loader.h"

namespace clr {

std::string scene_digest(const Json& document, const Scene& scene) {
    try {
        Sha256 hash;
        hash.add_field(std::string("clrender scene digest 1")).add_field(document.dump());
        for (const ImageFileInfo& file : scene.image_files) {  // each file once, in the scene's order
            hash.add_field(file.format);
            if (file.format == "placeholder") continue;  // a missing file: its checkerboard is fixed
            const std::vector<unsigned char> bytes = read_image_file(file.path);
            hash.add_field(bytes.data(), bytes.size());
        }
        return to_hex(hash.finish()).substr(0, 16);
    } catch (const std::exception&) {  // libcrypto refused, or the file went away since it was read
        return "";
    }
}

}  // namespace clr
