// OBJ texts for tests that need a file of some size: the reader's and the mesh cache's.
#pragma once

#include <string>

namespace clr::testing {

// A flat grid of `cells` x `cells` quads, two triangles each (the first of a quad with corner
// normals, the second without), in material "green" of "grid.mtl" (mtllib and usemtl lines):
// over a MiB of text from 160 cells on.
std::string grid_obj_text(int cells);

}  // namespace clr::testing
