// The checks a Wavefront OBJ file's text must pass before tinyobjloader builds its mesh
// (obj_reader.h). tinyobjloader accepts what clrender must refuse with the file and line:
// it reads "nan" or "1e999" as a number, keeps an index beyond the vertices with only a
// warning, resolves a relative index before the first vertex to a negative one and drops a
// face of one or two corners in silence. This pass reads the lines only as far as those
// checks need; building the mesh stays the library's.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace clr {

// `text` without the UTF-8 byte order mark (EF BB BF) that some editors write at its start:
// it is not part of the first line's keyword. Every function below skips it.
std::string_view without_byte_order_mark(std::string_view text);

// The most corners a face may have: tinyobjloader keeps a face's corner count in a byte, and
// reads a larger polygon as another one.
constexpr std::uint64_t kMaxFaceCorners = 255;

// What the checks counted, for the reader's limits and its consistency check.
struct ObjTextCounts {
    std::uint64_t positions = 0;  // `v` lines
    std::uint64_t normals = 0;    // `vn` lines
    std::uint64_t texcoords = 0;  // `vt` lines
    std::uint64_t faces = 0;      // `f` lines
    std::uint64_t triangles = 0;  // a face of n corners fans into n - 2
    // `o`, `g`, `usemtl` and `mtllib` lines: each may start a shape of tinyobjloader's or name a
    // material or a .mtl file, memory beside the triangles' (obj_reader.h, kStatementBytes).
    std::uint64_t named_statements = 0;
    // The bytes of the `o`, `g`, `s`, `usemtl` and `mtllib` lines: the names and groups they hold
    // are copied several times over (obj_reader.h, kStatementTextBytes), which a long one shows.
    std::uint64_t grouping_statement_bytes = 0;
    // Lines whose first word is no OBJ statement ("V", a typo, or a `v` line behind the byte
    // order mark of a file joined on, "\xEF\xBB\xBFv"), which tinyobjloader skips in silence:
    // a position skipped so shifts the corners of every face after it. The first one's line
    // (from 1; 0 for none) and word.
    std::uint64_t unknown_statements = 0;
    std::uint64_t first_unknown_line = 0;
    std::string first_unknown_keyword;
    // `v` lines with more than four numbers: a vertex colour after the position
    // (`v x y z r g b`, as MeshLab and photogrammetry tools write it), which no mesh draws (a
    // mesh takes one colour). The first one's line (from 1; 0 for none).
    std::uint64_t coloured_positions = 0;
    std::uint64_t first_coloured_line = 0;
};

// A line the checks refuse: its number (from 1) and why, in a user's terms.
struct ObjTextProblem {
    std::uint64_t line = 0;
    std::string detail;
};

// Checks every `v`, `vn`, `vt` and `f` line of `text` (up to a '#' at the start of a word,
// which starts a comment: one inside a word, "1.#INF", is part of the number; numbers and
// indices may carry a '+' sign): coordinates are finite numbers within
// clrender's coordinate range, of at most 64 characters and a decimal exponent of at most 300
// in magnitude (beyond which tinyobjloader's arithmetic overflows); a face has from three to
// kMaxFaceCorners corners, each naming a position (and optionally a texture coordinate and a
// normal) by a non-zero index, counted from the start (1 is the first) or, negative, back
// from the latest one before the face, that names an entry of the file. Stops at the first
// problem. Also stops when the faces fan into more than `max_triangles` triangles (the memory
// budget). Other lines (`o`, `g`, `s`, `usemtl`, `mtllib`, comments, unknown commands) are
// the library's.
// Returns the counts; sets `problem` (line 0: none) to the first problem found.
ObjTextCounts check_obj_text(std::string_view text, std::uint64_t max_triangles, ObjTextProblem& problem);

// The largest magnitude of a material's colour component: colours outside [0, 1] are kept as a
// scene's are (docs/scene-format.md), but must stay far from float's overflow.
constexpr double kMaxMaterialColor = 1e6;

// Checks every `Kd` line of a .mtl text: exactly three numbers (the forms "Kd spectral" and
// "Kd xyz", and a lone r that the format repeats for g and b, are refused rather than read as
// tinyobjloader reads them), finite, within the limits of check_obj_text's numbers and within
// kMaxMaterialColor. Returns the first problem (line 0: none).
ObjTextProblem check_mtl_text(std::string_view text);

// The line (from 1; 0 for none) of the first `Kd` statement of the .mtl `text` before its first
// `newmtl`: a colour of no material, which tinyobjloader drops in silence (the mesh came out
// grey where its author had meant that colour). A file without a `newmtl` has none: tinyobjloader
// keeps its colour as a nameless material's, which faces without a `usemtl` take.
std::uint64_t first_colour_without_material(std::string_view text);

// Calls `visit(line_number, keyword, line)` for each line of `text` that has a first word.
void for_each_keyword(std::string_view text,
                      const std::function<void(std::uint64_t, std::string_view, std::string_view)>& visit);

// Calls `visit(line_number, line)` for each line of `text` whose first word is `keyword`.
void for_each_statement(std::string_view text, std::string_view keyword,
                        const std::function<void(std::uint64_t, std::string_view)>& visit);

// `text` with only the statements clrender uses kept for tinyobjloader (`v`, `vn`, `vt`, `f`,
// `o`, `g`, `s`); every other line (comments, lines, points, skin weights,
// tags, curves) is left empty, so that lines keep their numbers and the library never parses
// what clrender ignores (its `vw` parser turns an out-of-range number into an int, undefined
// behaviour); a comment after the numbers of a `v`, `vn`, `vt`, `f` or `Kd` line is cut.
// Every line ends in "\n".
std::string obj_statements_used(std::string_view text);

// The same for a .mtl file: only `newmtl` and `Kd`, the diffuse colour that clrender reads.
std::string mtl_statements_used(std::string_view text);

// A .mtl file an OBJ names: the name as its `mtllib` statement writes it, and the line (from 1)
// of the first statement naming it, which a problem reading the file names.
struct ObjLibraryName {
    std::string name;
    std::uint64_t line = 0;
};

// What the OBJ `text` says of materials, read in one pass:
struct ObjMaterialStatements {
    // The .mtl files it names: every name of every `mtllib` statement, in the file's order, as
    // tinyobjloader cuts a statement into names (the text after "mtllib" and one blank, cut at
    // spaces; a backslash keeps the next character, so "a\ b.mtl" is one name). clrender reads
    // them all before the faces, so a `usemtl` finds a material whichever line names its file
    // (tinyobjloader itself reads only the first name of a statement that it can read, and a
    // `usemtl` only among the files named above it).
    std::vector<ObjLibraryName> libraries;  // each name once, where it first appears
    // Each material that `usemtl` statements use, once, in the order of first use: its name (the
    // statement's first word, as tinyobjloader reads it), the whole name (the rest of the
    // statement, blanks around it left out: "my mat" of `usemtl my mat # note`, which a
    // `newmtl my mat` defines), the line of its first use and how many lines use it.
    struct Use {
        std::string name;
        std::string whole;
        std::uint64_t first_line = 0;
        std::uint64_t lines = 0;
    };
    std::vector<Use> uses;
    // The material of the first face: the name and whole name of the last `usemtl` before the
    // first `f` line ("" where there is none).
    std::string first_face_material;
    std::string first_face_whole;
};
// Whether a file (or any entry) of the OBJ's folder has `name`, as an `mtllib` statement writes
// it: a line whose whole rest names one names that file (obj_reader.cpp gives the lookup).
using LibraryFileExists = std::function<bool(const std::string& name)>;

// With `exists`, an `mtllib` line that cuts into several names while the whole rest of it (the
// blanks around it left out) names a file names that one file: "mtllib My Model.mtl", as Blender
// writes the .mtl of a model saved as "My Model.obj", and as other readers take it (three.js,
// Assimp). Cut, it named "My", which is no file: the model was refused.
ObjMaterialStatements material_statements(std::string_view text, const LibraryFileExists& exists = {});

// Calls `visit(line_number, name)` for each name of each `mtllib` statement of `text`, as
// material_statements cuts them, repeated ones included, one at a time: a text that fails its
// checks has had no memory estimate, and may name millions. Stops when `visit` returns false.
void for_each_library_name(std::string_view text, const std::function<bool(std::uint64_t, std::string)>& visit,
                           const LibraryFileExists& exists = {});

}  // namespace clr
