#include "support/png_chunks.h"

#include <png.h>

#include <csetjmp>
#include <cstdio>

namespace clr::testing {
namespace {

// libpng's part, in a function of its own: a longjmp out of libpng lands here with nothing to
// unwind. Returns false when the file is no readable PNG.
bool read_description(std::FILE* file, PngDescription& description) {
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    png_infop end_info = info ? png_create_info_struct(png) : nullptr;
    if (!end_info || setjmp(png_jmpbuf(png))) {
        png_destroy_read_struct(&png, &info, &end_info);
        return false;
    }
    png_init_io(png, file);
    png_read_png(png, info, PNG_TRANSFORM_IDENTITY, nullptr);  // text after the pixels lands in info too
    int intent = 0;
    if (png_get_sRGB(png, info, &intent) != 0) description.srgb_intent = intent;
    png_textp chunks = nullptr;
    const int count = png_get_text(png, info, &chunks, nullptr);
    for (int i = 0; i < count; ++i) description.text[chunks[i].key] = std::string(chunks[i].text, chunks[i].text_length);
    png_destroy_read_struct(&png, &info, &end_info);
    return true;
}

}  // namespace

PngDescription read_png_description(const std::string& path) {
    PngDescription description;
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (!file) return description;
    description.readable = read_description(file, description);
    std::fclose(file);
    if (!description.readable) return PngDescription{};
    return description;
}

}  // namespace clr::testing
