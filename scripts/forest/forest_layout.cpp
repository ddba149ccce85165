#include "scripts/forest/forest_layout.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

#include "scripts/forest/camera_flight.h"
#include "scripts/forest/noise.h"
#include "scripts/forest/random.h"

namespace forest {

using clr::Vec3;

namespace {

constexpr double kGroundPerTree = 30.0;  // square metres: a dense but walkable forest
constexpr double kMinimumSpacing = 2.2;  // between two trunks
constexpr double kMainClearingRadius = 20.0;
constexpr double kLoneTreeHeight = 9.5;
constexpr int kBoulderCount = 36;

// Rounds to millimetres so the JSON stays short; exact halves keep centre.y = height / 2 exact.
double round_mm(double value) { return std::round(value * 1000) / 1000; }

// A bucket grid of tree bases, to test spacing without comparing every pair.
class SpacingGrid {
public:
    bool has_neighbour_within(double x, double z, double distance) const {
        const int cx = cell(x), cz = cell(z);
        for (int dz = -1; dz <= 1; ++dz) {
            for (int dx = -1; dx <= 1; ++dx) {
                const auto found = cells_.find({cx + dx, cz + dz});
                if (found == cells_.end()) continue;
                for (const auto& [ox, oz] : found->second) {
                    if (std::hypot(ox - x, oz - z) < distance) return true;
                }
            }
        }
        return false;
    }
    void add(double x, double z) { cells_[{cell(x), cell(z)}].push_back({x, z}); }

private:
    static int cell(double v) { return static_cast<int>(std::floor(v / 4.0)); }
    std::map<std::pair<int, int>, std::vector<std::pair<double, double>>> cells_;
};

// Whether a tree at (x, z) of this size would come within the margin of the camera.
bool blocks_camera(const std::vector<Vec3>& eyes, double x, double z, double height, double width) {
    const double reach = width / 2 + kCameraMargin;
    for (const Vec3& eye : eyes) {
        if (eye.y < height + kCameraMargin && std::hypot(eye.x - x, eye.z - z) < reach) return true;
    }
    return false;
}

bool in_clearing(const std::vector<Clearing>& clearings, double x, double z, double extra) {
    for (const Clearing& c : clearings) {
        if (std::hypot(c.x - x, c.z - z) < c.radius + extra) return true;
    }
    return false;
}

std::vector<Clearing> plan_clearings(Random& random, double half_extent) {
    std::vector<Clearing> clearings{{0, 0, kMainClearingRadius}};
    while (clearings.size() < 7) {
        const Clearing candidate{random.uniform(-half_extent, half_extent), random.uniform(-half_extent, half_extent),
                                 random.uniform(6, 13)};
        if (!in_clearing(clearings, candidate.x, candidate.z, candidate.radius + 10)) clearings.push_back(candidate);
    }
    return clearings;
}

// Stands of one kind: spruce where a slow noise is high, birch groves where it is low.
TreeKind pick_kind(Random& random, double x, double z, std::uint32_t seed) {
    const double stand = value_noise(x / 45, z / 45, 0, seed);
    const double draw = random.unit();
    if (draw < 0.2 + 0.6 * stand) return TreeKind::Conifer;
    if (draw < 0.62 + 0.3 * stand) return TreeKind::Broadleaf;
    return TreeKind::Birch;
}

double pick_height(Random& random, TreeKind kind) {
    switch (kind) {
        case TreeKind::Conifer: return random.uniform(10, 17);
        case TreeKind::Broadleaf: return random.uniform(7, 11.5);
        case TreeKind::Birch: return random.uniform(8.5, 13.5);
    }
    return 10;
}

TreeInstance make_tree(TreeKind kind, double x, double z, double height, const std::array<double, 3>& aspect) {
    const double h = round_mm(height);
    return {kind, {round_mm(x), 0, round_mm(z)}, h, round_mm(h * aspect[static_cast<int>(kind)])};
}

void place_trees(ForestLayout& layout, Random& random, int count, const std::vector<Vec3>& eyes,
                 const std::array<double, 3>& aspect, std::uint32_t stand_seed) {
    SpacingGrid grid;
    layout.trees.push_back(make_tree(TreeKind::Broadleaf, 0, 0, kLoneTreeHeight, aspect));
    grid.add(0, 0);
    const long attempts_allowed = 400L * count + 10000;
    for (long attempt = 0; static_cast<int>(layout.trees.size()) < count; ++attempt) {
        if (attempt > attempts_allowed) throw std::runtime_error("the trees do not fit around the camera path");
        const double x = random.uniform(-layout.half_extent, layout.half_extent);
        const double z = random.uniform(-layout.half_extent, layout.half_extent);
        const TreeKind kind = pick_kind(random, x, z, stand_seed);
        const double height = pick_height(random, kind);
        if (in_clearing(layout.clearings, x, z, 0) || grid.has_neighbour_within(x, z, kMinimumSpacing)) continue;
        const TreeInstance tree = make_tree(kind, x, z, height, aspect);
        if (blocks_camera(eyes, tree.base.x, tree.base.z, tree.height, tree.width)) continue;
        layout.trees.push_back(tree);
        grid.add(tree.base.x, tree.base.z);
    }
}

Colour boulder_colour(Random& random) {
    const Colour grey{0.55, 0.55, 0.52}, brown{0.52, 0.43, 0.33}, moss{0.40, 0.46, 0.30};
    const Colour base = lerp(grey, brown, random.unit());
    return lerp(base, moss, random.uniform(0, 0.35)) * random.uniform(0.85, 1.1);
}

bool boulder_fits(const ForestLayout& layout, const std::vector<Vec3>& eyes, const Boulder& b) {
    for (const TreeInstance& tree : layout.trees) {
        if (std::hypot(tree.base.x - b.centre.x, tree.base.z - b.centre.z) < b.radius + 0.6) return false;
    }
    for (const Boulder& other : layout.boulders) {
        if (clr::length(other.centre - b.centre) < b.radius + other.radius) return false;
    }
    for (const Vec3& eye : eyes) {
        if (clr::length(eye - b.centre) < b.radius + kCameraMargin + 1) return false;
    }
    return true;
}

// Partly sunk rocks: a handful in the big clearing where the camera passes them, the rest in
// the other clearings and among the trees.
void place_boulders(ForestLayout& layout, Random& random, const std::vector<Vec3>& eyes) {
    for (int attempt = 0; attempt < 20000 && static_cast<int>(layout.boulders.size()) < kBoulderCount; ++attempt) {
        const double radius = random.uniform(0.5, 2.2);
        const int clearing = layout.boulders.size() < 8 ? 0 : random.below(static_cast<int>(layout.clearings.size()));
        const Clearing& near = layout.clearings[clearing];
        double x, z;
        if (layout.boulders.size() < 24) {
            const double angle = random.uniform(0, 6.2831853), distance = random.uniform(0.5, 1.0) * near.radius;
            x = near.x + distance * std::cos(angle);
            z = near.z + distance * std::sin(angle);
        } else {
            x = random.uniform(-layout.half_extent, layout.half_extent);
            z = random.uniform(-layout.half_extent, layout.half_extent);
        }
        const Boulder boulder{{round_mm(x), round_mm(radius * random.uniform(-0.45, 0.2)), round_mm(z)},
                              round_mm(radius), boulder_colour(random)};
        if (boulder_fits(layout, eyes, boulder)) layout.boulders.push_back(boulder);
    }
}

}  // namespace

ForestLayout plan_forest(const ForestOptions& options, const std::array<double, 3>& width_over_height) {
    if (options.trees < 1) throw std::runtime_error("a forest needs at least one tree");
    ForestLayout layout;
    layout.half_extent = std::max(95.0, std::sqrt(options.trees * kGroundPerTree) / 2);
    layout.camera = flight_keys();
    // Four samples a frame: the camera moves at most a metre or so between them.
    const std::vector<Vec3> eyes = sample_eyes(layout.camera, 4 * std::max(options.frames, 2));
    Random random(derive_seed(options.seed, 1));
    layout.clearings = plan_clearings(random, layout.half_extent);
    place_trees(layout, random, options.trees, eyes, width_over_height,
                static_cast<std::uint32_t>(derive_seed(options.seed, 2)));
    place_boulders(layout, random, eyes);
    return layout;
}

}  // namespace forest
