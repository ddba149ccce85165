// Checks of a JPEG's structure made before stb_image decodes it, for the cases where stb 2.27
// (the version Debian 12 packages) would read or write outside its own tables instead of
// failing. Each throws ImageError naming what is wrong; files stb reads safely pass untouched.
#pragma once

#include <vector>

namespace clr {

// Refuses a Huffman table declaring more than the 256 codes a table can hold (stb wrote them
// past its tables: a heap overflow with bytes from the file).
void check_jpeg_huffman_tables(const std::vector<unsigned char>& bytes);

// Refuses a scan that decodes with a Huffman table no DHT segment before it defined (stb
// then indexes its never-initialised table: out-of-bounds reads of its own arrays).
void check_jpeg_scans_use_defined_tables(const std::vector<unsigned char>& bytes);

}  // namespace clr
