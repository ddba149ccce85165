// The shapes of large meshes' BVH trees (render/scene_bvh.h) kept across runs: building the
// tree of a 1M-triangle mesh is about a third of a warm still's time, making its boxes again
// from a stored shape a pass over the triangles. Entries live in trees/ under the cache folder
// (core/cache_folder.h, core/cache_entry_folder.h), named by a hash of the mesh's placed
// triangles (every corner's bits), their count and the depth the tree may take.
//
// An entry holds the shape only: which nodes are inner and which leaves hold which of the
// mesh's triangles. A loaded shape is checked to be a tree over exactly the mesh's triangles,
// no deeper than allowed, and its boxes are made from the triangles themselves, so no entry,
// not even one planted with a valid checksum, can make a BVH that misses a triangle or
// overflows the kernels' stack; the worst a wrong shape can do is walk slowly.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "core/cache_entry_folder.h"
#include "render/bvh.h"
#include "scene/scene.h"

namespace clr {

class MeshTreeCache {
public:
    // Smaller meshes build their trees in about the time an entry takes to look up.
    static constexpr std::size_t kSmallestStoredTriangles = std::size_t(1) << 16;
    static constexpr std::uint64_t kDefaultSizeLimit = std::uint64_t(256) << 20;
    // Part of every key and header: a change of the entry layout must bump it.
    static constexpr std::uint32_t kFormatVersion = 1;

    using Key = Sha256Digest;

    // trees/ under cache_folder_from_environment(); disabled when that is "".
    static MeshTreeCache from_environment();

    // Entries go in `cache_folder`/trees; "" disables the cache. `smallest`: the fewest triangles
    // a stored tree has (kSmallestStoredTriangles; tests lower it).
    explicit MeshTreeCache(std::string cache_folder, std::uint64_t size_limit = kDefaultSizeLimit,
                           std::size_t smallest = kSmallestStoredTriangles);
    bool enabled() const { return entries_.enabled(); }
    // Whether `mesh` is large enough to be worth an entry.
    bool worth_keeping(const Mesh& mesh) const { return enabled() && mesh.triangle_count >= smallest_; }

    // The key of `mesh`'s tree (its triangles in `scene`) no deeper than `max_depth`.
    static Key key(const Scene& scene, const Mesh& mesh, int max_depth);

    // The tree stored for `key`, over `mesh`'s triangles with boxes made from them, or nothing:
    // no entry, a damaged one, or a shape that is not a tree over exactly those triangles no
    // deeper than `max_depth` (such an entry is removed).
    std::optional<Bvh> load(const Key& key, const Scene& scene, const Mesh& mesh, int max_depth) const;
    // Stores the shape of `tree`, a tree over `mesh`'s triangles (best effort).
    void store(const Key& key, const Bvh& tree, const Mesh& mesh) const;

private:
    CacheEntryFolder entries_;
    std::size_t smallest_;
};

}  // namespace clr
