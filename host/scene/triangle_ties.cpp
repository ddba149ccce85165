#include "scene/triangle_ties.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <map>
#include <random>
#include <tuple>
#include <vector>

namespace clr {
namespace {

using Ties = std::array<std::int32_t, 6>;

std::uint64_t position_bits(double v) {
    if (v == 0) v = 0;  // +0 and -0 are one position
    std::uint64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    return bits;
}

// Seeded once a run: the numbers do not depend on it (first appearance decides them), but a
// file cannot be made whose positions all fall in one run of the table.
const std::uint64_t kHashSeed = (std::uint64_t(std::random_device{}()) << 32) ^ std::random_device{}();

std::uint64_t position_hash(const Vec3& p) {
    std::uint64_t h = (position_bits(p.x) ^ kHashSeed) * 0x9E3779B97F4A7C15ull;
    h = (h ^ (h >> 29) ^ position_bits(p.y)) * 0xBF58476D1CE4E5B9ull;
    h = (h ^ (h >> 31) ^ position_bits(p.z)) * 0x94D049BB133111EBull;
    return h ^ (h >> 32);
}

// A number for each of `count` positions (`at(i)`): equal positions, equal numbers, counted
// from 0 in order of first appearance. An open-addressing table, at most half full.
template <typename At>
std::vector<std::uint32_t> numbered(std::size_t count, const At& at, std::uint32_t& distinct) {
    std::size_t size = 16;
    while (size < 2 * count) size *= 2;
    constexpr std::uint32_t kEmpty = 0xFFFFFFFFu;
    std::vector<std::uint32_t> slots(size, kEmpty);  // the first position with each number
    std::vector<std::uint32_t> numbers(count);
    distinct = 0;
    for (std::uint32_t i = 0; i < count; ++i) {
        const Vec3& p = at(i);
        std::size_t slot = position_hash(p) & (size - 1);
        while (slots[slot] != kEmpty) {
            const Vec3& q = at(slots[slot]);
            if (p.x == q.x && p.y == q.y && p.z == q.z) break;
            slot = (slot + 1) & (size - 1);
        }
        if (slots[slot] == kEmpty) {
            slots[slot] = i;
            numbers[i] = distinct++;
        } else {
            numbers[i] = numbers[slots[slot]];
        }
    }
    return numbers;
}

bool same_position(const Vec3& a, const Vec3& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

// The two lowest triangles seen: the lowest other than t is the first unless that is t.
struct Lowest {
    std::int32_t first = -1, second = -1;
    void add(std::int32_t t) {
        if (first < 0 || t < first) {
            second = first;
            first = t;
        } else if (t != first && (second < 0 || t < second)) {
            second = t;
        }
    }
    std::int32_t other_than(std::int32_t t) const { return first != t ? first : second >= 0 ? second : t; }
};

// The ties of `triangles` (scene indices), among themselves, from the vertex numbers of their
// corners (three a triangle, `vertex_count` distinct): the lowest triangles around each vertex,
// and along each edge (a, b), a < b, listed under a and sorted, so that an edge or a vertex that
// a million triangles share (a fan, a file made to be slow) costs a sort, not a million scans.
void tie_group(Scene& scene, const std::vector<std::uint32_t>& triangles, const std::vector<std::uint32_t>& vertex,
               std::uint32_t vertex_count) {
    std::vector<Lowest> around(vertex_count);
    // Whether every corner at the vertex has a corner normal, all the same (1), or not (0).
    std::vector<std::uint8_t> smooth(vertex_count, 1);
    std::vector<const Vec3*> normal_at(vertex_count, nullptr);
    std::vector<std::uint32_t> start(vertex_count + 1, 0);
    const auto edge = [&](std::size_t t, int k) {
        const std::uint32_t a = vertex[3 * t + (k + 1) % 3], b = vertex[3 * t + (k + 2) % 3];
        return std::pair{std::min(a, b), std::max(a, b)};
    };
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        const Triangle& triangle = scene.triangles[triangles[t]];
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t v = vertex[3 * t + k];
            around[v].add(static_cast<std::int32_t>(triangles[t]));
            ++start[edge(t, k).first + 1];
            const Vec3* normal = triangle.normals >= 0 ? &scene.corner_normals[triangle.normals][k] : nullptr;
            if (!normal || (normal_at[v] && !same_position(*normal, *normal_at[v]))) smooth[v] = 0;
            normal_at[v] = normal;
        }
    }
    for (std::uint32_t v = 0; v < vertex_count; ++v) start[v + 1] += start[v];
    std::vector<std::pair<std::uint32_t, std::int32_t>> edges(start.back());  // (b, triangle) under a
    {
        std::vector<std::uint32_t> filled(start.begin(), start.end() - 1);
        for (std::size_t t = 0; t < triangles.size(); ++t)
            for (int k = 0; k < 3; ++k) {
                const auto [a, b] = edge(t, k);
                edges[filled[a]++] = {b, static_cast<std::int32_t>(triangles[t])};
            }
    }
    for (std::uint32_t v = 0; v < vertex_count; ++v)
        if (start[v + 1] - start[v] > 1) std::sort(edges.begin() + start[v], edges.begin() + start[v + 1]);
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        const std::int32_t self = static_cast<std::int32_t>(triangles[t]);
        Ties& ties = scene.triangle_ties[self];
        for (int k = 0; k < 3; ++k) {
            const auto [a, b] = edge(t, k);
            // The edge's entries, lowest triangle first: the lowest other is among the first two.
            const auto end = edges.begin() + start[a + 1];
            auto e = std::lower_bound(edges.begin() + start[a], end, std::pair{b, std::int32_t{-1}});
            Lowest along;
            for (int taken = 0; e != end && e->first == b && taken < 3; ++e, ++taken) along.add(e->second);
            const bool smooth_edge = smooth[a] && smooth[b];
            ties[k] = smooth_edge ? self : along.other_than(self);
            ties[3 + k] = smooth[vertex[3 * t + k]] ? self : around[vertex[3 * t + k]].other_than(self);
            for (int j : {k, 3 + k}) scene.has_triangle_ties |= ties[j] != self;
        }
    }
}

// tie_group() for triangles whose corners are numbered by position here.
void tie_by_corners(Scene& scene, const std::vector<std::uint32_t>& triangles) {
    std::uint32_t distinct = 0;
    const std::vector<std::uint32_t> vertex = numbered(
        triangles.size() * 3,
        [&](std::uint32_t c) -> const Vec3& { return scene.triangles[triangles[c / 3]].corners[c % 3]; }, distinct);
    tie_group(scene, triangles, vertex, distinct);
}

// Whether `triangle` has a corner at `p`.
bool has_corner(const Triangle& triangle, const Vec3& p) {
    return std::any_of(triangle.corners.begin(), triangle.corners.end(), [&](const Vec3& c) { return same_position(c, p); });
}

// Mesh `to` takes the ties of mesh `from` (the same file, scale and triangle count), shifted;
// false where a neighbour does not share the corners it should (the caller then finds them).
bool copy_ties(Scene& scene, const Mesh& from, const Mesh& to) {
    const auto shift = static_cast<std::int64_t>(to.first_triangle) - static_cast<std::int64_t>(from.first_triangle);
    for (std::size_t i = 0; i < to.triangle_count; ++i) {
        const std::size_t t = to.first_triangle + i;
        const Triangle& triangle = scene.triangles[t];
        Ties ties = scene.triangle_ties[from.first_triangle + i];
        for (int k = 0; k < 6; ++k) {
            const std::int64_t other = ties[k] + shift;
            if (other < static_cast<std::int64_t>(to.first_triangle) ||
                other >= static_cast<std::int64_t>(to.first_triangle + to.triangle_count))
                return false;
            ties[k] = static_cast<std::int32_t>(other);
            const Triangle& neighbour = scene.triangles[other];
            const int corner = k < 3 ? (k + 1) % 3 : k - 3;
            if (!has_corner(neighbour, triangle.corners[corner])) return false;
            if (k < 3 && !has_corner(neighbour, triangle.corners[(k + 2) % 3])) return false;
        }
        scene.triangle_ties[t] = ties;
        for (int k = 0; k < 6; ++k) scene.has_triangle_ties |= ties[k] != static_cast<std::int32_t>(t);
    }
    return true;
}

}  // namespace

void compute_triangle_ties(Scene& scene) {
    scene.triangle_ties.resize(scene.triangles.size());
    std::vector<std::uint32_t> surface_triangles;
    std::map<std::tuple<std::string, std::size_t, double, double, double>, std::size_t> first_of_shape;
    for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
        const Mesh& mesh = scene.meshes[m];
        const std::size_t end = std::min(scene.triangles.size(), mesh.first_triangle + mesh.triangle_count);
        if (mesh.first_triangle >= end || mesh.tied) continue;
        for (std::size_t t = mesh.first_triangle; t < end; ++t) scene.triangle_ties[t].fill(static_cast<std::int32_t>(t));
        if (mesh.surface_triangle) {
            for (std::size_t t = mesh.first_triangle; t < end; ++t) surface_triangles.push_back(static_cast<std::uint32_t>(t));
            continue;
        }
        if (!mesh.path.empty() && !mesh.placeholder) {
            const auto [it, first] = first_of_shape.emplace(
                std::tuple{mesh.path, mesh.triangle_count, mesh.scale.x, mesh.scale.y, mesh.scale.z}, m);
            if (!first && copy_ties(scene, scene.meshes[it->second], mesh)) continue;
        }
        std::vector<std::uint32_t> triangles(end - mesh.first_triangle);
        for (std::size_t i = 0; i < triangles.size(); ++i) triangles[i] = static_cast<std::uint32_t>(mesh.first_triangle + i);
        tie_by_corners(scene, triangles);
    }
    if (!surface_triangles.empty()) tie_by_corners(scene, surface_triangles);
}

void tie_placed_mesh(Scene& scene, std::size_t first_triangle, const std::vector<Vec3>& positions,
                     const std::vector<std::array<std::uint32_t, 3>>& corners) {
    if (scene.triangle_ties.size() < first_triangle + corners.size()) scene.triangle_ties.resize(first_triangle + corners.size());
    std::uint32_t distinct = 0;
    const std::vector<std::uint32_t> number =
        numbered(positions.size(), [&](std::uint32_t i) -> const Vec3& { return positions[i]; }, distinct);
    std::vector<std::uint32_t> triangles(corners.size()), vertex(3 * corners.size());
    for (std::size_t t = 0; t < corners.size(); ++t) {
        triangles[t] = static_cast<std::uint32_t>(first_triangle + t);
        for (int k = 0; k < 3; ++k) vertex[3 * t + k] = number[corners[t][k]];
    }
    tie_group(scene, triangles, vertex, distinct);
}

}  // namespace clr
