// The reference's own bounding volume hierarchy over a scene's mesh triangles, so that
// --reference and --explain-pixel test the triangles a ray's boxes reach instead of every
// triangle of every mesh (a mesh of 70,000 triangles would take each ray 70,000 tests).
// Written for the reference, independently of the renderer's (render/bvh): median splits in
// double, boxes widened by a margin far above double rounding, so that a ray is never kept
// from a triangle it meets; the nearest hit is then the same as testing every triangle
// (ties go to the lowest index in both).
#pragma once

#include <cstdint>
#include <vector>

#include "reference/reference.h"

namespace clr::reference {

class TriangleTree {
public:
    explicit TriangleTree(const std::vector<Triangle>& triangles);

    // Calls visit(index) for each triangle whose box the ray's segment (0, t_max) may reach.
    // `t_max` is read before each box, so a visit that shortens it prunes the rest.
    template <typename Visit>
    void visit(const Ray& ray, const double& t_max, Visit&& visit) const {
        if (nodes_.empty()) return;
        std::uint32_t stack[128];
        int top = 0;
        stack[top++] = 0;
        while (top > 0) {
            const Node& node = nodes_[stack[--top]];
            if (!reaches(node, ray, t_max)) continue;
            if (node.count == 0) {
                stack[top++] = node.first + 1;
                stack[top++] = node.first;
                continue;
            }
            for (std::uint32_t k = node.first; k < node.first + node.count; ++k) visit(static_cast<int>(items_[k]));
        }
    }

private:
    struct Node {
        Vec3 lower, upper;
        std::uint32_t first = 0;  // inner node: left child (the right one is first + 1); leaf: first item
        std::uint32_t count = 0;  // leaf: its triangles; 0: an inner node
    };
    static bool reaches(const Node& node, const Ray& ray, double t_max);
    void build(std::uint32_t node, std::uint32_t begin, std::uint32_t end, const std::vector<Vec3>& centres,
               const std::vector<Triangle>& triangles, int depth);

    std::vector<Node> nodes_;
    std::vector<std::uint32_t> items_;
};

}  // namespace clr::reference
