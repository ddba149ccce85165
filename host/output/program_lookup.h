// Finding a helper program as a shell would: a name with a '/' is a path, a bare name is
// looked up in the folders of $PATH.
#pragma once

#include <optional>
#include <string>

namespace clr {

bool is_executable_file(const std::string& path);

// The first executable `name` in the folders of $PATH (an empty entry is the current folder).
std::optional<std::string> search_path(const std::string& name);

// `name` itself when it contains a '/' and is executable, else search_path(name).
std::optional<std::string> resolve_program(const std::string& name);

}  // namespace clr
