// How a scene's file names (images, OBJ meshes) become the paths read: relative to the scene's
// folder, "." steps dropped so that "./a.png" and "a.png" are one file; a name with a ".." step
// kept as written, for the system to resolve (through a symbolic link "x", "x/../a.png" is not
// "a.png", and the file read must be the one every other program opens).
#pragma once

#include <sys/types.h>

#include <filesystem>
#include <string>
#include <tuple>

namespace clr {

std::string path_in_folder(const std::filesystem::path& folder, const std::filesystem::path& name);

// A file as what its read depends on: its identity (device and inode) and that of the folder
// its relative names start from (an OBJ's `mtllib` names, a .mtl's textures), each as the name
// reaches it. "m.obj", "d/../m.obj" and a link beside m.obj are one file; a link from another
// folder reads its relative names from there, so it is another. A name stat() cannot follow
// keeps its own key (the name itself).
using FileInFolderKey = std::tuple<dev_t, ino_t, dev_t, ino_t, std::string>;
FileInFolderKey file_in_folder_key(const std::string& path);

}  // namespace clr
