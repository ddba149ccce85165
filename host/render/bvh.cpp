#include "render/bvh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <future>
#include <limits>
#include <stdexcept>
#include <string>
#include <system_error>

#include "core/box3.h"
#include "core/parallel_for.h"
#include "core/usable_cpus.h"

namespace clr {
namespace {

constexpr int kBins = 16;         // candidate split planes per axis
constexpr std::uint32_t kLeafSize = 4;

using Box = Box3;
using Primitive = BvhPrimitive;

// Subtrees of at least this many primitives are built on a thread of their own, down to a depth
// that gives every usable CPU work (below that, starting a thread costs more than it saves).
constexpr std::uint32_t kParallelPrimitives = 1u << 15;

int parallel_levels() {
    int levels = 0;
    for (int cpus = usable_cpu_count(); (1 << levels) < cpus; ++levels) {
    }
    return levels;
}

// Binned SAH, top down. The nodes are laid out depth first, each pair of children together
// (the left child's subtree, then the right child's); a subtree built on another thread is
// built into its own array and spliced in where it would have been, so the BVH is the same
// bytes on any number of threads.
class Builder {
public:
    Builder(std::vector<Primitive> primitives, int max_depth) : primitives_(std::move(primitives)), max_depth_(max_depth) {}

    Bvh build() {
        Bvh bvh;
        if (primitives_.empty()) return bvh;
        Bounds all;
        for (const Primitive& p : primitives_) all.grow(p);
        bvh.nodes.emplace_back();
        build_node(bvh.nodes, 0, 0, static_cast<std::uint32_t>(primitives_.size()), all, 0, parallel_levels());
        bvh.items.reserve(primitives_.size());
        for (const Primitive& p : primitives_) bvh.items.push_back(p.item);
        return bvh;
    }

private:
    using Nodes = std::vector<Bvh::Node>;

    // The box around some primitives, and the box around their centroids.
    struct Bounds {
        Box box, centroids;
        void grow(const Primitive& p) {
            box.grow(p.box);
            centroids.grow(p.centroid);
        }
        void grow(const Bounds& b) {
            box.grow(b.box);
            centroids.grow(b.centroids);
        }
    };

    // Where split() divides a node's primitives, and the bounds of both sides (unions of the
    // bins' bounds: min and max are exact, so they are what a pass over each side would give).
    struct Split {
        std::uint32_t middle;
        Bounds left, right;
    };

    // Fills nodes[index] with primitives [begin, end) within `bounds`, splitting where the
    // surface-area heuristic says traversal is cheapest; a leaf when no split pays.
    void build_node(Nodes& nodes, std::size_t index, std::uint32_t begin, std::uint32_t end, const Bounds& bounds,
                    int depth, int parallel_levels) {
        nodes[index].lower = bounds.box.lower;
        nodes[index].upper = bounds.box.upper;
        // Depth is capped so that the kernels' fixed traversal stack always suffices.
        bool may_split = end - begin > kLeafSize && depth < max_depth_;
        const Split cut = may_split ? split(begin, end, bounds) : Split{begin, {}, {}};
        const std::uint32_t middle = cut.middle;
        if (middle == begin || middle == end) {
            nodes[index].first = begin;
            nodes[index].count = end - begin;
            return;
        }
        auto left = static_cast<std::uint32_t>(nodes.size());
        nodes[index].first = left;
        nodes.emplace_back();
        nodes.emplace_back();
        if (parallel_levels <= 0 || end - middle < kParallelPrimitives) {
            build_node(nodes, left, begin, middle, cut.left, depth + 1, 0);
            build_node(nodes, left + 1, middle, end, cut.right, depth + 1, 0);
            return;
        }
        // The right subtree on another thread, into its own array whose node 0 is its root. A
        // process that cannot start a thread builds both here, the same nodes.
        Nodes right(1);
        std::future<void> right_built;
        try {
            right_built = std::async(std::launch::async, [&] {
                build_node(right, 0, middle, end, cut.right, depth + 1, parallel_levels - 1);
            });
        } catch (const std::system_error&) {
            build_node(nodes, left, begin, middle, cut.left, depth + 1, 0);
            build_node(nodes, left + 1, middle, end, cut.right, depth + 1, 0);
            return;
        }
        try {
            build_node(nodes, left, begin, middle, cut.left, depth + 1, parallel_levels - 1);
        } catch (...) {
            right_built.wait();  // it reads primitives_ and writes `right`: done before they go
            throw;
        }
        right_built.get();
        splice(nodes, left + 1, right);
    }

    // Puts `subtree` (node 0 its root) at nodes[root], its other nodes after the last of
    // `nodes`, with their child indices moved along.
    static void splice(Nodes& nodes, std::size_t root, const Nodes& subtree) {
        const auto shift = static_cast<std::uint32_t>(nodes.size() - 1);
        auto placed = [shift](Bvh::Node node) {
            if (node.count == 0) node.first += shift;  // an inner node's child; a leaf's items stay
            return node;
        };
        nodes[root] = placed(subtree[0]);
        nodes.reserve(nodes.size() + subtree.size() - 1);
        for (std::size_t i = 1; i < subtree.size(); ++i) nodes.push_back(placed(subtree[i]));
    }

    // Binned SAH over the axis of largest centroid extent. The partition point is `begin` when
    // keeping a leaf is cheaper (or all centroids coincide).
    Split split(std::uint32_t begin, std::uint32_t end, const Bounds& bounds) {
        const Split leaf{begin, {}, {}};
        Vec3 extent = bounds.centroids.upper - bounds.centroids.lower;
        int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
        double low = bounds.centroids.lower[axis], width = extent[axis];
        if (!(width > 0)) return leaf;
        // Each primitive's bin, found once for both the counts and the partition.
        std::vector<std::uint8_t> bins(end - begin);
        std::array<Bounds, kBins> binned;
        std::array<std::uint32_t, kBins> counts{};
        for (std::uint32_t i = begin; i < end; ++i) {
            const int bin = std::min(kBins - 1, static_cast<int>((primitives_[i].centroid[axis] - low) / width * kBins));
            bins[i - begin] = static_cast<std::uint8_t>(bin);
            binned[bin].grow(primitives_[i]);
            ++counts[bin];
        }
        // Cost of each split between bins b and b+1: areas times counts on both sides.
        std::array<double, kBins - 1> right_cost{};
        Box right;
        std::uint32_t right_count = 0;
        for (int b = kBins - 1; b > 0; --b) {
            right.grow(binned[b].box);
            right_count += counts[b];
            right_cost[b - 1] = right.area() * right_count;
        }
        Box left;
        std::uint32_t left_count = 0;
        const double area = bounds.box.area();
        double best_cost = area * (end - begin);  // cost of a leaf
        int best_split = -1;
        for (int b = 0; b < kBins - 1; ++b) {
            left.grow(binned[b].box);
            left_count += counts[b];
            double cost = left.area() * left_count + right_cost[b] + area * 0.5;  // plus a traversal step
            if (cost < best_cost && left_count > 0 && left_count < end - begin) best_cost = cost, best_split = b;
        }
        if (best_split < 0) return leaf;
        Split cut{partition(begin, end, bins, best_split), {}, {}};
        for (int b = 0; b < kBins; ++b) (b <= best_split ? cut.left : cut.right).grow(binned[b]);
        return cut;
    }

    // Moves the primitives of bins up to `last_left` before the others, swapping as
    // std::partition does for bidirectional iterators (libstdc++), so that the order, and so the
    // BVH, is what it was when this called std::partition; `bins` moves along.
    std::uint32_t partition(std::uint32_t begin, std::uint32_t end, std::vector<std::uint8_t>& bins, int last_left) {
        std::uint32_t first = begin, last = end;
        auto is_left = [&](std::uint32_t i) { return bins[i - begin] <= last_left; };
        while (true) {
            while (first != last && is_left(first)) ++first;
            if (first == last) return first;
            --last;
            while (first != last && !is_left(last)) --last;
            if (first == last) return first;
            std::swap(primitives_[first], primitives_[last]);
            std::swap(bins[first - begin], bins[last - begin]);
            ++first;
        }
    }

    std::vector<Primitive> primitives_;
    int max_depth_;
};

// Rounds towards -inf or +inf, so float bounds still contain the double ones.
float down(double v) {
    float f = static_cast<float>(v);
    return f > v ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}
float up(double v) {
    float f = static_cast<float>(v);
    return f < v ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

}  // namespace

Bvh build_tree(std::vector<BvhPrimitive> primitives, int max_depth) {
    return Builder(std::move(primitives), std::min(max_depth, kMaxBvhDepth)).build();
}

namespace {

// `value` as a ClrBvhNode w word: the float whose bits are value + CLR_BVH_WORD_BIAS, a normal
// float (the kernels read it back with bvh_first() and bvh_count()). A larger value than a word
// holds would name another node or item: the scene limits make that many impossible, so it is a bug.
float word_of(std::uint32_t value) {
    if (value > CLR_BVH_WORD_MAX)
        throw std::length_error("BVH word " + std::to_string(value) + " above " + std::to_string(CLR_BVH_WORD_MAX));
    const std::uint32_t bits = value + CLR_BVH_WORD_BIAS;
    float word;
    std::memcpy(&word, &bits, sizeof word);
    return word;
}

// `node` in the device form; an inner node's children found at `children` there.
ClrBvhNode device_node(const Bvh::Node& node, const Vec3& shift, std::uint32_t children) {
    ClrBvhNode out{};
    // A little room, so that objects rounded to float on their own (compile_scene) stay
    // inside the float bounds too.
    Vec3 lower = node.lower - shift, upper = node.upper - shift;
    double size = std::max({std::fabs(lower.x), std::fabs(lower.y), std::fabs(lower.z), std::fabs(upper.x),
                            std::fabs(upper.y), std::fabs(upper.z)});
    Vec3 pad{1e-6 * size, 1e-6 * size, 1e-6 * size};
    lower = lower - pad;
    upper = upper + pad;
    out.lower.s[0] = down(lower.x);
    out.lower.s[1] = down(lower.y);
    out.lower.s[2] = down(lower.z);
    out.upper.s[0] = up(upper.x);
    out.upper.s[1] = up(upper.y);
    out.upper.s[2] = up(upper.z);
    out.lower.s[3] = word_of(node.count == 0 ? children : node.first);
    out.upper.s[3] = word_of(node.count);
    return out;
}

// Where each of `bvh`'s nodes goes in the device form: in order, but every pair of siblings
// starting at an even index (a zero node that no node names before it where needed), so that
// with 32-byte nodes in a 64-byte aligned buffer a node's children share one cache line.
// Returns the device form's node count.
std::uint32_t device_positions(const Bvh& bvh, std::vector<std::uint32_t>& positions) {
    std::vector<bool> starts_pair(bvh.nodes.size(), false);
    for (const Bvh::Node& node : bvh.nodes)
        if (node.count == 0) starts_pair[node.first] = true;
    positions.resize(bvh.nodes.size());
    std::uint32_t next = 0;
    for (std::size_t i = 0; i < bvh.nodes.size(); ++i) {
        if (starts_pair[i] && next % 2 == 1) ++next;
        positions[i] = next++;
    }
    return next;
}

// Nodes a worker converts at a time: a moving camera re-expresses every node each frame (half
// a million for a 1M-triangle mesh), on every usable CPU.
constexpr std::size_t kNodesPerTask = 1u << 16;

}  // namespace

void compile_bvh(const Bvh& bvh, const Vec3& origin, std::vector<ClrBvhNode>& nodes) {
    std::vector<std::uint32_t> positions;
    ClrBvhNode unnamed{};  // zero box, zero first and count, as normal w words
    unnamed.lower.s[3] = unnamed.upper.s[3] = word_of(0);
    nodes.assign(device_positions(bvh, positions), unnamed);
    const Vec3 shift = origin - bvh.origin;  // zero when the frame's impostors were placed there
    const std::size_t tasks = (bvh.nodes.size() + kNodesPerTask - 1) / kNodesPerTask;
    parallel_for(tasks, static_cast<std::size_t>(usable_cpu_count()), [&](std::size_t task) {
        const std::size_t end = std::min(bvh.nodes.size(), (task + 1) * kNodesPerTask);
        for (std::size_t i = task * kNodesPerTask; i < end; ++i) {
            const Bvh::Node& node = bvh.nodes[i];
            const std::uint32_t children = node.count == 0 ? positions[node.first] : 0;
            nodes[positions[i]] = device_node(node, shift, children);
        }
    });
}

}  // namespace clr
