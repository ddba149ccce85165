// The colour textures of a .mtl file's materials: clrender draws a mesh in one colour, its
// material's `Kd` (docs/scene-format.md, Meshes), so a `map_Kd` is read past, and the reader
// warns about it rather than drop the texture in silence.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <string_view>

namespace clr {

// A material's name from its `newmtl` statement: the rest of the line after "newmtl" and a
// blank, up to a NUL (tinyobjloader reads it as a C string), without the blanks around it.
// tinyobjloader keeps the blanks before it ("newmtl  red" defines " red"), but a `usemtl` is
// matched without them, so clrender names the material "red", as the one who wrote it meant.
std::string mtl_material_name(std::string_view statement);

// A name tinyobjloader's LoadMtl keys a material by, as mtl_material_name reads it: without the
// blanks around it.
std::string trimmed_material_name(std::string_view name);

// A material's first `map_Kd` statement: its line (from 1) and its text (the line as written).
struct MtlTextureMap {
    std::uint64_t line = 0;
    std::string statement;
};

// Each material of the .mtl `text` that has a `map_Kd` statement, by its name as `newmtl`
// gives it (mtl_material_name): the first such statement. A `map_Kd` before any `newmtl` belongs to no material.
std::map<std::string, MtlTextureMap> diffuse_texture_maps(std::string_view text);

}  // namespace clr
