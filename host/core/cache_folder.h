// Where clrender keeps what it caches across runs (built programs, decoded images): one rule
// for every cache, so that one variable moves or turns off all of them; and the one way a cache
// gets its own sub-folder there, so that no cache can be turned against its user.
#pragma once

#include <string>

namespace clr {

// $CLRENDER_CACHE_DIR when set ("off" or empty: no cache, returns ""), else
// $XDG_CACHE_HOME/clrender, else $HOME/.cache/clrender; "" when none of them is set.
std::string cache_folder_from_environment();

// `root`/`name` ready for a cache's entries, with `create`: creating what is missing (the root
// and the sub-folder with mode 0700, so that other users can neither read nor plant entries),
// without: "" when it is missing. "" too when
// caching there would not be safe or cannot work, which just means no caching:
// - the root is not a folder (a file, a dangling link), cannot be created, or is not owned by
//   this user or is writable by others (the root may be a symlink to a folder that passes this:
//   users move caches that way);
// - the sub-folder is not a real folder (a symlink, a file), not owned by this user, or
//   writable by others.
// A root "" (caching off) gives "".
std::string usable_cache_subfolder(const std::string& root, const std::string& name, bool create);

}  // namespace clr
