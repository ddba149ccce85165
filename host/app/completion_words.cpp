#include "app/completion_words.h"

#include <CLI/CLI.hpp>
#include <sstream>
#include <string>
#include <vector>

namespace clr {

std::string completion_words(const CLI::App& app) {
    std::ostringstream out;
    for (const CLI::Option* option : app.get_options()) {
        if (!option->nonpositional() || option->get_group().empty()) continue;
        const bool takes_value = option->get_items_expected_max() > 0;  // flags expect none
        std::vector<std::string> names;
        for (const std::string& name : option->get_snames()) names.push_back("-" + name);
        for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
        for (const std::string& name : names) {
            out << name;
            if (takes_value) out << ' ' << option->get_type_name();
            out << '\n';
        }
    }
    return out.str();
}

}  // namespace clr
