#include "scene/mtl_texture_maps.h"

#include <algorithm>
#include <vector>

#include "scene/obj_text_checks.h"

namespace clr {
namespace {

// A material's name from its `newmtl` line, as tinyobjloader reads it.
std::string material_name(std::string_view line) {
    std::string name(line.substr(std::min(line.find("newmtl") + 7, line.size())));
    name = name.substr(0, name.find('\0'));
    while (!name.empty() && (name.back() == ' ' || name.back() == '\t')) name.pop_back();
    return name;
}

}  // namespace

std::map<std::string, MtlTextureMap> diffuse_texture_maps(std::string_view text) {
    std::vector<std::pair<std::uint64_t, std::string>> materials;  // each newmtl: its line and name
    for_each_statement(text, "newmtl",
                       [&](std::uint64_t line, std::string_view statement) { materials.emplace_back(line, material_name(statement)); });
    std::map<std::string, MtlTextureMap> maps;
    for_each_statement(text, "map_Kd", [&](std::uint64_t line, std::string_view statement) {
        const auto after = std::upper_bound(materials.begin(), materials.end(), line,
                                            [](std::uint64_t at, const auto& material) { return at < material.first; });
        if (after == materials.begin()) return;  // before the first newmtl: no material's
        maps.emplace(std::prev(after)->second, MtlTextureMap{line, std::string(statement)});  // the first one kept
    });
    return maps;
}

}  // namespace clr
