#include "render/bvh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "core/box3.h"
#include "kinds/kinds.h"
#include "render/scene_item.h"

namespace clr {
namespace {

constexpr int kBins = 16;         // candidate split planes per axis
constexpr std::uint32_t kLeafSize = 4;

using Box = Box3;

struct Primitive {
    Box box;
    Vec3 centroid;
    std::uint32_t item;
};

// The frame's objects' boxes relative to `origin`, kind by kind (kinds/kinds.h).
std::vector<Primitive> primitives_of(const FrameGeometry& frame, const Vec3& origin) {
    std::vector<Primitive> primitives;
    for_each_bounded_kind([&](auto kind) {
        using Kind = decltype(kind);
        for (std::size_t i = 0; i < Kind::count(frame); ++i) {
            // Zero for placed impostors, whose corners are relative to `origin` already: exact.
            const Vec3 shift = origin - Kind::origin(frame, i);
            Primitive p;
            p.box = Kind::box(Kind::object(frame, i), shift, p.centroid);
            p.item = scene_item(Kind::kHit, i);
            primitives.push_back(p);
        }
    });
    return primitives;
}

class Builder {
public:
    explicit Builder(std::vector<Primitive> primitives) : primitives_(std::move(primitives)) {}

    Bvh build() {
        Bvh bvh;
        if (primitives_.empty()) return bvh;
        bvh.nodes.emplace_back();
        build_node(bvh, 0, 0, static_cast<std::uint32_t>(primitives_.size()), 0);
        for (const Primitive& p : primitives_) bvh.items.push_back(p.item);
        return bvh;
    }

private:
    // Fills node `index` with primitives [begin, end), splitting where the surface-area
    // heuristic says traversal is cheapest; a leaf when no split pays.
    void build_node(Bvh& bvh, std::size_t index, std::uint32_t begin, std::uint32_t end, int depth) {
        Box bounds, centroids;
        for (std::uint32_t i = begin; i < end; ++i) {
            bounds.grow(primitives_[i].box);
            centroids.grow(primitives_[i].centroid);
        }
        bvh.nodes[index].lower = bounds.lower;
        bvh.nodes[index].upper = bounds.upper;
        // Depth is capped so that the kernels' fixed traversal stack always suffices.
        bool may_split = end - begin > kLeafSize && depth < kMaxBvhDepth;
        std::uint32_t middle = may_split ? split(begin, end, bounds, centroids) : begin;
        if (middle == begin || middle == end) {
            bvh.nodes[index].first = begin;
            bvh.nodes[index].count = end - begin;
            return;
        }
        auto left = static_cast<std::uint32_t>(bvh.nodes.size());
        bvh.nodes[index].first = left;
        bvh.nodes.emplace_back();
        bvh.nodes.emplace_back();
        build_node(bvh, left, begin, middle, depth + 1);
        build_node(bvh, left + 1, middle, end, depth + 1);
    }

    // Binned SAH over the axis of largest centroid extent. Returns the partition point, or
    // `begin` when keeping a leaf is cheaper (or all centroids coincide).
    std::uint32_t split(std::uint32_t begin, std::uint32_t end, const Box& bounds, const Box& centroids) {
        Vec3 extent = centroids.upper - centroids.lower;
        int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
        double low = centroids.lower[axis], width = extent[axis];
        if (!(width > 0)) return begin;
        auto bin_of = [&](const Primitive& p) {
            return std::min(kBins - 1, static_cast<int>((p.centroid[axis] - low) / width * kBins));
        };
        std::array<Box, kBins> boxes;
        std::array<std::uint32_t, kBins> counts{};
        for (std::uint32_t i = begin; i < end; ++i) {
            int bin = bin_of(primitives_[i]);
            boxes[bin].grow(primitives_[i].box);
            ++counts[bin];
        }
        // Cost of each split between bins b and b+1: areas times counts on both sides.
        std::array<double, kBins - 1> right_cost{};
        Box right;
        std::uint32_t right_count = 0;
        for (int b = kBins - 1; b > 0; --b) {
            right.grow(boxes[b]);
            right_count += counts[b];
            right_cost[b - 1] = right.area() * right_count;
        }
        Box left;
        std::uint32_t left_count = 0;
        double best_cost = bounds.area() * (end - begin);  // cost of a leaf
        int best_split = -1;
        for (int b = 0; b < kBins - 1; ++b) {
            left.grow(boxes[b]);
            left_count += counts[b];
            double cost = left.area() * left_count + right_cost[b] + bounds.area() * 0.5;  // plus a traversal step
            if (cost < best_cost && left_count > 0 && left_count < end - begin) best_cost = cost, best_split = b;
        }
        if (best_split < 0) return begin;
        auto middle = std::partition(primitives_.begin() + begin, primitives_.begin() + end,
                                     [&](const Primitive& p) { return bin_of(p) <= best_split; });
        return static_cast<std::uint32_t>(middle - primitives_.begin());
    }

    std::vector<Primitive> primitives_;
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

Bvh build_bvh(const FrameGeometry& frame) {
    const Vec3 origin = frame.impostor_origin();
    Bvh bvh = Builder(primitives_of(frame, origin)).build();
    bvh.origin = origin;
    return bvh;
}

std::vector<ClrBvhNode> compile_bvh(const Bvh& bvh, const Vec3& origin) {
    std::vector<ClrBvhNode> nodes;
    nodes.reserve(bvh.nodes.size());
    const Vec3 shift = origin - bvh.origin;  // zero when the frame's impostors were placed there
    for (const Bvh::Node& node : bvh.nodes) {
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
        out.first = node.first;
        out.count = node.count;
        nodes.push_back(out);
    }
    return nodes;
}

}  // namespace clr
