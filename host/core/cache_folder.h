// Where clrender keeps what it caches across runs (built programs, decoded images): one rule
// for every cache, so that one variable moves or turns off all of them.
#pragma once

#include <string>

namespace clr {

// $CLRENDER_CACHE_DIR when set ("off" or empty: no cache, returns ""), else
// $XDG_CACHE_HOME/clrender, else $HOME/.cache/clrender; "" when none of them is set.
std::string cache_folder_from_environment();

}  // namespace clr
