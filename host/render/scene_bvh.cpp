#include "render/scene_bvh.h"

#include <algorithm>
#include <map>
#include <optional>
#include <string>
#include <utility>

#include "core/parallel_for.h"
#include "core/usable_cpus.h"
#include "kinds/kinds.h"
#include "render/scene_item.h"

namespace clr {
namespace {

bool has_own_tree(const MeshTrees& meshes, std::uint32_t mesh) {
    return mesh < meshes.tree_of_mesh.size() && meshes.tree_of_mesh[mesh] != MeshTrees::kNone;
}

// The frame's objects outside the mesh trees, boxes relative to `origin`, kind by kind.
std::vector<BvhPrimitive> loose_primitives(const FrameGeometry& frame, const Vec3& origin, const MeshTrees& meshes) {
    std::vector<BvhPrimitive> primitives;
    for_each_bounded_kind([&](auto kind) {
        using Kind = decltype(kind);
        for (std::size_t i = 0; i < Kind::count(frame); ++i) {
            if constexpr (Kind::kHit == CLR_HIT_TRIANGLE) {
                if (has_own_tree(meshes, frame.triangles()[i].mesh)) continue;
            }
            // Zero for placed impostors, whose corners are relative to `origin` already: exact.
            const Vec3 shift = origin - Kind::origin(frame, i);
            BvhPrimitive p;
            p.box = Kind::box(Kind::object(frame, i), shift, p.centroid);
            p.item = scene_item(Kind::kHit, i);
            primitives.push_back(p);
        }
    });
    return primitives;
}

Box3 triangle_box(const Scene& scene, std::uint32_t item) {
    Vec3 centroid;
    return TriangleKind::box(scene.triangles[scene_item_index(item)], Vec3{}, centroid);
}

Bvh mesh_tree(const Scene& scene, const Mesh& mesh, int max_depth) {
    std::vector<BvhPrimitive> primitives(mesh.triangle_count);
    for (std::size_t k = 0; k < mesh.triangle_count; ++k) {
        BvhPrimitive& p = primitives[k];
        p.item = scene_item(CLR_HIT_TRIANGLE, mesh.first_triangle + k);
        p.box = TriangleKind::box(scene.triangles[mesh.first_triangle + k], Vec3{}, p.centroid);
    }
    return build_tree(std::move(primitives), max_depth);
}

// `shape`, the tree of the mesh whose triangles start at `shape_first`, for another mesh of as
// many triangles starting at `first`: the same nodes and leaves over its triangles, each box
// made anew from them.
Bvh refitted(const Bvh& shape, std::size_t shape_first, const Scene& scene, std::size_t first) {
    Bvh tree;
    tree.items.reserve(shape.items.size());
    for (std::uint32_t item : shape.items)
        tree.items.push_back(scene_item(CLR_HIT_TRIANGLE, first + (scene_item_index(item) - shape_first)));
    tree.nodes = shape.nodes;
    make_boxes(tree, scene);
    return tree;
}

// Levels a balanced binary tree over `parts` leaves takes.
int levels_over(std::size_t parts) {
    int levels = 0;
    while ((std::size_t(1) << levels) < parts) ++levels;
    return levels;
}

// A tree to join: its bounds less `shift` are relative to the frame's origin.
struct Part {
    const Bvh* tree;
    Vec3 shift;
    Vec3 centroid;
};

Bvh::Node shifted(Bvh::Node node, const Vec3& shift) {
    node.lower = node.lower - shift;
    node.upper = node.upper - shift;
    return node;
}

// Puts part's tree at joined.nodes[index], its other nodes and its items after the last ones.
void graft(Bvh& joined, std::size_t index, const Part& part) {
    const Bvh& tree = *part.tree;
    const auto node_shift = static_cast<std::uint32_t>(joined.nodes.size() - 1);
    const auto item_shift = static_cast<std::uint32_t>(joined.items.size());
    auto placed = [&](const Bvh::Node& node) {
        Bvh::Node out = shifted(node, part.shift);
        out.first += out.count == 0 ? node_shift : item_shift;
        return out;
    };
    joined.items.insert(joined.items.end(), tree.items.begin(), tree.items.end());
    joined.nodes[index] = placed(tree.nodes[0]);
    joined.nodes.reserve(joined.nodes.size() + tree.nodes.size() - 1);
    for (std::size_t i = 1; i < tree.nodes.size(); ++i) joined.nodes.push_back(placed(tree.nodes[i]));
}

// Fills joined.nodes[index] with parts [begin, end): halves split at the median centre along
// the axis where the centres spread most, down to one part a node (levels_over() levels).
void join(Bvh& joined, std::size_t index, std::vector<Part>& parts, std::size_t begin, std::size_t end) {
    if (end - begin == 1) {
        graft(joined, index, parts[begin]);
        return;
    }
    Box3 box, centres;
    for (std::size_t i = begin; i < end; ++i) {
        const Bvh::Node root = shifted(parts[i].tree->nodes[0], parts[i].shift);
        box.grow(root.lower);
        box.grow(root.upper);
        centres.grow(parts[i].centroid);
    }
    const Vec3 extent = centres.upper - centres.lower;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const std::size_t middle = begin + (end - begin) / 2;
    std::nth_element(parts.begin() + begin, parts.begin() + middle, parts.begin() + end,
                     [axis](const Part& a, const Part& b) { return a.centroid[axis] < b.centroid[axis]; });
    const auto left = static_cast<std::uint32_t>(joined.nodes.size());
    joined.nodes[index] = {box.lower, box.upper, left, 0};
    joined.nodes.emplace_back();
    joined.nodes.emplace_back();
    join(joined, left, parts, begin, middle);
    join(joined, left + 1, parts, middle, end);
}

// A mesh's tree: from `cache` when it holds one for these triangles, else built (and stored).
Bvh mesh_tree(const Scene& scene, const Mesh& mesh, int max_depth, const MeshTreeCache* cache) {
    if (!cache || !cache->worth_keeping(mesh)) return mesh_tree(scene, mesh, max_depth);
    const MeshTreeCache::Key key = MeshTreeCache::key(scene, mesh, max_depth);
    if (std::optional<Bvh> stored = cache->load(key, scene, mesh, max_depth)) return std::move(*stored);
    Bvh tree = mesh_tree(scene, mesh, max_depth);
    cache->store(key, tree, mesh);
    return tree;
}

}  // namespace

void make_boxes(Bvh& tree, const Scene& scene) {
    // Children before parents: build_tree() puts each node before them.
    for (std::size_t i = tree.nodes.size(); i-- > 0;) {
        Bvh::Node& node = tree.nodes[i];
        Box3 box;
        if (node.count == 0) {
            for (std::uint32_t child : {node.first, node.first + 1}) {
                box.grow(tree.nodes[child].lower);
                box.grow(tree.nodes[child].upper);
            }
        } else {
            for (std::uint32_t k = node.first; k < node.first + node.count; ++k) box.grow(triangle_box(scene, tree.items[k]));
        }
        node.lower = box.lower;
        node.upper = box.upper;
    }
}

MeshTrees build_mesh_trees(const Scene& scene, const MeshTreeCache* cache) {
    MeshTrees meshes;
    meshes.tree_of_mesh.assign(scene.meshes.size(), MeshTrees::kNone);
    std::vector<std::size_t> own;  // meshes with a tree
    for (std::size_t m = 0; m < scene.meshes.size(); ++m)
        if (scene.meshes[m].triangle_count >= kOwnTreeTriangles) own.push_back(m);
    if (own.empty()) return meshes;
    meshes.max_depth = kMaxBvhDepth - levels_over(own.size() + 1);  // +1: the frame's own tree
    // The first mesh of each file (and triangle count) is built; the others take its shape.
    std::map<std::pair<std::string, std::size_t>, std::size_t> first_of_shape;
    std::vector<std::size_t> shape_of(own.size());
    meshes.trees.resize(own.size());
    for (std::size_t t = 0; t < own.size(); ++t) {
        const Mesh& mesh = scene.meshes[own[t]];
        meshes.tree_of_mesh[own[t]] = static_cast<std::uint32_t>(t);
        shape_of[t] = t;
        // A placeholder cube stands in for a file that failed to load: not that file's shape.
        if (!mesh.path.empty() && !mesh.placeholder)
            shape_of[t] = first_of_shape.emplace(std::pair{mesh.path, mesh.triangle_count}, t).first->second;
        if (shape_of[t] == t) meshes.trees[t] = mesh_tree(scene, mesh, meshes.max_depth, cache);
    }
    parallel_for(own.size(), static_cast<std::size_t>(usable_cpu_count()), [&](std::size_t t) {
        if (shape_of[t] == t) return;
        meshes.trees[t] = refitted(meshes.trees[shape_of[t]], scene.meshes[own[shape_of[t]]].first_triangle, scene,
                                   scene.meshes[own[t]].first_triangle);
    });
    return meshes;
}

Bvh build_bvh(const FrameGeometry& frame, const MeshTrees& meshes) {
    const Vec3 origin = frame.impostor_origin();
    Bvh loose = build_tree(loose_primitives(frame, origin, meshes), meshes.max_depth);
    loose.origin = origin;
    if (meshes.trees.empty()) return loose;
    std::vector<Part> parts;
    auto add = [&parts](const Bvh& tree, const Vec3& shift) {
        if (tree.nodes.empty()) return;
        const Bvh::Node root = shifted(tree.nodes[0], shift);
        parts.push_back({&tree, shift, (root.lower + root.upper) * 0.5});
    };
    add(loose, Vec3{});
    for (const Bvh& tree : meshes.trees) add(tree, origin);  // theirs are relative to (0, 0, 0)
    Bvh joined;
    joined.origin = origin;
    std::size_t nodes = 1, items = 0;
    for (const Part& part : parts) nodes += part.tree->nodes.size() + 1, items += part.tree->items.size();
    joined.nodes.reserve(nodes);
    joined.items.reserve(items);
    joined.nodes.emplace_back();
    join(joined, 0, parts, 0, parts.size());
    return joined;
}

Bvh build_bvh(const FrameGeometry& frame) { return build_bvh(frame, build_mesh_trees(frame.scene())); }

}  // namespace clr
