#include "render/mesh_tree_cache.h"

#include <cstring>
#include <vector>

#include "core/cache_folder.h"
#include "core/payload_checksum.h"
#include "render/scene_bvh.h"
#include "render/scene_item.h"

namespace clr {
namespace {

// Nodes and leaf items as 32-bit numbers: at most 2n - 1 nodes of two and n items for a tree
// over n triangles (kMaxSceneTriangles at most).
CacheEntryKind tree_entries(std::uint64_t size_limit) {
    const std::uint64_t largest = (std::uint64_t(1) << 24) * 5 * sizeof(std::uint32_t) + 2 * sizeof(std::uint64_t);
    return {"tree", {'c', 'l', 'r', 't', 'r', 'e', 'e', '1'}, MeshTreeCache::kFormatVersion,
            std::min(size_limit, largest)};
}

// Whether nodes and items (items local to the mesh: 0 .. triangles - 1) form a tree that holds
// each triangle in exactly one leaf, whose children follow their parent (as build_tree() lays
// them out, which also rules out cycles), no deeper than max_depth.
bool is_tree_over(const std::vector<Bvh::Node>& nodes, const std::vector<std::uint32_t>& items,
                  std::size_t triangles, int max_depth) {
    if (nodes.empty() || items.size() != triangles || nodes.size() > 2 * triangles) return false;
    std::vector<int> depth(nodes.size(), -1);
    std::vector<bool> slot_used(items.size()), triangle_seen(triangles);
    depth[0] = 0;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        const Bvh::Node& node = nodes[i];
        if (depth[i] < 0) return false;  // no parent reached it
        if (node.count == 0) {
            const std::uint64_t left = node.first;
            if (left <= i || left + 1 >= nodes.size() || depth[left] >= 0 || depth[left + 1] >= 0 ||
                depth[i] + 1 > max_depth)
                return false;
            depth[left] = depth[left + 1] = depth[i] + 1;
            continue;
        }
        if (std::uint64_t(node.first) + node.count > items.size()) return false;
        for (std::uint32_t k = node.first; k < node.first + node.count; ++k) {
            if (slot_used[k] || items[k] >= triangles || triangle_seen[items[k]]) return false;
            slot_used[k] = triangle_seen[items[k]] = true;
        }
    }
    for (bool used : slot_used)
        if (!used) return false;
    return true;
}

template <typename T>
void put(std::vector<unsigned char>& out, const T& value) {
    const auto* bytes = reinterpret_cast<const unsigned char*>(&value);
    out.insert(out.end(), bytes, bytes + sizeof(T));
}

template <typename T>
bool get(const std::vector<unsigned char>& in, std::size_t& at, T& value) {
    if (in.size() - at < sizeof(T)) return false;
    std::memcpy(&value, in.data() + at, sizeof(T));
    at += sizeof(T);
    return true;
}

}  // namespace

MeshTreeCache MeshTreeCache::from_environment() { return MeshTreeCache(cache_folder_from_environment()); }

MeshTreeCache::MeshTreeCache(std::string cache_folder, std::uint64_t size_limit, std::size_t smallest)
    : entries_(std::move(cache_folder), "trees", tree_entries(size_limit), size_limit), smallest_(smallest) {}

MeshTreeCache::Key MeshTreeCache::key(const Scene& scene, const Mesh& mesh, int max_depth) {
    // XXH3 over the corners (tens of megabytes for a large mesh, at memory speed), then SHA-256
    // over that and the rest. A collision could only cost speed: a loaded shape is checked and
    // its boxes made from the mesh's own triangles.
    PayloadChecksummer corners;
    for (std::size_t i = 0; i < mesh.triangle_count; ++i) {
        const Triangle& triangle = scene.triangles[mesh.first_triangle + i];
        corners.add(triangle.corners.data(), sizeof(triangle.corners));
    }
    const PayloadChecksum digest = corners.finish();
    return Sha256()
        .add_field(std::string("clrender mesh tree shape"))
        .add_number(kFormatVersion)
        .add_number(mesh.triangle_count)
        .add_number(static_cast<std::uint64_t>(max_depth))
        .add_field(digest.data(), digest.size())
        .finish();
}

std::optional<Bvh> MeshTreeCache::load(const Key& key, const Scene& scene, const Mesh& mesh, int max_depth) const {
    std::optional<CacheEntry> entry = entries_.load(key);
    if (!entry) return std::nullopt;
    const std::vector<unsigned char>& in = entry->payload;
    std::size_t at = 0;
    std::uint64_t node_count = 0, item_count = 0;
    Bvh tree;
    bool read = get(in, at, node_count) && get(in, at, item_count) && item_count == mesh.triangle_count &&
                node_count <= 2 * item_count && in.size() - at == node_count * 8 + item_count * 4;
    if (read) {
        tree.nodes.resize(node_count);
        tree.items.resize(item_count);
        for (Bvh::Node& node : tree.nodes) get(in, at, node.first), get(in, at, node.count);
        for (std::uint32_t& item : tree.items) get(in, at, item);
    }
    if (!read || !is_tree_over(tree.nodes, tree.items, mesh.triangle_count, max_depth)) {
        entries_.remove(key);
        return std::nullopt;
    }
    for (std::uint32_t& item : tree.items) item = scene_item(CLR_HIT_TRIANGLE, mesh.first_triangle + item);
    make_boxes(tree, scene);
    return tree;
}

void MeshTreeCache::store(const Key& key, const Bvh& tree, const Mesh& mesh) const {
    if (!enabled()) return;
    std::vector<unsigned char> out;
    out.reserve(2 * sizeof(std::uint64_t) + tree.nodes.size() * 8 + tree.items.size() * 4);
    put<std::uint64_t>(out, tree.nodes.size());
    put<std::uint64_t>(out, tree.items.size());
    for (const Bvh::Node& node : tree.nodes) put(out, node.first), put(out, node.count);
    for (std::uint32_t item : tree.items)
        put<std::uint32_t>(out, static_cast<std::uint32_t>(scene_item_index(item) - mesh.first_triangle));
    entries_.store(key, {0, 0}, out.data(), out.size());
}

}  // namespace clr
