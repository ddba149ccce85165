// The viewer's writes into --output-dir never replace anything: not a file the user had there,
// not the file a symbolic link points at, not the viewer's own earlier export. A name that is
// taken (by a file, a folder, a link, even a link to nothing) is skipped for the next one of
// the series NAME, NAME-2, NAME-3, ..., as a browser names a download whose name is taken.
// The final rename itself refuses to replace (RENAME_NOREPLACE, or link(2) where the file
// system lacks it), so a file made under the chosen name meanwhile is not replaced either.
// (A video's MP4 is written later by its render, whose own rename replaces: the name is only
// checked to be free when its scene is written.)
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/errors.h"

namespace clr {

// How many names of a series are tried before the write is refused.
constexpr int kMostNameTries = 1000;

struct UnusedNameFile {
    std::string name;  // the series' name that was used: "tour" or "tour-2"
    std::string path;  // FOLDER/NAME + extension
};

// What `check` throws for a name that no file holds but that may not be written all the same
// (an input of the run that need not exist, such as a texture a .mtl names): the series passes
// over it as over a taken one.
class UnusableName : public OutputError {
public:
    using OutputError::OutputError;
};

// Writes `text` to FOLDER/NAME + `extension` for the first NAME of `base`'s series whose file
// does not exist and for which no FOLDER/NAME + e exists for any e of `also_unused` (the
// outputs that will follow under the same name). `check(path)` may pass over a name by
// throwing UnusableName, or refuse the write by throwing anything else. Throws OutputError
// when the file cannot be written, the folder cannot be looked in, or every name is taken.
UnusedNameFile write_under_unused_name(const std::string& folder, const std::string& base, const std::string& extension,
                                       const std::vector<std::string>& also_unused, const std::string& text,
                                       const std::function<void(const std::string& path)>& check);

// The n-th name (from 1) of `base`'s series: "base", "base-2", "base-3", ...
std::string series_name(const std::string& base, int n);

// Whether `path` names a directory entry of any kind (a link is not followed). Throws
// OutputError, naming the folder and the reason, where that cannot be told (the folder is not a
// folder, or may not be searched), or naming the entry where its name is too long.
bool entry_exists(const std::string& path);

}  // namespace clr
