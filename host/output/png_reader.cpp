// libpng reports errors by longjmp: each function that calls it owns nothing that needs
// unwinding (its caller owns the strings and pixel memory), and the error handler keeps
// libpng's message instead of printing it, so that a failure is one line of clrender's.
#include "output/png_reader.h"

#include <png.h>
#include <sys/stat.h>

#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <memory>
#include <new>
#include <vector>

namespace clr {
namespace {

struct ReadState {
    std::FILE* file = nullptr;
    std::string problem;  // set before libpng's longjmp (or a refusal without one)
};

// Keeps the first message (a read failure sets its own before calling png_error).
void keep_error(png_structp png, png_const_charp message) {
    auto* state = static_cast<ReadState*>(png_get_error_ptr(png));
    if (state->problem.empty()) state->problem = message;
    png_longjmp(png, 1);
}

void ignore_warning(png_structp, png_const_charp) {}

void read_from_file(png_structp png, png_bytep data, png_size_t size) {
    auto* state = static_cast<ReadState*>(png_get_io_ptr(png));
    if (std::fread(data, 1, size, state->file) == size) return;
    if (std::ferror(state->file)) state->problem = std::string("cannot read: ") + std::strerror(errno);
    png_error(png, "truncated: the file ends early");
}

struct FileCloser {
    void operator()(std::FILE* file) const { std::fclose(file); }
};
using OpenFile = std::unique_ptr<std::FILE, FileCloser>;

// Opens a regular file (a FIFO would block the open) that starts with PNG's signature.
OpenFile open_png(const std::string& path) {
    struct stat status {};
    if (::stat(path.c_str(), &status) != 0) throw PngReadError(std::string("cannot open: ") + std::strerror(errno));
    if (!S_ISREG(status.st_mode)) throw PngReadError("not a regular file");
    OpenFile file(std::fopen(path.c_str(), "rb"));
    if (!file) throw PngReadError(std::string("cannot open: ") + std::strerror(errno));
    png_byte signature[8] = {};
    if (std::fread(signature, 1, sizeof signature, file.get()) != sizeof signature ||
        png_sig_cmp(signature, 0, sizeof signature) != 0)
        throw PngReadError("not a PNG file");
    return file;
}

// The read structures for `state`, past the signature; nullptr when libpng cannot start.
png_structp start_reading(ReadState& state, png_infop& info) {
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &state, keep_error, ignore_warning);
    info = png ? png_create_info_struct(png) : nullptr;
    if (!info) {
        png_destroy_read_struct(&png, nullptr, nullptr);
        return nullptr;
    }
    png_set_read_fn(png, &state, read_from_file);
    png_set_sig_bytes(png, 8);
    return png;
}

// IHDR's part of a header: nothing that needs unwinding, so it may live where libpng longjmps.
struct ImageForm {
    int width = 0, height = 0;
    bool alpha = false, clrender_form = false;
};

ImageForm read_form(png_structp png, png_infop info) {
    ImageForm form;
    form.width = static_cast<int>(png_get_image_width(png, info));
    form.height = static_cast<int>(png_get_image_height(png, info));
    const int color_type = png_get_color_type(png, info);
    form.alpha = (color_type & PNG_COLOR_MASK_ALPHA) != 0;
    form.clrender_form = png_get_bit_depth(png, info) == 8 &&
                         (color_type == PNG_COLOR_TYPE_RGB || color_type == PNG_COLOR_TYPE_RGB_ALPHA);
    return form;
}

// Fills `header` from the chunks before the pixel data. Returns false with state.problem set.
bool read_header_chunks(ReadState& state, PngHeader& header) {
    png_infop info = nullptr;
    png_structp png = start_reading(state, info);
    if (!png) {
        state.problem = "cannot start libpng";
        return false;
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_read_struct(&png, &info, nullptr);
        return false;
    }
    png_read_info(png, info);
    const ImageForm form = read_form(png, info);
    header.width = form.width;
    header.height = form.height;
    header.alpha = form.alpha;
    header.clrender_form = form.clrender_form;
    png_textp chunks = nullptr;
    const int count = png_get_text(png, info, &chunks, nullptr);
    try {
        for (int i = 0; i < count; ++i)
            header.text.emplace_back(chunks[i].key, std::string(chunks[i].text, chunks[i].text_length));
    } catch (const std::bad_alloc&) {
        state.problem = "out of memory";
    }
    png_destroy_read_struct(&png, &info, nullptr);
    return state.problem.empty();
}

// Whether the file's last 12 bytes are an IEND chunk: a PNG cut short does not end with one.
bool ends_with_iend(std::FILE* file) {
    static const unsigned char iend[12] = {0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xAE, 0x42, 0x60, 0x82};
    unsigned char last[12] = {};
    return std::fseek(file, -12, SEEK_END) == 0 && std::fread(last, 1, sizeof last, file) == sizeof last &&
           std::memcmp(last, iend, sizeof iend) == 0;
}

// Decodes into `rows` (height pointers into RGBA memory). Returns false with state.problem set.
bool decode_rows(ReadState& state, int width, int height, std::vector<png_bytep>& rows) {
    png_infop info = nullptr;
    png_structp png = start_reading(state, info);
    if (!png) {
        state.problem = "cannot start libpng";
        return false;
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_read_struct(&png, &info, nullptr);
        return false;
    }
    png_read_info(png, info);
    const ImageForm form = read_form(png, info);
    if (!form.clrender_form || form.width != width || form.height != height) {
        state.problem = form.clrender_form ? "the image changed while it was read" : "not an 8-bit RGB or RGBA PNG";
        png_destroy_read_struct(&png, &info, nullptr);
        return false;
    }
    if (!form.alpha) png_set_filler(png, 0xFF, PNG_FILLER_AFTER);
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    png_read_image(png, rows.data());
    png_read_end(png, nullptr);  // the CRCs of the chunks after the pixels, up to IEND
    png_destroy_read_struct(&png, &info, nullptr);
    return true;
}

}  // namespace

PngHeader read_png_header(const std::string& path) {
    OpenFile file = open_png(path);
    ReadState state;
    state.file = file.get();
    PngHeader header;
    if (!read_header_chunks(state, header)) throw PngReadError(state.problem);
    if (!ends_with_iend(file.get())) throw PngReadError("truncated: it does not end with an IEND chunk");
    return header;
}

Image read_png_pixels(const std::string& path, int width, int height) {
    OpenFile file = open_png(path);
    Image image;
    image.width = width;
    image.height = height;
    image.path = path;
    image.rgba.resize(static_cast<std::size_t>(width) * height * 4);
    std::vector<png_bytep> rows(static_cast<std::size_t>(height));
    for (int row = 0; row < height; ++row) rows[row] = image.rgba.data() + static_cast<std::size_t>(row) * width * 4;
    ReadState state;
    state.file = file.get();
    if (!decode_rows(state, width, height, rows)) throw PngReadError(state.problem);
    return image;
}

}  // namespace clr
