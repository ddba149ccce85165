// The .mtl statements clrender reads (`newmtl`, `Kd`, and `map_Kd`, which it warns about),
// written in another case: tinyobjloader matches a statement's word case for case and skips
// "KD 1 0 0" or "Newmtl red" in silence, so the mesh was drawn grey, or its material undefined,
// with nothing said. The OBJ reader warns about the first such line of each .mtl it uses.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace clr {

// The first line of a .mtl whose first word is one of those statements in another case.
struct MtlMiscasedStatement {
    std::uint64_t line = 0;  // from 1; 0: the file has none
    std::string written;     // its first word as written
    std::string meant;       // the statement it is but for case
    std::uint64_t more = 0;  // later such lines
};

MtlMiscasedStatement first_miscased_statement(std::string_view text);

}  // namespace clr
