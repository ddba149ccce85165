#include "scene/jpeg_checks.h"

#include <cstddef>
#include <string>

#include "scene/image_loader.h"  // ImageError

namespace clr {

// stb_image 2.27, the version Debian 12 packages, trusts the code counts of a JPEG Huffman
// table: counts that add up to more than 256 make it write past its 256-entry tables, a
// heap overflow with bytes taken from the file (nothings/stb issue #1289, fixed upstream
// after 2.27; found here by fuzz/image_fuzzer.cpp). The JPEG standard allows at most 256
// codes a table, so such a file is corrupt and is refused before stb sees it.
//
// Rather than follow the file's segments as stb does (and risk disagreeing with it on where
// they are), every FF C4 (DHT) marker byte pair is taken as the start of a DHT segment: stb
// reads a table only right after one, and in entropy-coded data an FF byte is always
// followed by 00 or a marker, so real tables are never missed. Each table is the table
// class/id byte, 16 code counts and the codes; the next one starts right after it, so a
// position needs checking only once however many candidate segments reach it.
void check_jpeg_huffman_tables(const std::vector<unsigned char>& bytes) {
    const auto byte_at = [&](std::size_t i) -> unsigned { return i < bytes.size() ? bytes[i] : 0; };  // as stb
    std::vector<bool> checked(bytes.size(), false);
    for (std::size_t marker = 0; marker + 1 < bytes.size(); ++marker) {
        if (bytes[marker] != 0xFF || bytes[marker + 1] != 0xC4) continue;
        // Tables follow the marker and the segment's 2-byte length. The length is ignored,
        // which can only check more tables than stb reads, never fewer.
        for (std::size_t table = marker + 4; table < bytes.size() && !checked[table];) {
            checked[table] = true;
            const unsigned class_and_id = bytes[table];
            if ((class_and_id >> 4) > 1 || (class_and_id & 15) > 3) break;  // stb rejects the file here
            unsigned codes = 0;
            for (std::size_t length = 1; length <= 16; ++length) codes += byte_at(table + length);
            if (codes > 256) {
                throw ImageError("corrupt JPEG: a Huffman table declares " + std::to_string(codes) +
                                 " codes, more than the 256 a table can hold");
            }
            table += 17 + codes;
        }
    }
}

// stb 2.27 allocates its decoder without clearing it, and a scan may name any of the four DC
// and four AC tables whether or not a DHT segment defined it; decoding with an undefined one
// indexes its tables with garbage (found by fuzz/image_fuzzer.cpp: UndefinedBehaviorSanitizer,
// index out of bounds in stbi__jpeg_huff_decode). The file's segments are followed the way stb
// follows them: markers (an FF, fill FFs, the marker byte) with their lengths, and after a
// scan's header its entropy-coded data up to the next marker (FF followed by anything but 00,
// a restart marker or another FF). Before the frame header stb skips stray bytes between
// segments; the check refuses them instead, because past them it could no longer be sure
// where stb finds its segments. Where the walk meets anything else stb refuses, it stops and
// leaves the verdict to stb. A scan needs, as stb decodes it, both tables in a baseline file;
// in a progressive one the DC table for a first DC scan and the AC table for an AC scan.
void check_jpeg_scans_use_defined_tables(const std::vector<unsigned char>& bytes) {
    const std::size_t size = bytes.size();
    const auto byte_at = [&](std::size_t i) -> unsigned { return i < size ? bytes[i] : 0; };
    bool defined[2][4] = {};  // [0: DC, 1: AC][table id]
    bool seen_frame = false, progressive = false;
    std::size_t at = 2;  // after the start-of-image marker
    while (at + 1 < size) {
        if (bytes[at] != 0xFF) {
            if (seen_frame) return;  // stb expects a marker here and fails
            throw ImageError("corrupt JPEG: stray bytes between segments at byte " + std::to_string(at));
        }
        while (at < size && bytes[at] == 0xFF) ++at;  // fill bytes
        if (at >= size) return;
        const unsigned marker = bytes[at++];
        if (marker == 0xD9 || marker == 0x00 || marker == 0x01 || (marker >= 0xD0 && marker <= 0xD8)) return;
        const std::size_t length = byte_at(at) << 8 | byte_at(at + 1);
        if (length < 2 || at + length > size) return;
        const std::size_t body = at + 2, end = at + length;
        if (marker == 0xC0 || marker == 0xC1 || marker == 0xC2) {
            if (seen_frame) return;  // stb refuses a second frame header
            seen_frame = true;
            progressive = marker == 0xC2;
        } else if (marker == 0xC4) {
            for (std::size_t table = body; table < end;) {
                const unsigned kind = bytes[table] >> 4, id = bytes[table] & 15;
                if (kind > 1 || id > 3) return;
                std::size_t codes = 0;
                for (std::size_t length_index = 1; length_index <= 16; ++length_index) codes += byte_at(table + length_index);
                defined[kind][id] = true;
                table += 17 + codes;
            }
        } else if (marker == 0xDA) {
            if (!seen_frame) return;  // stb refuses a scan before the frame header
            const unsigned components = byte_at(body);
            const unsigned spectral_start = byte_at(body + 1 + 2 * components);
            const unsigned approximation_high = byte_at(body + 3 + 2 * components) >> 4;
            const bool needs_dc = !progressive || (spectral_start == 0 && approximation_high == 0);
            const bool needs_ac = !progressive || spectral_start > 0;
            for (unsigned c = 0; c < components; ++c) {
                const unsigned tables = byte_at(body + 2 + 2 * c);
                const unsigned dc = tables >> 4, ac = tables & 15;
                if (dc > 3 || ac > 3) return;  // stb refuses the scan
                const bool dc_missing = needs_dc && !defined[0][dc];
                if (dc_missing || (needs_ac && !defined[1][ac]))
                    throw ImageError("corrupt JPEG: a scan decodes with " + std::string(dc_missing ? "DC" : "AC") +
                                     " Huffman table " + std::to_string(dc_missing ? dc : ac) +
                                     ", which no table definition (DHT) before it gives");
            }
            // The entropy-coded data runs to the next marker.
            at = end;
            while (at + 1 < size && !(bytes[at] == 0xFF && bytes[at + 1] != 0x00 && bytes[at + 1] != 0xFF &&
                                      !(bytes[at + 1] >= 0xD0 && bytes[at + 1] <= 0xD7)))
                ++at;
            continue;
        }
        at = end;
    }
}

}  // namespace clr
