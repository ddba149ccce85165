// stb_image against libjpeg-turbo on JPEG files: decode time (best of several runs) and how far
// their pixels differ, with libjpeg's smooth upsampling of subsampled chroma (as clrender decodes)
// and without it. The figures behind clrender's choice of JPEG decoder (docs/benchmarks.md,
// Figures behind design choices). Usage: clrender_jpeg_bench FILE.jpg...
#include <cstddef>
#include <cstdio>
#include <jpeglib.h>
#include <stb_image.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

std::vector<unsigned char> read_file(const char* path) {
    std::ifstream file(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(file), {}};
}

// RGBA from libjpeg-turbo with the accurate integer IDCT (clrender's settings when `smooth`).
std::vector<unsigned char> decode_turbo(const std::vector<unsigned char>& bytes, bool smooth) {
    jpeg_decompress_struct info{};
    jpeg_error_mgr errors{};
    info.err = jpeg_std_error(&errors);  // exits on an error: the benchmark takes valid files
    jpeg_create_decompress(&info);
    jpeg_mem_src(&info, bytes.data(), bytes.size());
    jpeg_read_header(&info, TRUE);
    info.out_color_space = JCS_EXT_RGBA;
    info.dct_method = JDCT_ISLOW;
    info.do_fancy_upsampling = smooth ? TRUE : FALSE;
    jpeg_start_decompress(&info);
    std::vector<unsigned char> rgba(std::size_t(info.output_width) * info.output_height * 4);
    while (info.output_scanline < info.output_height) {
        JSAMPROW row = &rgba[std::size_t(info.output_scanline) * info.output_width * 4];
        jpeg_read_scanlines(&info, &row, 1);
    }
    jpeg_finish_decompress(&info);
    jpeg_destroy_decompress(&info);
    return rgba;
}

double milliseconds(Clock::time_point from, Clock::time_point to) {
    return std::chrono::duration<double, std::milli>(to - from).count();
}

struct Difference {
    int largest = 0;
    double share = 0;  // of the samples that differ at all
};

Difference difference(const unsigned char* a, const std::vector<unsigned char>& b) {
    Difference result;
    std::size_t differing = 0;
    for (std::size_t i = 0; i < b.size(); ++i) {
        const int d = std::abs(int(a[i]) - int(b[i]));
        result.largest = std::max(result.largest, d);
        differing += d != 0;
    }
    result.share = b.empty() ? 0 : double(differing) / b.size();
    return result;
}

}  // namespace

int main(int argc, char** argv) {
    for (int arg = 1; arg < argc; ++arg) {
        const std::vector<unsigned char> bytes = read_file(argv[arg]);
        const int runs = std::clamp(int(2e7 / std::max<std::size_t>(bytes.size(), 1)), 3, 50);
        double stb_ms = 1e30, smooth_ms = 1e30, plain_ms = 1e30;
        unsigned char* stb = nullptr;
        std::vector<unsigned char> smooth, plain;
        int width = 0, height = 0, channels = 0;
        for (int run = 0; run < runs; ++run) {
            stbi_image_free(stb);
            const auto t0 = Clock::now();
            stb = stbi_load_from_memory(bytes.data(), int(bytes.size()), &width, &height, &channels, 4);
            const auto t1 = Clock::now();
            smooth = decode_turbo(bytes, true);
            const auto t2 = Clock::now();
            plain = decode_turbo(bytes, false);
            const auto t3 = Clock::now();
            if (!stb) return std::fprintf(stderr, "%s: stb cannot decode it\n", argv[arg]), 1;
            stb_ms = std::min(stb_ms, milliseconds(t0, t1));
            smooth_ms = std::min(smooth_ms, milliseconds(t1, t2));
            plain_ms = std::min(plain_ms, milliseconds(t2, t3));
        }
        const Difference d_smooth = difference(stb, smooth), d_plain = difference(stb, plain);
        std::printf("%s %dx%d: stb %.2f ms, libjpeg-turbo %.2f ms (%.2fx), without smooth upsampling %.2f ms; "
                    "pixels against stb: largest difference %d, %.2f%% of samples differ (without: %d, %.2f%%)\n",
                    argv[arg], width, height, stb_ms, smooth_ms, smooth_ms / stb_ms, plain_ms, d_smooth.largest,
                    100 * d_smooth.share, d_plain.largest, 100 * d_plain.share);
        stbi_image_free(stb);
    }
    return 0;
}
