#include "scripts/forest/tree_views.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "scripts/forest/noise.h"

namespace forest {

using clr::Vec3;

namespace {

constexpr double kPi = 3.14159265358979323846;

// What a ray hit: where, the surface normal there, and which primitive.
struct Hit {
    double depth = -1e30;  // along the view direction: larger is nearer the eye
    Vec3 point, normal;
    Colour colour;
    Surface surface = Surface::Leaves;
};

// The primitives that one picture row (a horizontal slice at height y) cuts, each as a circle.
struct SliceCircle {
    double x, z, radius;
    const Ball* ball = nullptr;
    const Frustum* frustum = nullptr;
};

std::vector<SliceCircle> slice(const TreeModel& model, double y) {
    std::vector<SliceCircle> circles;
    for (const Ball& ball : model.balls) {
        const double dy = y - ball.centre.y;
        if (std::abs(dy) < ball.radius) {
            circles.push_back({ball.centre.x, ball.centre.z, std::sqrt(ball.radius * ball.radius - dy * dy), &ball});
        }
    }
    for (const Frustum& f : model.frusta) {
        if (y >= f.y0 && y <= f.y1) {
            const double radius = f.r0 + (f.r1 - f.r0) * (y - f.y0) / (f.y1 - f.y0);
            circles.push_back({f.x, f.z, radius, nullptr, &f});
        }
    }
    return circles;
}

Vec3 surface_normal(const SliceCircle& circle, const Vec3& point) {
    if (circle.ball) return (point - circle.ball->centre) / circle.ball->radius;
    const Frustum& f = *circle.frustum;
    const double slope = (f.r0 - f.r1) / (f.y1 - f.y0);
    return clr::normalize(Vec3((point.x - f.x) / circle.radius, slope, (point.z - f.z) / circle.radius));
}

// The nearest surface along the horizontal ray through `across` (on the picture's right axis)
// travelling against `direction`, or nothing.
std::optional<Hit> cast(const std::vector<SliceCircle>& circles, double y, double across, const Vec3& right,
                        const Vec3& direction) {
    std::optional<Hit> best;
    for (const SliceCircle& circle : circles) {
        const double offset = across - (circle.x * right.x + circle.z * right.z);
        if (std::abs(offset) >= circle.radius) continue;
        const double depth = circle.x * direction.x + circle.z * direction.z +
                             std::sqrt(circle.radius * circle.radius - offset * offset);
        if (best && depth <= best->depth) continue;
        Hit hit;
        hit.depth = depth;
        hit.point = {across * right.x + depth * direction.x, y, across * right.z + depth * direction.z};
        hit.normal = surface_normal(circle, hit.point);
        hit.colour = circle.ball ? circle.ball->colour : circle.frustum->colour;
        hit.surface = circle.ball ? circle.ball->surface : circle.frustum->surface;
        best = hit;
    }
    return best;
}

// Whether a leaf clump lies between `point` and the light: the shade inside a crown.
bool in_shadow(const TreeModel& model, const Vec3& point, const Vec3& towards_light) {
    for (const Ball& ball : model.balls) {
        const Vec3 to_centre = ball.centre - point;
        const double along = clr::dot(to_centre, towards_light);
        if (along <= 0) continue;
        const double miss_squared = clr::dot(to_centre, to_centre) - along * along;
        if (miss_squared < ball.radius * ball.radius) return true;
    }
    return false;
}

// Bark grain, birch marks or leaf speckle: how much brighter or darker a surface is here.
double texture_factor(const Hit& hit) {
    const Vec3& p = hit.point;
    const double angle = std::atan2(p.z, p.x);
    switch (hit.surface) {
        case Surface::Leaves: {
            const double speckle = hash_unit(static_cast<std::int32_t>(std::floor(p.x * 160)),
                                             static_cast<std::int32_t>(std::floor(p.y * 160)),
                                             static_cast<std::int32_t>(std::floor(p.z * 160)), 7u);
            return 0.78 + 0.4 * speckle * (0.6 + 0.4 * value_noise(p.x * 25, p.y * 25, p.z * 25, 3u));
        }
        case Surface::Bark: return 0.8 + 0.35 * value_noise(angle * 4, p.y * 90, 0, 11u);
        case Surface::BirchBark: {
            const double mark = value_noise(angle * 2.5, p.y * 110, 0, 13u) * value_noise(angle, p.y * 20, 5, 17u);
            return mark > 0.36 ? 0.18 : 0.92 + 0.1 * value_noise(angle * 6, p.y * 200, 0, 19u);
        }
    }
    return 1;
}

Colour shade(const TreeModel& model, const Hit& hit, const Vec3& towards_light) {
    // Partly wrapped round the shape: leaf clumps scatter light, so their far sides are not black.
    const double facing = clr::dot(hit.normal, towards_light);
    double direct = 0.6 * std::max(0.0, facing) + 0.4 * (0.5 + 0.5 * facing);
    if (direct > 0 && in_shadow(model, hit.point + hit.normal * 0.004, towards_light)) direct *= 0.25;
    // Lower parts of a crown get less sky: a cheap stand-in for ambient occlusion.
    const double sky = 0.32 + 0.16 * std::clamp(hit.point.y / model.top, 0.0, 1.0);
    return hit.colour * ((sky + 0.75 * direct) * texture_factor(hit));
}

}  // namespace

Vec3 view_direction(int index) {
    const double angle = index * 2 * kPi / kViewCount;
    return {std::sin(angle), 0, std::cos(angle)};
}

Canvas render_tree_view(const TreeModel& model, const Vec3& direction, const Vec3& towards_light, int picture_width,
                        int picture_height) {
    const Vec3 right{direction.z, 0, -direction.x};  // up x direction
    const double frame_top = model.top * 1.01;
    const double half_width = frame_top * picture_width / picture_height / 2;
    Canvas canvas(picture_width, picture_height);
    for (int row = 0; row < picture_height; ++row) {
        const double y = frame_top * (1 - (row + 0.5) / picture_height);
        const std::vector<SliceCircle> circles = slice(model, y);
        for (int column = 0; column < picture_width; ++column) {
            const double across = -half_width + (column + 0.5) * 2 * half_width / picture_width;
            if (const std::optional<Hit> hit = cast(circles, y, across, right, direction)) {
                canvas.at(column, row) = opaque(shade(model, *hit, towards_light));
            }
        }
    }
    return canvas;
}

TreePictures render_tree_pictures(TreeKind kind, const TreeModel& model, const Vec3& towards_light,
                                  int picture_height) {
    // Wide enough for the farthest reach in any direction, in whole pairs of texels.
    const double aspect = 2 * model.half_width * 1.02 / (model.top * 1.01);
    const int width = 2 * static_cast<int>(std::ceil(picture_height * aspect / 2));
    TreePictures pictures{kind, {}, static_cast<double>(width) / picture_height};
    for (int i = 0; i < kViewCount; ++i) {
        pictures.views.push_back(render_tree_view(model, view_direction(i), towards_light, width, picture_height));
    }
    return pictures;
}

}  // namespace forest
