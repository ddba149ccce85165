#include "scripts/forest/tree_models.h"

#include <algorithm>
#include <cmath>

#include "scripts/forest/random.h"

namespace forest {

using clr::Vec3;

std::string kind_name(TreeKind kind) {
    switch (kind) {
        case TreeKind::Conifer: return "spruce";
        case TreeKind::Broadleaf: return "oak";
        case TreeKind::Birch: return "birch";
    }
    return "tree";
}

namespace {

constexpr double kPi = 3.14159265358979323846;

Colour vary(Random& random, const Colour& colour, double amount) {
    const double brightness = random.uniform(1 - amount, 1 + amount);
    return {colour.x * brightness, colour.y * random.uniform(1 - amount / 2, 1 + amount / 2) * brightness,
            colour.z * brightness};
}

// A point at `radius` from `centre` in a random direction (uniform over the sphere).
Vec3 random_on_sphere(Random& random, const Vec3& centre, double radius) {
    const double y = random.uniform(-1, 1), angle = random.uniform(0, 2 * kPi);
    const double ring = std::sqrt(1 - y * y);
    return centre + Vec3(ring * std::cos(angle), y, ring * std::sin(angle)) * radius;
}

// A leaf clump: many small balls on and inside a sphere, so that its outline is ragged.
void add_clump(TreeModel& model, Random& random, const Vec3& centre, double radius, const Colour& colour, int leaves) {
    model.balls.push_back({centre, radius * 0.8, colour * 0.75, Surface::Leaves});
    for (int i = 0; i < leaves; ++i) {
        const Vec3 at = random_on_sphere(random, centre, radius * random.uniform(0.6, 1.0));
        model.balls.push_back({at, radius * random.uniform(0.22, 0.36), vary(random, colour, 0.15), Surface::Leaves});
    }
}

// A branch as a row of balls from `from` to `to`, thinning towards its tip.
void add_branch(TreeModel& model, const Vec3& from, const Vec3& to, double radius, const Colour& colour) {
    const int steps = std::max(2, static_cast<int>(clr::length(to - from) / (radius * 0.7)));
    for (int i = 0; i <= steps; ++i) {
        const double t = static_cast<double>(i) / steps;
        model.balls.push_back({from + (to - from) * t, radius * (1 - 0.5 * t), colour, Surface::Bark});
    }
}

Vec3 horizontal(double angle, double distance, double y) {
    return {distance * std::cos(angle), y, distance * std::sin(angle)};
}

// A spruce: tiers of dark cones, needle clumps on their rims, one dead branch low on one side
// and a patch of fresh light-green growth with cones on another.
void build_conifer(TreeModel& model, Random& random) {
    const Colour bark{0.33, 0.22, 0.14}, needles{0.10, 0.30, 0.15};
    model.frusta.push_back({0, 0, -0.01, 0.96, 0.032, 0.006, bark, Surface::Bark});
    const int tiers = 8;
    for (int i = 0; i < tiers; ++i) {
        const double y0 = 0.12 + i * 0.105, fraction = static_cast<double>(i) / tiers;
        const double reach = (0.25 * (1 - fraction) + 0.03) * random.uniform(0.9, 1.1);
        const Colour tier = vary(random, needles, 0.1);
        model.frusta.push_back({0, 0, y0, y0 + 0.2, reach, 0.015, tier * 0.85, Surface::Leaves});
        for (int k = 0; k < 60; ++k) {
            const double angle = random.uniform(0, 2 * kPi), along = random.uniform(0.0, 0.9);
            const double y = y0 + 0.2 * along;
            const double r = (reach + (0.015 - reach) * along) * random.uniform(0.92, 1.1);
            model.balls.push_back({horizontal(angle, r, y - 0.01), random.uniform(0.012, 0.022), vary(random, tier * 1.1, 0.12),
                                   Surface::Leaves});
        }
    }
    model.balls.push_back({{0, 0.985, 0}, 0.02, needles, Surface::Leaves});
    const double dead_side = random.uniform(0, 2 * kPi);
    add_branch(model, horizontal(dead_side, 0.02, 0.2), horizontal(dead_side, 0.33, 0.17), 0.012, {0.42, 0.33, 0.25});
    const double fresh_side = dead_side + random.uniform(1.8, 2.6);
    for (int k = 0; k < 30; ++k) {
        const double y = random.uniform(0.3, 0.6), reach = 0.25 * (1 - (y - 0.12) / 0.84) + 0.03;
        model.balls.push_back({horizontal(fresh_side + random.uniform(-0.5, 0.5), reach, y), random.uniform(0.014, 0.024),
                               vary(random, {0.45, 0.62, 0.18}, 0.1), Surface::Leaves});
    }
    for (int k = 0; k < 5; ++k) {
        const double y = random.uniform(0.6, 0.85), reach = 0.25 * (1 - (y - 0.12) / 0.84) + 0.03;
        model.balls.push_back({horizontal(fresh_side + random.uniform(-0.4, 0.4), reach, y), 0.0075,
                               {0.36, 0.22, 0.12}, Surface::Bark});
    }
}

// An oak: a short trunk forking into a broad crown of clumps; one long branch reaches out on
// one side, and the clumps on that side have turned autumn orange.
void build_broadleaf(TreeModel& model, Random& random) {
    const Colour bark{0.30, 0.22, 0.15}, leaves{0.20, 0.42, 0.14}, autumn{0.80, 0.42, 0.10};
    model.frusta.push_back({0, 0, -0.01, 0.45, 0.06, 0.038, bark, Surface::Bark});
    const double reach_side = random.uniform(0, 2 * kPi);
    for (int i = 0; i < 3; ++i) {
        const double angle = reach_side + i * 2.1;
        add_branch(model, {0, 0.38, 0}, horizontal(angle, 0.16, 0.56), 0.034, bark);
    }
    const Vec3 crown{0, 0.64, 0};
    for (int i = 0; i < 22; ++i) {
        const double angle = random.uniform(0, 2 * kPi), out = std::sqrt(random.unit());
        const Vec3 at = crown + Vec3(std::cos(angle) * out * 0.25, random.uniform(-0.16, 0.2), std::sin(angle) * out * 0.25);
        const bool turned = std::cos(angle - reach_side) > 0.8 && out > 0.5;
        const Colour colour = turned ? lerp(leaves, autumn, random.uniform(0.7, 1.0)) : vary(random, leaves, 0.12);
        add_clump(model, random, at, random.uniform(0.08, 0.12), colour, 24);
    }
    const Vec3 tip = horizontal(reach_side, 0.36, 0.5);
    add_branch(model, {0, 0.38, 0}, tip, 0.022, bark);
    add_clump(model, random, tip + Vec3(0, 0.03, 0), 0.085, lerp(leaves, autumn, 0.9), 18);
}

// A birch: a slender white trunk with a slight kink, a narrow hanging crown of small light
// leaves, and one side branch carrying a yellow clump.
void build_birch(TreeModel& model, Random& random) {
    const Colour bark{0.88, 0.86, 0.80}, leaves{0.36, 0.56, 0.20}, yellow{0.86, 0.76, 0.22};
    const double lean = random.uniform(0, 2 * kPi);
    const double segment = 0.2;
    for (int i = 0; i < 5; ++i) {
        const double offset = 0.012 * i * i / 4.0;
        const double r0 = 0.024 - 0.0035 * i, r1 = 0.024 - 0.0035 * (i + 1);
        model.frusta.push_back({offset * std::cos(lean), offset * std::sin(lean), i * segment - (i == 0 ? 0.01 : 0),
                                (i + 1) * segment + 0.005, r0, r1, bark, Surface::BirchBark});
    }
    for (int i = 0; i < 16; ++i) {
        const double y = random.uniform(0.4, 0.93), angle = random.uniform(0, 2 * kPi);
        const double width = 0.13 * std::sin(kPi * (y - 0.3) / 0.72) + 0.02;
        add_clump(model, random, horizontal(angle, random.uniform(0.0, width), y), random.uniform(0.05, 0.075),
                  vary(random, leaves, 0.12), 14);
    }
    const double side = lean + kPi * 0.6;
    const Vec3 tip = horizontal(side, 0.26, 0.55);
    add_branch(model, horizontal(side, 0.0, 0.45), tip, 0.012, bark);
    add_clump(model, random, tip, 0.065, yellow, 16);
}

void measure(TreeModel& model) {
    model.top = 0;
    model.half_width = 0;
    for (const Ball& ball : model.balls) {
        model.top = std::max(model.top, ball.centre.y + ball.radius);
        model.half_width = std::max(model.half_width, std::hypot(ball.centre.x, ball.centre.z) + ball.radius);
    }
    for (const Frustum& f : model.frusta) {
        model.top = std::max(model.top, f.y1);
        model.half_width = std::max(model.half_width, std::hypot(f.x, f.z) + std::max(f.r0, f.r1));
    }
}

}  // namespace

TreeModel build_tree_model(TreeKind kind, std::uint64_t seed) {
    TreeModel model;
    Random random(seed);
    switch (kind) {
        case TreeKind::Conifer: build_conifer(model, random); break;
        case TreeKind::Broadleaf: build_broadleaf(model, random); break;
        case TreeKind::Birch: build_birch(model, random); break;
    }
    measure(model);
    return model;
}

}  // namespace forest
