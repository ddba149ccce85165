#include "support/png_header.h"

namespace clr::testing {
namespace {

std::uint32_t crc32(const std::string& bytes) {
    std::uint32_t crc = 0xFFFFFFFFu;
    for (unsigned char byte : bytes) {
        crc ^= byte;
        for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

std::string big_endian(std::uint32_t value) {
    return {char(value >> 24), char(value >> 16), char(value >> 8), char(value)};
}

}  // namespace

std::string png_header_only(std::uint32_t width, std::uint32_t height, int bit_depth) {
    const std::string ihdr = "IHDR" + big_endian(width) + big_endian(height) + char(bit_depth) + char(6) + '\0' + '\0' + '\0';
    return std::string("\x89PNG\r\n\x1A\n", 8) + big_endian(13) + ihdr + big_endian(crc32(ihdr));
}

}  // namespace clr::testing
