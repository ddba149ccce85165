// CLI11's --help layout, but with at least two spaces between an option and its description:
// CLI11 leaves one when the option is one character short of the column, and help2man, which
// makes the man page from --help, then reads the description as part of the option's name.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

namespace clr {

class HelpFormatter : public CLI::Formatter {
public:
    std::string make_option(const CLI::Option* option, bool is_positional) const override;
};

}  // namespace clr
