// The temporary names a clrender process will use next, made first, as another user who may
// write into the output folder could: the names are "<host id>-<pid>-<counter>", the pid is
// public and the counter starts at 0.
#pragma once

#include "support/temp_folder.h"

namespace clr::testing {

// Makes, as empty files in `folder`, the next `count` usual temporary names of this process
// and each with ".log" added (the encoder's log); returns how many files that made.
int take_the_next_usual_temp_names(const TempFolder& folder, int count);

}  // namespace clr::testing
