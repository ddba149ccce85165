// The billboard kind in the double-precision reference renderer (billboard_kind.h).
#include <algorithm>
#include <cmath>

#include "kinds/billboard_kind.h"
#include "reference/geometry.h"
#include "reference/trace_observer.h"

namespace clr {

using reference::HitKind;
using reference::detail::billboard_plane_hit;
using reference::detail::inside_unit_square;
using reference::detail::is_leaving;
using reference::detail::is_textured;
using reference::detail::PlaneHit;
using reference::detail::texel_at;
using reference::detail::texel_is_opaque;

namespace {

// A billboard point counts as a hit unless it lies on a transparent texel, which lets the
// ray through as if the billboard were not there (docs/scene-format.md, Conventions: Billboards).
bool billboard_blocks(const Billboard& billboard, double a, double b) {
    if (!inside_unit_square(a, b)) return false;
    if (!is_textured(billboard)) return true;
    return texel_is_opaque(*billboard.image, texel_at(*billboard.image, a, b));
}

// Euclidean distance in (a, b) from the point to the boundary of the unit square, inside or
// outside: (a, b) measures in units of the billboard's edges, so this is relative to its size.
double square_edge_distance(double a, double b) {
    const double outside_a = std::max({-a, 0.0, a - 1});
    const double outside_b = std::max({-b, 0.0, b - 1});
    if (outside_a > 0 || outside_b > 0) return std::hypot(outside_a, outside_b);
    return std::min({a, 1 - a, b, 1 - b});
}

// Distance in (a, b) to the nearest line between texels: lines sit at a = k/W and b = k/H.
double texel_edge_distance(const Image& image, double a, double b) {
    const double texels_a = a * image.width;
    const double texels_b = b * image.height;
    return std::min(std::abs(texels_a - std::round(texels_a)) / image.width,
                    std::abs(texels_b - std::round(texels_b)) / image.height);
}

}  // namespace

HitKind BillboardKind::reference_kind() { return HitKind::Billboard; }

void BillboardKind::reference_nearest(const Scene& scene, const reference::Ray& ray,
                                      const reference::SurfaceId& leaving, double& nearest_t, reference::Hit& nearest,
                                      reference::TraceObserver* observer) {
    for (int i = 0; i < static_cast<int>(scene.billboards.size()); ++i) {
        if (is_leaving(leaving, HitKind::Billboard, i)) continue;
        const auto plane = billboard_plane_hit(scene.billboards[i], ray);
        const bool accepted = plane.meets && plane.t > 0 && plane.t < nearest_t &&
                              billboard_blocks(scene.billboards[i], plane.a, plane.b);
        if (observer) observer->billboard_tested(i, plane, nearest_t, accepted);
        if (!accepted) continue;
        nearest_t = plane.t;
        nearest = {HitKind::Billboard, i, plane.t, plane.a, plane.b};
    }
}

double BillboardKind::reference_margin(const Scene& scene, const reference::Ray& ray, double t_max,
                                       const reference::SurfaceId& leaving, std::vector<double>& hit_ts) {
    double margin = reference::kInfinity;
    for (int i = 0; i < static_cast<int>(scene.billboards.size()); ++i) {
        if (is_leaving(leaving, HitKind::Billboard, i)) continue;
        const Billboard& billboard = scene.billboards[i];
        const PlaneHit plane = billboard_plane_hit(billboard, ray);
        if (!plane.meets || plane.t <= 0 || plane.t >= t_max) continue;
        margin = std::min(margin, square_edge_distance(plane.a, plane.b));
        if (!inside_unit_square(plane.a, plane.b)) continue;
        if (is_textured(billboard)) {
            const Image& image = *billboard.image;
            margin = std::min(margin, texel_edge_distance(image, plane.a, plane.b));
            if (!texel_is_opaque(image, texel_at(image, plane.a, plane.b))) continue;
        }
        hit_ts.push_back(plane.t);
    }
    return margin;
}

Vec3 BillboardKind::reference_normal(const Scene& scene, int index, const Vec3&, const Vec3&) {
    return reference::detail::billboard_front_normal(scene.billboards[index]);
}

bool BillboardKind::reference_is_mirror(const Scene& scene, int index) { return scene.billboards[index].is_mirror; }

// Its flat colour, or the texel under the hit (intersect() only returns opaque texels, so the
// texel's alpha needs no blending).
reference::ColourSource BillboardKind::reference_own_color(const Scene& scene, const reference::Hit& hit,
                                                           Color& colour) {
    const Billboard& billboard = scene.billboards[hit.index];
    if (!is_textured(billboard)) {
        colour = billboard.ambient;
        return reference::ColourSource::BillboardAmbient;
    }
    colour = reference::detail::texel_color(*billboard.image, texel_at(*billboard.image, hit.a, hit.b));
    return reference::ColourSource::BillboardTexel;
}

const Color& BillboardKind::reference_ambient(const Scene& scene, int index) { return scene.billboards[index].ambient; }

}  // namespace clr
