// The .mtl files that the OBJ files of one scene name, each read and checked once: a scene
// exported one OBJ file per object names one shared library from each, and every OBJ read it
// whole again (100 OBJ files naming one 16 MiB .mtl took 10 s to load, each run).
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "core/sha256.h"
#include "core/vec3.h"
#include "scene/mtl_statement_case.h"
#include "scene/mtl_texture_maps.h"

namespace clr {

// A material as tinyobjloader's LoadMtl lists it, of a .mtl text alone.
struct MtlMaterial {
    Vec3 diffuse{};              // its Kd (0 where none is given)
    bool gives_diffuse = false;  // a Kd line gives it one (an unset Kd is 0, as a black one)
};

// A named `newmtl` statement of a .mtl, as the warning about materials defined again reads it.
struct MtlDefinition {
    std::uint64_t line = 0;
    std::string name;
};

// What an OBJ needs of the materials of one .mtl file, made once for all the OBJ files that name
// it: LoadMtl of a library of 10,000 materials took 27 ms, for each OBJ file of a scene exported
// one OBJ file per object (500 of them: 13.5 s). The OBJ reader combines the files an OBJ names
// as LoadMtl would have filled its list: in order, a name's first definition kept.
struct MtlMaterials {
    std::size_t count = 0;  // the file's materials; `list` is left empty for more than an OBJ may have
    std::vector<MtlMaterial> list;                       // in LoadMtl's order
    std::unordered_map<std::string, std::size_t> first;  // each name LoadMtl keys: its first in `list`
    std::vector<MtlDefinition> definitions;              // in the file's order
    std::unordered_set<std::string> defined;             // the names of `definitions`
    std::uint64_t defined_again = 0;  // the definitions of a name that an earlier line defines
    std::size_t first_again = 0;      // the first of them, where there is one
};

// What an OBJ reader needs of one .mtl file, as the file read.
struct MtlFileRead {
    bool read = false;    // its bytes were read: `digest` is theirs
    std::string problem;  // why its materials cannot be used ("" when they can), without its name
    Sha256Digest digest{};
    MtlMaterials materials;  // of its statements that clrender uses (mtl_statements_used)
    std::map<std::string, MtlTextureMap> texture_maps;  // diffuse_texture_maps of the whole text
    // mtl_texture_files of the whole text, for any file read (also one whose materials cannot be
    // used): the files it names as textures, as written (relative to its folder, or absolute).
    std::vector<std::string> texture_files;
    // Whether a texture statement of a material past kMaxObjMaterials is left out of
    // `texture_files`: the list is not every texture of the file.
    bool texture_files_cut = false;
    MtlMiscasedStatement miscased;                      // first_miscased_statement of the whole text
    std::uint64_t colour_without_material = 0;          // first_colour_without_material of the text
};

class MtlLibrary {
public:
    // Most bytes the files a library reads may take together (bytes_held in mtl_library.cpp):
    // every file is kept once read, for the whole scene. A file not kept was read and parsed
    // again by each OBJ naming it: 30 small OBJ files naming a 16 MiB .mtl of 10,000 long
    // material names (70 MB held, past a 64 MiB bound) took 11 s, 1,000 would take minutes.
    static constexpr std::uint64_t kMostHeldBytes = std::uint64_t(1) << 30;

    explicit MtlLibrary(std::uint64_t most_held_bytes = kMostHeldBytes) : most_held_bytes_(most_held_bytes) {}

    // The .mtl at `path` as read, by its identity (device and inode) where `stat` gives one:
    // read and checked at the first call for a file, kept for the later ones. Throws
    // MeshMemoryError (obj_reader.h), naming the file, where keeping it would take the files
    // kept past the library's bound.
    std::shared_ptr<const MtlFileRead> read(const std::string& path);

    // How many times a file was read and parsed: once per file a scene names, however many OBJ
    // files name it (a name stat() cannot follow, which names no file, is tried each time).
    std::uint64_t files_parsed() const { return files_parsed_; }

private:
    std::map<std::pair<dev_t, ino_t>, std::shared_ptr<const MtlFileRead>> kept_;
    std::uint64_t kept_bytes_ = 0;
    std::uint64_t most_held_bytes_;
    std::uint64_t files_parsed_ = 0;
};

}  // namespace clr
