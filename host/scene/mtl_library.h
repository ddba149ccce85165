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
};

class MtlLibrary {
public:
    // Files whose materials together take more than this are read again by each OBJ that names
    // them rather than kept: what the library keeps stays a fraction of a scene's meshes.
    static constexpr std::uint64_t kMostKeptBytes = std::uint64_t(64) << 20;

    // The .mtl at `path` as read, by its identity (device and inode) where `stat` gives one:
    // read and checked at the first call for a file, kept for the later ones. Shared: an OBJ
    // holds each of its files' reads while it is read, also one that is not kept.
    std::shared_ptr<const MtlFileRead> read(const std::string& path);

private:
    std::map<std::pair<dev_t, ino_t>, std::shared_ptr<const MtlFileRead>> kept_;
    std::uint64_t kept_bytes_ = 0;
};

}  // namespace clr
