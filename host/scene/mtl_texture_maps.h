// The colour textures of a .mtl file's materials: clrender draws a mesh in one colour, its
// material's `Kd` (docs/scene-format.md, Meshes), so a `map_Kd` is read past, and the reader
// warns about it rather than drop the texture in silence.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <string_view>

namespace clr {

// A material's first `map_Kd` statement: its line (from 1) and its text (the line as written).
struct MtlTextureMap {
    std::uint64_t line = 0;
    std::string statement;
};

// Each material of the .mtl `text` that has a `map_Kd` statement, by its name as `newmtl`
// gives it (the rest of the line without trailing blanks, up to a NUL, as tinyobjloader reads
// it): the first such statement. A `map_Kd` before any `newmtl` belongs to no material.
std::map<std::string, MtlTextureMap> diffuse_texture_maps(std::string_view text);

}  // namespace clr
