// Parsed OBJ meshes kept across runs. Checking and parsing a large OBJ is most of a cold
// still's time (a 1M-triangle terrain: about 0.9 of 1.8 s, docs/benchmarks.md, Start-up);
// reading back and checking the parsed mesh is a fraction of that. Entries live in meshes/
// under the cache folder (core/cache_folder.h, core/cache_entry_folder.h), named by the SHA-256
// of the OBJ's whole text, of its path and the working folder (its `mtllib` names are relative
// to its folder), of the clrender build that parsed it and of the entry format: an edited OBJ
// or another build is a new key. An entry also lists the .mtl files the parse read with the
// SHA-256 of each; a hit needs every one to read the same again, so an edited or removed .mtl
// is a miss and the OBJ is parsed (and its problem reported) as without a cache.
//
// A hit is checked as the reader checks its own result before it is used (every index in
// range, coordinates finite and within clrender's range): not even an entry planted in the
// private cache folder with correct checksums can make a mesh the reader would refuse. Failures
// are never stored, so they are reported every time. Only OBJ files of at least
// kSmallestStoredBytes, and meshes of at most kLargestStoredBytes, are stored; the folder is
// kept under a size limit by removing the least recently used entries.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <string>

#include "core/cache_entry_folder.h"
#include "core/sha256.h"
#include "scene/obj_reader.h"

namespace clr {

class MeshCache {
public:
    // Smaller files parse in about the time an entry takes to look up and read.
    static constexpr std::size_t kSmallestStoredBytes = 1u << 20;
    static constexpr std::uint64_t kDefaultSizeLimit = std::uint64_t(1) << 30;
    // A stored mesh is copied into one payload first: larger meshes (about 5M triangles) are
    // not stored, so that storing never doubles a huge mesh's memory.
    static constexpr std::uint64_t kLargestStoredBytes = std::uint64_t(256) << 20;
    // Part of every key and header: a change of the entry layout must bump it. (A change of
    // how OBJ files are read changes the build, which is in every key already.)
    static constexpr std::uint32_t kFormatVersion = 1;

    using Key = Sha256Digest;

    // meshes/ under cache_folder_from_environment(); disabled when that is "".
    static MeshCache from_environment();

    // Entries go in `cache_folder`/meshes; "" disables the cache. `size_limit`: most bytes of
    // entries kept there.
    // `largest_mesh`: the most bytes of mesh arrays stored (kLargestStoredBytes; tests lower it).
    explicit MeshCache(std::string cache_folder, std::uint64_t size_limit = kDefaultSizeLimit,
                       std::uint64_t largest_mesh = kLargestStoredBytes);
    bool enabled() const { return entries_.enabled(); }
    std::string folder() const { return entries_.folder(); }
    // The entry's file for `key`.
    std::string path(const Key& key) const { return entries_.path(key); }

    // The key of the OBJ at `path` whose text is `text`.
    static Key key(const std::string& path, const std::string& text);

    // The mesh stored for `key`, or nothing: no entry, a damaged one, a .mtl that no longer
    // reads as it did, or a mesh that fails the reader's checks (such an entry is removed).
    // The .mtl files are read through `library` where one is given (see parse_obj).
    std::optional<ObjMesh> load(const Key& key, MtlLibrary* library = nullptr) const;
    // Stores `mesh` (best effort: a folder that cannot be written leaves the cache as it was),
    // then trims the folder to the size limit.
    void store(const Key& key, const ObjMesh& mesh) const;

private:
    CacheEntryFolder entries_;
    std::uint64_t largest_mesh_;
};

// read_obj(path) through `cache`: the same mesh, and the same ObjError for a file that cannot
// be read (failures are never stored). A parse reads the .mtl files through `library` (see
// parse_obj).
ObjMesh read_obj_through_cache(const std::string& path, const MeshCache& cache,
                               std::uint64_t memory_budget = std::numeric_limits<std::uint64_t>::max(),
                               MtlLibrary* library = nullptr);

}  // namespace clr
