// Scene values set on the command line, `-D key=value`: applied to the parsed document
// before it is validated, so that the loader checks them as it checks the file's own values
// (docs/command-line.md, Scene overrides).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "scene/json_reader.h"

namespace clr {

struct SceneOverride {
    std::string argument;  // as given: "spheres.0.radius=2", for messages
    std::vector<std::string> path;  // the key's reference tokens: {"spheres", "0", "radius"}
    Json value;
    // Warnings about the value ("/clrender/spp: duplicate key ..."), for the scene's warnings.
    std::vector<std::string> warnings = {};
};

// Reads one -D argument. The key is a JSON pointer ("/spheres/0/radius", RFC 6901) or a
// dotted path ("spheres.0.radius"); the value is JSON when it parses as JSON ("2", "[0, 0, 5]",
// "true", "\"a.png\""), else the text itself as a string ("tex.png"). Throws UsageError for
// an argument without '=' or with an empty key, a number too large for a double (1e400) and
// a value that starts as a JSON array or object but is not JSON ("[0, 0"), naming where.
SceneOverride parse_scene_override(const std::string& argument);

// Sets each override's value in `document`, in order; an object on the way that is missing
// is made (so "clrender.spp=4" works in a scene without "clrender"). Returns, for each, its
// JSON pointer and argument (Diagnostics::overridden). Throws UsageError, naming the
// argument, for a path through a value that is not an object or array, or to an array
// element that does not exist ("-" appends one, as in JSON Patch).
std::vector<std::pair<std::string, std::string>> apply_scene_overrides(Json& document,
                                                                      const std::vector<SceneOverride>& overrides);

}  // namespace clr
