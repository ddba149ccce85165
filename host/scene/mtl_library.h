// The .mtl files that the OBJ files of one scene name, each read and checked once: a scene
// exported one OBJ file per object names one shared library from each, and every OBJ read it
// whole again (100 OBJ files naming one 16 MiB .mtl took 10 s to load, each run).
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <map>
#include <string>
#include <utility>

#include "core/sha256.h"
#include "scene/mtl_texture_maps.h"

namespace clr {

// What an OBJ reader needs of one .mtl file, as the file read.
struct MtlFileRead {
    bool read = false;    // its bytes were read: `digest` is theirs
    std::string problem;  // why its materials cannot be used ("" when they can), without its name
    Sha256Digest digest{};
    std::string used;  // its statements that clrender uses (mtl_statements_used)
    std::map<std::string, MtlTextureMap> texture_maps;  // diffuse_texture_maps of the whole text
};

class MtlLibrary {
public:
    // Files whose used statements together pass this are read again by each OBJ that names
    // them rather than kept: what the library keeps stays a fraction of a scene's meshes.
    static constexpr std::uint64_t kMostKeptBytes = std::uint64_t(64) << 20;

    // The .mtl at `path` as read, by its identity (device and inode) where `stat` gives one:
    // read and checked at the first call for a file, kept for the later ones.
    const MtlFileRead& read(const std::string& path);

private:
    std::map<std::pair<dev_t, ino_t>, MtlFileRead> kept_;
    std::uint64_t kept_bytes_ = 0;
    MtlFileRead last_;  // a file that is not kept
};

}  // namespace clr
