#include "scene/jpeg_decoder.h"

// jpeglib.h needs size_t and FILE declared before it.
#include <cstddef>
#include <cstdio>
#include <csetjmp>
#include <jpeglib.h>
#include <jerror.h>  // the JWRN_ message codes

#include <new>
#include <string>

#include "core/printable_text.h"
#include "scene/image_loader.h"  // ImageError

namespace clr {
namespace {

constexpr int kRgba = 4;

// libjpeg's error manager, extended with where to jump and what went wrong. libjpeg calls
// error_exit for an error it cannot go on from, and emit_message for warnings (level -1:
// corrupt or missing data, which it would otherwise patch over with grey) and trace messages.
struct ErrorState {
    jpeg_error_mgr manager;  // first: libjpeg sees a pointer to it
    std::jmp_buf jump;
    char message[JMSG_LENGTH_MAX];
    bool failed_on_warning;
};

[[noreturn]] void on_error(j_common_ptr info) {
    auto* state = reinterpret_cast<ErrorState*>(info->err);
    (*info->err->format_message)(info, state->message);
    std::longjmp(state->jump, 1);
}

// The warnings after which libjpeg makes up pixels (grey for data that is missing or cannot
// be decoded): a silently wrong image, so they are refused as corrupt. Others (extraneous
// bytes before a marker, as some cameras write; an unknown JFIF version) lose nothing.
bool loses_pixels(int warning) {
    switch (warning) {
        case JWRN_HIT_MARKER:
        case JWRN_JPEG_EOF:
        case JWRN_HUFF_BAD_CODE:
        case JWRN_ARITH_BAD_CODE:
        case JWRN_MUST_RESYNC:
        case JWRN_NOT_SEQUENTIAL:
        case JWRN_BOGUS_PROGRESSION: return true;
        default: return false;
    }
}

void on_message(j_common_ptr info, int level) {
    if (level >= 0 || !loses_pixels(info->err->msg_code)) return;
    auto* state = reinterpret_cast<ErrorState*>(info->err);
    (*info->err->format_message)(info, state->message);
    state->failed_on_warning = true;
    std::longjmp(state->jump, 1);
}

// stb_image's CMYK conversion (stb 2.27, stbi__blinn_8x8 and the Adobe inverted convention
// libjpeg leaves in place): each channel times K.
unsigned char times_over_255(unsigned x, unsigned y) {
    const unsigned t = x * y + 128;
    return static_cast<unsigned char>((t + (t >> 8)) >> 8);
}

void cmyk_row_to_rgba(unsigned char* row, unsigned width) {
    for (unsigned x = 0; x < width; ++x) {
        unsigned char* p = row + std::size_t(x) * kRgba;
        const unsigned k = p[3];
        p[0] = times_over_255(p[0], k);
        p[1] = times_over_255(p[1], k);
        p[2] = times_over_255(p[2], k);
        p[3] = 255;
    }
}

// The libjpeg calls, from the header to the last row, in one C-style frame: libjpeg longjmps
// back to the setjmp here, so no object with a destructor may live in this frame, and the
// decompressor is destroyed by the caller. Returns false when libjpeg failed (the reason is in
// `state`); C++ exceptions (the size check, std::bad_alloc) leave it as usual.
bool run_decoder(jpeg_decompress_struct& info, ErrorState& state, const std::vector<unsigned char>& bytes, Image& image,
                 void (*check_size)(long long, long long)) {
    if (setjmp(state.jump)) return false;
    jpeg_mem_src(&info, bytes.data(), static_cast<unsigned long>(bytes.size()));
    jpeg_read_header(&info, TRUE);
    // Before anything is allocated for pixels: a few bytes can claim gigabytes.
    check_size(info.image_width, info.image_height);
    const bool cmyk = info.jpeg_color_space == JCS_CMYK || info.jpeg_color_space == JCS_YCCK;
    info.out_color_space = cmyk ? JCS_CMYK : JCS_EXT_RGBA;  // RGBA with alpha 255 for grey and colour
    // Closest to stb_image: the accurate integer IDCT and smooth (triangular) upsampling of
    // subsampled chroma (docs/benchmarks.md, Figures behind design choices).
    info.dct_method = JDCT_ISLOW;
    info.do_fancy_upsampling = TRUE;
    jpeg_start_decompress(&info);
    image.width = static_cast<int>(info.output_width);
    image.height = static_cast<int>(info.output_height);
    const std::size_t stride = std::size_t(info.output_width) * kRgba;
    image.rgba.resize(stride * info.output_height);
    while (info.output_scanline < info.output_height) {
        unsigned char* row = image.rgba.data() + stride * info.output_scanline;
        JSAMPROW rows[] = {row};
        jpeg_read_scanlines(&info, rows, 1);
        if (cmyk) cmyk_row_to_rgba(row, info.output_width);
    }
    jpeg_finish_decompress(&info);
    return true;
}

// Owns libjpeg's decompressor, so that an exception or a failure cannot leak it.
class Decompressor {
public:
    Decompressor() {
        info_.err = jpeg_std_error(&state_.manager);
        state_.manager.error_exit = on_error;
        state_.manager.emit_message = on_message;
        state_.message[0] = '\0';
        state_.failed_on_warning = false;
        created_ = create();
    }
    ~Decompressor() {
        if (created_) jpeg_destroy_decompress(&info_);
    }
    Decompressor(const Decompressor&) = delete;
    Decompressor& operator=(const Decompressor&) = delete;

    bool created() const { return created_; }
    jpeg_decompress_struct& info() { return info_; }
    ErrorState& state() { return state_; }

private:
    // jpeg_create_decompress fails only when it cannot allocate its working memory.
    bool create() {
        if (setjmp(state_.jump)) return false;
        jpeg_create_decompress(&info_);
        return true;
    }

    jpeg_decompress_struct info_{};
    ErrorState state_{};
    bool created_ = false;
};

}  // namespace

void decode_jpeg(const std::vector<unsigned char>& bytes, Image& image, void (*check_size)(long long, long long)) {
    Decompressor decompressor;
    if (!decompressor.created()) throw std::bad_alloc();
    if (!run_decoder(decompressor.info(), decompressor.state(), bytes, image, check_size)) {
        image.rgba.clear();
        image.width = image.height = 0;
        throw ImageError("corrupt JPEG: " + printable(decompressor.state().message));
    }
}

std::string jpeg_decoder_version() { return std::to_string(LIBJPEG_TURBO_VERSION_NUMBER); }

void* jpeg_decoder_entry_point() { return reinterpret_cast<void*>(&jpeg_read_header); }

}  // namespace clr
