// What the bash completion (packaging/bash-completion/clrender) asks the binary for with the
// hidden --completion-words: every visible option and the kind of value it takes, so that an
// option added to the parser completes without editing the completion script.
#pragma once

#include <string>

namespace CLI {
class App;
}

namespace clr {

// One line per option name: the name, then CLI11's type name when it takes a value ("TEXT",
// "INT:INT in [1 - 4096]", "TEXT:{float,double}"); nothing after a flag's name. Positionals
// and hidden options are left out.
std::string completion_words(const CLI::App& app);

}  // namespace clr
