// Fixed point with 16 fraction bits: each coefficient is off by at most 2^-17, so a value
// (three terms of at most 255, or of 4 * 255 summed over a 2x2 block and divided by 4) is off
// by less than 0.006 before rounding. The loops keep to plain integer arithmetic on rows so
// that the compiler can vectorise them; a 1280x720 frame takes about 1.6 ms on one core of a
// 2-CPU Xeon (docs/benchmarks.md, Videos at the speed of the machine).
#include "output/yuv420_frame.h"

#include <algorithm>

namespace clr {
namespace {

constexpr int kFractionBits = 16;

// BT.709's luma weights (ITU-R BT.709-6, item 3.2).
constexpr double kKr = 0.2126, kKb = 0.0722, kKg = 1 - kKr - kKb;
// Limited range: Y' spans 219 steps from 16, Cb and Cr 224 steps around 128.
constexpr double kLumaScale = 219.0 / 255.0, kChromaScale = 224.0 / 255.0;

constexpr std::int32_t fixed(double value) {
    return static_cast<std::int32_t>(value * (1 << kFractionBits) + (value < 0 ? -0.5 : 0.5));
}

constexpr std::int32_t kYr = fixed(kLumaScale * kKr), kYg = fixed(kLumaScale * kKg), kYb = fixed(kLumaScale * kKb);
constexpr std::int32_t kCbR = fixed(-kChromaScale * kKr / (2 * (1 - kKb)));
constexpr std::int32_t kCbG = fixed(-kChromaScale * kKg / (2 * (1 - kKb)));
constexpr std::int32_t kCbB = fixed(kChromaScale * 0.5);
constexpr std::int32_t kCrR = fixed(kChromaScale * 0.5);
constexpr std::int32_t kCrG = fixed(-kChromaScale * kKg / (2 * (1 - kKr)));
constexpr std::int32_t kCrB = fixed(-kChromaScale * kKb / (2 * (1 - kKr)));

// Offsets with the rounding half folded in. Every sum stays positive (Y' >= 16, Cb and Cr >=
// 16 for any 8-bit input), so the right shifts round to nearest.
constexpr std::int32_t kLumaOffset = (16 << kFractionBits) + (1 << (kFractionBits - 1));
// Chroma sums four pixels: two more fraction bits divide by 4.
constexpr int kChromaShift = kFractionBits + 2;
constexpr std::int32_t kChromaOffset = (128 << kChromaShift) + (1 << (kChromaShift - 1));

// The padding outside the frame: black, Y' 16.
constexpr std::uint8_t kPaddingLuma = 16;

}  // namespace

int even_size(int size) { return size + (size & 1); }

std::size_t yuv420_bytes(int width, int height) {
    const std::size_t luma = static_cast<std::size_t>(even_size(width)) * static_cast<std::size_t>(even_size(height));
    return luma + luma / 2;
}

namespace {

std::uint8_t luma_of(std::int32_t r, std::int32_t g, std::int32_t b) {
    return static_cast<std::uint8_t>((kYr * r + kYg * g + kYb * b + kLumaOffset) >> kFractionBits);
}

// Cb or Cr from the sums of a block's four R'G'B' values.
std::uint8_t chroma_of(std::int32_t cr, std::int32_t cg, std::int32_t cb, std::int32_t r_sum, std::int32_t g_sum,
                       std::int32_t b_sum) {
    return static_cast<std::uint8_t>((cr * r_sum + cg * g_sum + cb * b_sum + kChromaOffset) >> kChromaShift);
}

// One pair of rows: `upper` and `lower` hold `width` RGBA pixels each (`lower` is a row of
// zeros, black, below an odd height's last row). Writes two rows of Y' (`luma_lower` may be
// a scratch row) and one of Cb and Cr.
// The pointers are __restrict: without it every store of a byte could alias the frame, and
// the compiler reloads the pixels after each one (1.6 times slower, and not vectorised).
void convert_row_pair(const std::uint8_t* __restrict upper, const std::uint8_t* __restrict lower, int width,
                      std::uint8_t* __restrict luma_upper, std::uint8_t* __restrict luma_lower,
                      std::uint8_t* __restrict cb, std::uint8_t* __restrict cr) {
    const int blocks = width / 2;
    // Whole 2x2 blocks: one loop body without branches, which the compiler vectorises.
    for (int block = 0; block < blocks; ++block) {
        const std::uint8_t* const u = upper + block * 8;
        const std::uint8_t* const l = lower + block * 8;
        const std::int32_t r0 = u[0], g0 = u[1], b0 = u[2], r1 = u[4], g1 = u[5], b1 = u[6];
        const std::int32_t r2 = l[0], g2 = l[1], b2 = l[2], r3 = l[4], g3 = l[5], b3 = l[6];
        luma_upper[block * 2] = luma_of(r0, g0, b0);
        luma_upper[block * 2 + 1] = luma_of(r1, g1, b1);
        luma_lower[block * 2] = luma_of(r2, g2, b2);
        luma_lower[block * 2 + 1] = luma_of(r3, g3, b3);
        const std::int32_t r = r0 + r1 + r2 + r3, g = g0 + g1 + g2 + g3, b = b0 + b1 + b2 + b3;
        cb[block] = chroma_of(kCbR, kCbG, kCbB, r, g, b);
        cr[block] = chroma_of(kCrR, kCrG, kCrB, r, g, b);
    }
    if (width % 2 == 0) return;
    // An odd width's last pixel and the black padding column beside it.
    const std::uint8_t* const u = upper + blocks * 8;
    const std::uint8_t* const l = lower + blocks * 8;
    luma_upper[blocks * 2] = luma_of(u[0], u[1], u[2]);
    luma_lower[blocks * 2] = luma_of(l[0], l[1], l[2]);
    luma_upper[blocks * 2 + 1] = kPaddingLuma;
    luma_lower[blocks * 2 + 1] = kPaddingLuma;
    cb[blocks] = chroma_of(kCbR, kCbG, kCbB, u[0] + l[0], u[1] + l[1], u[2] + l[2]);
    cr[blocks] = chroma_of(kCrR, kCrG, kCrB, u[0] + l[0], u[1] + l[1], u[2] + l[2]);
}

}  // namespace

void rgba_to_yuv420(const Image& frame, std::vector<std::uint8_t>& yuv) {
    const int width = frame.width, height = frame.height;
    const int padded_width = even_size(width), padded_height = even_size(height);
    yuv.resize(yuv420_bytes(width, height));
    std::uint8_t* const luma = yuv.data();
    std::uint8_t* const cb = luma + static_cast<std::size_t>(padded_width) * padded_height;
    std::uint8_t* const cr = cb + static_cast<std::size_t>(padded_width / 2) * (padded_height / 2);
    const std::size_t row_bytes = static_cast<std::size_t>(width) * 4;

    for (int top = 0; top < height; top += 2) {
        const std::uint8_t* const upper = frame.rgba.data() + static_cast<std::size_t>(top) * row_bytes;
        std::uint8_t* const luma_upper = luma + static_cast<std::size_t>(top) * padded_width;
        const std::size_t block_row = static_cast<std::size_t>(top / 2) * (padded_width / 2);
        if (top + 1 < height) {
            convert_row_pair(upper, upper + row_bytes, width, luma_upper, luma_upper + padded_width, cb + block_row,
                             cr + block_row);
        } else {
            // An odd height: the padding row below is black, and its Y' is 16 whatever the
            // conversion of black would round to.
            const std::vector<std::uint8_t> black(row_bytes, 0);
            convert_row_pair(upper, black.data(), width, luma_upper, luma_upper + padded_width, cb + block_row,
                             cr + block_row);
            std::fill(luma_upper + padded_width, luma_upper + 2 * padded_width, kPaddingLuma);
        }
    }
}

}  // namespace clr
