#include "app/help_formatter.h"

#include <sstream>

namespace clr {

std::string HelpFormatter::make_option(const CLI::Option* option, bool is_positional) const {
    const std::string name = "  " + make_option_name(option, is_positional) + make_option_opts(option);
    const std::string description = make_option_desc(option);
    const std::size_t width = get_column_width();
    std::ostringstream out;
    out << name;
    if (!description.empty()) {
        if (name.size() + 2 > width)
            out << "\n" << std::string(width, ' ');
        else
            out << std::string(width - name.size(), ' ');
        for (char c : description) {
            out.put(c);
            if (c == '\n') out << std::string(width, ' ');
        }
    }
    out << "\n";
    return out.str();
}

}  // namespace clr
