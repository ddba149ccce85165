// Reads a Wavefront OBJ file into triangles: the meshes a scene's `obj` objects name
// (docs/scene-format.md). tinyobjloader (Debian's libtinyobjloader-dev) parses the file and
// its .mtl; clrender's own checks come first (obj_text_checks.h) so that a bad file is
// refused with its line, never read half-right. Faces of more than three corners are fanned
// from their first corner, as the scene format defines.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "core/sha256.h"
#include "core/vec3.h"

namespace clr {

// Why an OBJ file could not be read, in one line ("line 12: corner 2: position index 9 is out
// of range: the file has 8"). The scene loader adds the scene file and JSON location.
class ObjError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
    // Every .mtl file the OBJ names, as paths, each file once, whichever line it failed at: they
    // stay inputs of the run (never replaced by an output) even when a placeholder stands in for
    // the mesh.
    std::vector<std::string> material_files;
    // Why `material_files` could not hold every file the OBJ names ("" when it does): a
    // placeholder cannot stand in for such a model, whose files the run could not all keep safe.
    std::string material_files_incomplete;
};

// Thrown where reading a mesh would take more memory than it may (parse_obj's budget): an
// exit 6 of the run, not a file that a placeholder may stand in for.
class MeshMemoryError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// What parsing a mesh takes a triangle, as measured (docs/robustness.md, Memory): the peak of
// `clrender --check` on terrains of 1M and 2M triangles grew by 240 MB a million, besides the
// text; a margin on top.
constexpr std::uint64_t kParsedTriangleBytes = 300;
// What an `o`, `g`, `usemtl` or `mtllib` line may take: tinyobjloader makes a shape (a name and
// several arrays) at each `o` or `g`, which for a file of one face per object took about 230
// bytes a triangle besides the 300; a material name is kept once. A margin on top. The text
// counts twice: the checks read it, tinyobjloader its copy without the lines it must not see.
constexpr std::uint64_t kStatementBytes = 512;
// What each byte of an `o`, `g`, `s`, `usemtl` or `mtllib` line may take besides twice the text:
// its names are copied several times over (clrender's lists of material and .mtl names,
// tinyobjloader's shape names, each word a string of its own). A 100 MB line peaked, text
// included, at 1.55 GB (`usemtl name`), 1.48 GB (`mtllib name`), 0.63 GB (`g name`), 0.33 GB
// (`s name`), and of one-letter words at 2.43 GB (`g a a ...`) and 2.21 GB (`mtllib a a ...`):
// 22 bytes a byte besides twice the text. A margin on top.
constexpr std::uint64_t kStatementTextBytes = 28;
// What a `v`, `vt` or `vn` line may take besides twice its text: tinyobjloader keeps its
// numbers as doubles (and a weight for each `v`), and clrender a copy of each position and
// normal. A file of such lines and one face (a point cloud, a scan) took, text included, 61
// bytes a `v 0 0 0` line, 63 a `vn 0 0 1` and 31 a `vt 0 0` (48 MiB of them: 380 MB where
// twice the text had been counted). A margin on top.
constexpr std::uint64_t kVertexLineBytes = 64;

// Largest OBJ file and largest .mtl file read, and most triangles a file may fan into: a
// triangle costs the reader about 48 bytes (three position and three normal indices) besides
// its vertices, so the limit keeps one mesh's indices under 1 GiB.
constexpr std::uint64_t kMaxObjFileBytes = std::uint64_t(1) << 30;
constexpr std::uint64_t kMaxMtlFileBytes = std::uint64_t(16) << 20;
constexpr std::uint64_t kMaxObjTriangles = std::uint64_t(1) << 24;
// Most materials the .mtl files of one OBJ may define together, and most .mtl files it may
// read: tinyobjloader keeps about 3 KB a material, so 16 MiB of `newmtl a` lines took 5.6 GB.
constexpr std::uint64_t kMaxObjMaterials = 10000;
constexpr std::uint64_t kMaxMtlFiles = 1024;
// Most bytes of distinct `mtllib` names that the list of a failed OBJ's .mtl files looks at
// (ObjError::material_files): each name is one stat() of its file, and a file that fails its
// checks has had no memory estimate. 131,072 spellings of one .mtl take 8.5 MB.
constexpr std::uint64_t kMaxMtlNameBytes = std::uint64_t(64) << 20;

struct ObjMesh {
    std::vector<Vec3> positions;  // as the file gives them, in its order
    std::vector<Vec3> normals;
    // Three corners a triangle, counter-clockwise as the face lists them: indices into
    // `positions`, and into `normals` where every corner of the face names a normal (-1
    // otherwise: the renderer uses the geometric normal).
    std::vector<std::array<std::uint32_t, 3>> triangles;
    std::vector<std::array<std::int32_t, 3>> triangle_normals;
    // The diffuse colour (`Kd`) of the material the first face uses, when its .mtl gives one.
    std::optional<Vec3> diffuse;
    std::uint64_t faces = 0;  // polygons in the file
    std::vector<std::string> material_files;  // the .mtl files read, as paths
    std::vector<Sha256Digest> material_digests;  // the SHA-256 of each, as read
    // What the file asks for that cannot be done, each one line ("line 7: usemtl red: no .mtl
    // file of the OBJ defines this material; ..."): the scene's warnings at its "filename".
    std::vector<std::string> warnings;
};

// Reads the OBJ at `path` (a regular file; `mtllib` names are relative to its folder, and a
// missing or unreadable .mtl is an error too). Throws ObjError with a one-line reason:
// missing, not a regular file, too large, a bad line (with its number), too many triangles.
// Throws MeshMemoryError, before the parse, when twice the text, its triangles at
// kParsedTriangleBytes each, its `o`, `g`, `usemtl` and `mtllib` lines at kStatementBytes
// each (and those and its `s` lines at kStatementTextBytes a byte) and its `v`, `vt` and `vn`
// lines at kVertexLineBytes each would take more than `memory_budget` bytes; std::bad_alloc
// when memory runs out all the same.
ObjMesh read_obj(const std::string& path, std::uint64_t memory_budget = std::numeric_limits<std::uint64_t>::max());

class MtlLibrary;
struct MtlMaterials;

// The image files the texture statements of a .mtl text name (`map_Kd`, `map_Ks`, `bump`, `norm`,
// ... every one tinyobjloader's LoadMtl reads), each as the file writes it, in the order of their
// first statement: the name LoadMtl keeps for each kind of texture of each material (its last
// such statement; "map_Kd -s 1 1 1 wood.png" names "wood.png"). clrender draws none of them, but
// they are the model's files, which no output may replace. Materials past kMaxObjMaterials
// (a file that is refused) add none: `cut`, when given, says whether any of them names one.
std::vector<std::string> mtl_texture_files(std::string_view text, bool* cut = nullptr);

// The materials of a .mtl's used statements (mtl_statements_used) as tinyobjloader's LoadMtl
// reads them, with the `newmtl` statements that define a name again; `problem` says where the
// library and clrender's own reading disagree on the count ("" where they agree).
MtlMaterials read_mtl_materials(const std::string& used, std::string& problem);

// The same for the file's content already read; `path` names the file in messages and
// locates its .mtl files, which `library` reads (the scene's, shared by its OBJ files), or
// one of this parse's own.
ObjMesh parse_obj(const std::string& text, const std::string& path,
                  std::uint64_t memory_budget = std::numeric_limits<std::uint64_t>::max(), MtlLibrary* library = nullptr);

// The whole text of the OBJ at `path`, with read_obj's limits; ObjError when it cannot be read.
std::string read_obj_text(const std::string& path);

}  // namespace clr
