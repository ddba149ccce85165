#include "scene/mtl_statement_case.h"

#include <array>
#include <cctype>

#include "scene/obj_text_checks.h"

namespace clr {
namespace {

bool equal_but_for_case(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i])))
            return false;
    return true;
}

}  // namespace

MtlMiscasedStatement first_miscased_statement(std::string_view text) {
    constexpr std::array<std::string_view, 3> kStatementsRead{"newmtl", "Kd", "map_Kd"};
    MtlMiscasedStatement first;
    for_each_keyword(text, [&](std::uint64_t line, std::string_view keyword, std::string_view) {
        for (const std::string_view statement : kStatementsRead) {
            if (keyword == statement || !equal_but_for_case(keyword, statement)) continue;
            if (first.line != 0) {
                ++first.more;
                return;
            }
            first = {line, std::string(keyword), std::string(statement), 0};
            return;
        }
    });
    return first;
}

}  // namespace clr
