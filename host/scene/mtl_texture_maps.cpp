#include "scene/mtl_texture_maps.h"

#include <algorithm>
#include <vector>

#include "scene/obj_text_checks.h"

namespace clr {

std::string trimmed_material_name(std::string_view name) {
    const auto blank = [](char c) { return c == ' ' || c == '\t'; };
    std::size_t at = 0, end = name.size();
    while (at < end && blank(name[at])) ++at;
    while (end > at && blank(name[end - 1])) --end;
    return std::string(name.substr(at, end - at));
}

std::string mtl_material_name(std::string_view statement) {
    const std::size_t at = std::min(statement.find("newmtl") + 7, statement.size());
    return trimmed_material_name(statement.substr(at, statement.find('\0', at) - at));
}

std::map<std::string, MtlTextureMap> diffuse_texture_maps(std::string_view text) {
    std::vector<std::pair<std::uint64_t, std::string>> materials;  // each newmtl: its line and name
    for_each_statement(text, "newmtl", [&](std::uint64_t line, std::string_view statement) {
        materials.emplace_back(line, mtl_material_name(statement));
    });
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
