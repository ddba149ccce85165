// How a scene's file names (images, OBJ meshes) become the paths read: relative to the scene's
// folder, "." steps dropped so that "./a.png" and "a.png" are one file; a name with a ".." step
// kept as written, for the system to resolve (through a symbolic link "x", "x/../a.png" is not
// "a.png", and the file read must be the one every other program opens).
#pragma once

#include <filesystem>
#include <string>

namespace clr {

std::string path_in_folder(const std::filesystem::path& folder, const std::filesystem::path& name);

}  // namespace clr
