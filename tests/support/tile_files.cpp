#include "support/tile_files.h"

#include <stdexcept>

#include "output/image_writer.h"
#include "output/png_reader.h"
#include "support/command.h"
#include "support/image_rect.h"

namespace clr::testing {
namespace {

Image read_png(const std::string& path, PngHeader& header) {
    header = read_png_header(path);
    Image image = read_png_pixels(path, header.width, header.height);
    image.write_alpha = header.alpha;
    return image;
}

}  // namespace

void set_png_text(const std::string& path, const std::string& key, const std::optional<std::string>& value) {
    PngHeader header;
    const Image image = read_png(path, header);
    ImageText text;
    bool found = false;
    for (const auto& pair : header.text) {
        if (pair.first != key) {
            text.push_back(pair);
        } else if (value) {
            text.emplace_back(key, *value);
            found = true;
        }
    }
    if (value && !found) text.emplace_back(key, *value);
    write_image(path, image, text);
}

std::function<void(const std::string&)> clrender_writes(std::vector<std::string> commands,
                                                        std::function<void(const std::string&)> alter) {
    return [commands, alter](const std::string& folder) {
        for (const std::string& command : commands) {
            const CommandResult result = run_clrender(command, folder);
            if (result.exit_code != 0) throw std::runtime_error("preparing the case: clrender " + command + ": " + result.output);
        }
        if (alter) alter(folder);
    };
}

void cut_png(const std::string& path, const PixelRect& rect) {
    PngHeader header;
    const Image image = read_png(path, header);
    Image part = cut(image, rect);
    part.write_alpha = image.write_alpha;
    write_image(path, part, header.text);
}

}  // namespace clr::testing
