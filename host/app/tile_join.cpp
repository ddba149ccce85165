#include "app/tile_join.h"

#include <cstdint>
#include <cstring>
#include <optional>
#include <utility>

#include "app/description_check.h"
#include "app/frame_description.h"
#include "app/frame_selection.h"
#include "core/errors.h"
#include "core/interruption.h"
#include "core/pixel_rect.h"
#include "output/image_writer.h"
#include "output/png_reader.h"

namespace clr {
namespace {

std::string size_text(int width, int height) { return std::to_string(width) + "x" + std::to_string(height); }

std::string pixel_text(int x, int y) { return std::to_string(x) + "," + std::to_string(y); }

// Which tile covers each pixel of the frame (0: none yet, else the tile's number + 1), so that
// overlaps name both tiles and a gap names a pixel. Four bytes a pixel, as the image itself.
class Coverage {
public:
    Coverage(int width, int height) : width_(width), height_(height), owner_(static_cast<std::size_t>(width) * height) {}

    // Marks `rect` as tile `tile`'s, or returns the first pixel of it that an earlier tile
    // covers, with that tile's number (the run then fails: what is marked no longer matters).
    struct Overlap {
        int x = 0, y = 0;
        std::size_t earlier_tile = 0;
    };
    std::optional<Overlap> cover(const PixelRect& rect, std::size_t tile) {
        for (int y = rect.y0; y < rect.y1; ++y)
            for (int x = rect.x0; x < rect.x1; ++x) {
                std::uint32_t& owner = owner_[static_cast<std::size_t>(y) * width_ + x];
                if (owner != 0) return Overlap{x, y, owner - 1};
                owner = static_cast<std::uint32_t>(tile + 1);
            }
        return std::nullopt;
    }

    // The first pixel, row by row, that no tile covers.
    std::optional<std::pair<int, int>> first_gap() const {
        for (std::size_t i = 0; i < owner_.size(); ++i)
            if (owner_[i] == 0) return std::pair<int, int>(static_cast<int>(i % width_), static_cast<int>(i / width_));
        return std::nullopt;
    }

private:
    int width_, height_;
    std::vector<std::uint32_t> owner_;
};

// The tile's rectangle of the frame, from its description, after checking that the tile was
// made by this render (everything but Crop) and is a crop of the frame at its Crop's size.
PixelRect checked_tile_rect(const std::string& tile, const PngHeader& header, const Scene& scene, int frame,
                            const Options& options) {
    if (header.text.empty())
        throw SceneError(tile, "", "the tile has no clrender description (PNG text chunks); --join takes the PNG "
                                   "tiles that clrender --crop writes");
    const std::optional<std::string> crop = text_of(header.text, "Crop");
    if (!crop)
        throw SceneError(tile, "", "the tile's description has no Crop: it is a whole image, not a tile that "
                                   "clrender --crop wrote");
    const std::optional<PixelRect> rect = parse_pixel_rect(*crop);
    if (!rect) throw SceneError(tile, "", "the tile's Crop '" + *crop + "' is not x0,x1,y0,y1");
    if (const auto difference = first_difference(without_key(header.text, "Crop"), describe_frame(scene, frame, options)))
        throw SceneError(tile, "", "the tile is of another render: " + difference_sentence(*difference, "tile"));
    if (header.width != rect->width() || header.height != rect->height())
        throw SceneError(tile, "", "the tile is " + size_text(header.width, header.height) + ", its Crop " + *crop +
                                       " is " + size_text(rect->width(), rect->height()));
    if (!rect->inside(scene.width, scene.height))
        throw SceneError(tile, "", "the tile's Crop " + *crop + " reaches outside the " +
                                       size_text(scene.width, scene.height) + " frame");
    if (!header.clrender_form) throw SceneError(tile, "", "the tile is not an 8-bit RGB or RGBA PNG as clrender writes");
    if (header.alpha != options.alpha)
        throw SceneError(tile, "", header.alpha ? "the tile has an alpha channel (rendered with --alpha); join it with --alpha"
                                                : "the tile has no alpha channel, and --alpha writes one: render the "
                                                  "tiles with --alpha");
    return *rect;
}

void paste(Image& frame, const Image& tile, const PixelRect& rect) {
    const std::size_t tile_row = static_cast<std::size_t>(rect.width()) * 4;
    for (int row = 0; row < rect.height(); ++row)
        std::memcpy(frame.rgba.data() + ((static_cast<std::size_t>(rect.y0) + row) * frame.width + rect.x0) * 4,
                    tile.rgba.data() + row * tile_row, tile_row);
}

}  // namespace

void check_join_request(const Options& options, const OutputPlan& plan) {
    if (options.join.empty()) return;
    if (plan.frames.size() != 1)
        throw UsageError("--join makes one image, and this run writes " + std::to_string(plan.frames.size()) +
                         " frames: name one with --frames N");
    if (!options.output_path.empty() && is_frame_pattern(options.output_path))
        throw UsageError("--join makes one image: -o " + options.output_path +
                         " is a frame pattern; name the image, e.g. -o frame.png");
    if (!options.output_path.empty() && image_format_for(options.output_path) == ImageFormat::Exr)
        throw UsageError("--join: -o " + options.output_path + " is an EXR, and tiles hold display colours, not "
                         "linear ones; write a .png or .ppm, or render the EXR in one process");
}

Image join_tiles(const Options& options, const Scene& scene, int frame) {
    const std::vector<std::string>& tiles = options.join;
    Image image;
    image.width = scene.width;
    image.height = scene.height;
    image.write_alpha = options.alpha;
    image.rgba.resize(static_cast<std::size_t>(scene.width) * scene.height * 4);
    Coverage coverage(scene.width, scene.height);
    for (std::size_t i = 0; i < tiles.size(); ++i) {
        throw_if_interrupted();
        const std::string& tile = tiles[i];
        try {
            const PixelRect rect = checked_tile_rect(tile, read_png_header(tile), scene, frame, options);
            if (const auto overlap = coverage.cover(rect, i)) {
                const std::string& earlier = tiles[overlap->earlier_tile];
                throw SceneError(tile, "", "the tile overlaps " + earlier +
                                               (earlier == tile ? " (the same file given twice)" : " (given earlier)") +
                                               ": both cover pixel " + pixel_text(overlap->x, overlap->y));
            }
            paste(image, read_png_pixels(tile, rect.width(), rect.height()), rect);
        } catch (const PngReadError& error) {
            throw SceneError(tile, "", std::string("cannot read the tile: ") + error.what());
        }
    }
    if (const auto gap = coverage.first_gap())
        throw SceneError("--join", "", std::to_string(tiles.size()) + (tiles.size() == 1 ? " tile leaves" : " tiles leave") +
                                           " pixels of the " + size_text(scene.width, scene.height) +
                                           " frame uncovered: no tile covers pixel " + pixel_text(gap->first, gap->second) +
                                           " (column " + std::to_string(gap->first) + ", row " +
                                           std::to_string(gap->second) + ")");
    return image;
}

std::unique_ptr<AtomicFile> write_joined_image(const Options& options, const Scene& scene, const OutputPlan& plan) {
    const int frame = plan.frames.front();
    const Image image = join_tiles(options, scene, frame);
    throw_if_interrupted();
    make_missing_folders(plan);
    return write_image_uncommitted(plan.image_path(frame), image, describe_frame(scene, frame, options));
}

}  // namespace clr
