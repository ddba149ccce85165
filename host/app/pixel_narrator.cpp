#include "app/pixel_narrator.h"

#include <cmath>

#include <cstdio>

#include "kinds/kinds.h"

namespace clr {

using reference::ColourSource;
using reference::HitKind;
using reference::RayRole;
using reference::detail::PlaneHit;
using reference::detail::SphereRoots;

std::string explain_number(double value) {
    char text[40];
    // -0 (a normal's zero component, say) reads as a different number to a reader: print 0.
    std::snprintf(text, sizeof text, "%.9g", value == 0 ? 0.0 : value);
    return text;
}

std::string explain_vector(const Vec3& value) {
    return "(" + explain_number(value.x) + ", " + explain_number(value.y) + ", " + explain_number(value.z) + ")";
}

namespace {

const char* role_name(RayRole role) {
    switch (role) {
        case RayRole::Primary: return "primary ray";
        case RayRole::Reflected: return "reflected ray";
        case RayRole::Shadow: return "shadow ray";
    }
    return "ray";
}

std::string colour_text(const Color& colour) { return explain_vector(colour); }

}  // namespace

std::string PixelNarrator::surface_name(HitKind kind, int index) const {
    if (kind == HitKind::Sphere) return "sphere " + std::to_string(index);
    if (kind == HitKind::Plane) return "plane " + std::to_string(index);
    if (kind == HitKind::Triangle) {
        const Triangle& triangle = scene_.triangles[index];
        const Mesh& mesh = scene_.meshes[triangle.mesh];
        return "triangle " + std::to_string(index - mesh.first_triangle) + " of mesh " + std::to_string(triangle.mesh) +
               " ('" + mesh.filename + "')";
    }
    if (index < own_billboards_) return "billboard " + std::to_string(index);
    return "impostor " + std::to_string(index - own_billboards_) + " (placed as billboard " + std::to_string(index) + ")";
}

std::string PixelNarrator::bound_name() const {
    if (found_in_search_) return "the nearest hit so far";
    if (role_ == RayRole::Shadow) return scene_.lit_by_lights() ? "the light's distance" : "the sun's distance";
    return "the search's limit";
}

void PixelNarrator::sample_started(int sample, int samples, double ox, double oy, const Vec3& witness_direction,
                                   const reference::Ray& ray) {
    out_ << "\n== Sample " << sample << " of " << samples << ": image point (j + " << explain_number(ox) << ", i + "
         << explain_number(oy) << ") ==\n";
    // The image point on [-1, 1]^2, as reference::witness_direction() maps it (row 0 on top).
    out_ << "x = 2(j + " << explain_number(ox) << ")/n_x - 1 = " << explain_number(2.0 * (col_ + ox) / camera_.width - 1.0)
         << ", y = 1 - 2(i + " << explain_number(oy) << ")/n_y = "
         << explain_number(1.0 - 2.0 * (row_ + oy) / camera_.height) << "\n";
    out_ << "witness point P(i, j) = Eye - D w + x hw u + y hh v (D = 1) = "
         << position(ray.origin + witness_direction) << "\n";
    out_ << "P(i, j) - Eye = " << explain_vector(witness_direction) << "\n";
    out_ << "ray o + t d: o = Eye = " << position(ray.origin)
         << ", d = unit(P(i, j) - Eye) = " << explain_vector(ray.direction) << "\n";
}

void PixelNarrator::sample_finished(int sample, const Color& colour) {
    out_ << "sample " << sample << " colour = " << colour_text(colour) << "\n";
}

void PixelNarrator::ray_cast(RayRole role, int depth, const reference::Ray& ray, double t_max) {
    role_ = role;
    ray_ = ray;
    clip_start_ = 0;
    found_in_search_ = false;
    out_ << "\n-- " << role_name(role);
    if (role == RayRole::Reflected)
        out_ << " " << depth << " of at most MaxDepth = " << scene_.max_depth << " (r = d - 2(d.n)n)";
    out_ << ": o = " << position(ray.origin) << ", d = " << explain_vector(ray.direction);
    if (role == RayRole::Shadow)
        out_ << ", 0 < t < " << explain_number(t_max)
             << (scene_.lit_by_lights() ? " (the light's distance)" : " (the sun's distance)");
    out_ << "\n";
}

void PixelNarrator::search_clipped(const reference::Ray& kept, double t_start, double t_end) {
    ray_ = kept;
    clip_start_ = t_start;
    out_ << "the camera keeps depths from near to far: t from " << explain_number(t_start)
         << (std::isfinite(t_end) ? " to " + explain_number(t_end) : std::string(" on (no far)"))
         << " along this ray; the search starts on the near plane at o' = o + "
         << explain_number(t_start) << " d = " << position(kept.origin)
         << "; in the tests below, o is o' and t counts from it\n";
}

void PixelNarrator::sphere_tested(int index, const SphereRoots& roots, double t_max, double t) {
    const Sphere& sphere = scene_.spheres[index];
    // The reference computes B/2 and (B/2)^2 - AC; the lecture's B and B^2 - 4AC are 2x and 4x them.
    out_ << surface_name(HitKind::Sphere, index) << " (c = " << position(sphere.center)
         << ", R = " << explain_number(sphere.radius) << "): A = d.d = 1, B = 2 d.(o - c) = "
         << explain_number(2 * roots.half_b) << ", C = (o - c).(o - c) - R^2 = " << explain_number(roots.c)
         << ", discriminant B^2 - 4AC = " << explain_number(4 * roots.quarter_discriminant) << "\n    ";
    if (!roots.real) {
        out_ << "miss: the discriminant is negative, the ray's line passes the sphere by\n";
        return;
    }
    out_ << "roots t = " << explain_number(roots.t_near) << ", " << explain_number(roots.t_far) << ": ";
    if (t < t_max) {
        out_ << "hit at t = " << explain_number(t)
             << (roots.t_near > 0 ? "" : " (the far root: o is inside the sphere)") << ", the nearest so far\n";
        found_in_search_ = true;
        return;
    }
    const double nearer = roots.t_near > 0 ? roots.t_near : roots.t_far;
    if (nearer <= 0)
        out_ << "rejected: behind the ray's origin (no root t > 0)\n";
    else
        out_ << "rejected: t = " << explain_number(nearer) << " is not nearer than " << bound_name() << " ("
             << explain_number(t_max) << ")\n";
}

void PixelNarrator::describe_billboard_plane(const PlaneHit& plane) const {
    out_ << "t_hit = ((UL - o).n) / (d.n) = " << explain_number(plane.t)
         << ", point o + t_hit d = " << position(reference::detail::point_at(ray_, plane.t))
         << ", (alpha, beta) = (" << explain_number(plane.a) << ", " << explain_number(plane.b) << ")";
}

void PixelNarrator::billboard_tested(int index, const PlaneHit& plane, double t_max, bool accepted) {
    const Billboard& billboard = scene_.billboards[index];
    out_ << surface_name(HitKind::Billboard, index) << " (UL = " << position(billboard.upper_left)
         << ", UR = " << position(billboard.upper_right) << ", LL = " << position(billboard.lower_left)
         << (billboard.is_mirror ? ", a mirror" : "") << ")\n    ";
    if (!plane.meets) {
        out_ << "miss: the ray is parallel to the billboard's plane (d.n = 0)\n";
        return;
    }
    describe_billboard_plane(plane);
    out_ << "\n    ";
    if (plane.t <= 0) {
        out_ << "rejected: the plane is behind the ray's origin (t_hit <= 0)\n";
        return;
    }
    if (plane.t >= t_max) {
        out_ << "rejected: not nearer than " << bound_name() << " (" << explain_number(t_max) << ")\n";
        return;
    }
    if (!reference::detail::inside_unit_square(plane.a, plane.b)) {
        out_ << "miss: outside the billboard (alpha or beta outside [0, 1])\n";
        return;
    }
    if (reference::detail::is_textured(billboard)) {
        const Image& image = *billboard.image;
        const auto texel = reference::detail::texel_at(image, plane.a, plane.b);
        out_ << "inside; texel (column " << texel.col << ", row " << texel.row << ") of the " << image.width << "x"
             << image.height << " image, alpha " << static_cast<int>(image.at(texel.col, texel.row, 3)) << ": ";
        if (!accepted) {
            out_ << "a hole (alpha < 255), rejected: the ray goes through\n";
            return;
        }
    } else {
        out_ << "inside: ";
    }
    out_ << (accepted ? "hit, the nearest so far\n" : "rejected\n");
    if (accepted) found_in_search_ = true;
}

// In the lecture's terms: the ray meets the triangle's plane at t_hit, and the point there is
// inside when the orientation test of each edge with the point turns the same way as the
// triangle's corners (counter-clockwise about n); the three tests over |n|^2 are the point's
// barycentric coordinates. Only triangles the point falls inside are narrated.
void PixelNarrator::triangle_tested(int index, const reference::detail::TriangleTest& test, double t_max,
                                    bool accepted) {
    if (!test.meets_plane || !test.inside) {
        ++triangles_missed_;
        return;
    }
    const Triangle& triangle = scene_.triangles[index];
    out_ << surface_name(HitKind::Triangle, index) << " (c0 = " << position(triangle.corners[0])
         << ", c1 = " << position(triangle.corners[1]) << ", c2 = " << position(triangle.corners[2]) << ")\n    ";
    out_ << "plane n = (c1 - c0) x (c2 - c0), t_hit = ((c0 - o).n) / (d.n) = " << explain_number(test.t)
         << ", point " << position(reference::detail::point_at(ray_, test.t))
         << "; orientation tests: the point is on the inner side of all three edges, barycentric (b0, b1, b2) = ("
         << explain_number(test.weights[0]) << ", " << explain_number(test.weights[1]) << ", "
         << explain_number(test.weights[2]) << ")\n    ";
    if (test.t <= 0)
        out_ << "rejected: the plane is behind the ray's origin (t_hit <= 0)\n";
    else if (!test.ahead)
        out_ << "rejected: t_hit is within rounding of the point the ray leaves (a neighbour of its triangle)\n";
    else if (test.t >= t_max)
        out_ << "rejected: not nearer than " << bound_name() << " (" << explain_number(t_max) << ")\n";
    else if (accepted)
        out_ << "hit, the nearest so far\n";
    else
        out_ << "rejected\n";
    if (accepted) found_in_search_ = true;
}

void PixelNarrator::plane_tested(int index, double t) {
    const Plane& plane = scene_.planes[index];
    out_ << surface_name(HitKind::Plane, index) << " (P0 = " << position(plane.point) << ", n = " << explain_vector(plane.normal)
         << "): t = ((P0 - o).n) / (d.n)";
    if (t < reference::kInfinity) {
        out_ << " = " << explain_number(t) << ": hit, the nearest so far\n";
        found_in_search_ = true;
    } else {
        out_ << ": rejected (d.n = 0, t <= 0, or not nearer than " << bound_name() << ")\n";
    }
}

void PixelNarrator::light_seen(int index, double cosine, bool hidden, double highlight) {
    const PointLight& light = scene_.lights[index];
    out_ << "light " << index << " at " << position(light.position) << ", colour " << colour_text(light.color)
         << ": n.l = " << explain_number(cosine);
    if (cosine <= 0)
        out_ << ": behind the surface, not counted\n";
    else if (hidden)
        out_ << ": hidden, not counted\n";
    else
        out_ << ", max(0, n.h)^p = " << explain_number(highlight) << ": adds I (k_d n.l + k_s max(0, n.h)^p)\n";
}

void PixelNarrator::nearest_found(const reference::Hit& hit) {
    if (triangles_missed_ > 0) {
        out_ << triangles_missed_ << (triangles_missed_ == 1 ? " triangle" : " triangles")
             << ": the ray passes outside (an orientation test fails) or runs parallel to the plane\n";
        triangles_missed_ = 0;
    }
    if (role_ == RayRole::Shadow) {
        shadowed_ = hit.kind != HitKind::None;
        if (shadowed_)
            out_ << "blocked by " << surface_name(hit.kind, hit.index) << " at t = " << explain_number(hit.t)
                 << ": the point is in shadow, s = 0\n";
        else if (scene_.lit_by_lights())
            out_ << "nothing blocks the light\n";
        else
            out_ << "nothing blocks the sun: s = 1\n";
        return;
    }
    if (hit.kind == HitKind::None)
        out_ << "nearest: nothing\n";
    else
        out_ << "nearest: " << surface_name(hit.kind, hit.index) << " at t = " << explain_number(hit.t + clip_start_)
             << (clip_start_ > 0 ? " from the eye (t = " + explain_number(hit.t) + " from o')" : "") << "\n";
}

void PixelNarrator::hit_settled(const reference::Hit& hit, const reference::TieSettled& tie) {
    const std::string corner = "c" + std::to_string(tie.k);
    const std::string edge = "c" + std::to_string((tie.k + 1) % 3) + "-c" + std::to_string((tie.k + 2) % 3);
    out_ << "the hit point lies on " << (tie.at_corner ? "corner " + corner : "edge " + edge) << " of "
         << surface_name(HitKind::Triangle, hit.index) << " to within the band t 2^-20 = " << explain_number(tie.band)
         << (tie.at_corner ? " (|P - " + corner + "|_1 = " : " (its distance |(P - a) x e|_1 / |e|_1 = ")
         << explain_number(tie.measure) << "): ";
    const std::string where = tie.at_corner ? "corner" : "edge";
    if (tie.other == hit.index)
        out_ << "no other triangle of its mesh shares that " << where << ", so it is shaded as itself\n";
    else if (tie.shaded == hit.index)
        out_ << "it is the lowest-numbered triangle there (beside " << surface_name(HitKind::Triangle, tie.other)
             << "), so it is shaded as itself whichever side of the " << where << " the rounding took; shadow and "
             << "reflected rays leave both\n";
    else
        out_ << "the lowest-numbered triangle there is " << surface_name(HitKind::Triangle, tie.shaded)
             << ", shaded in its place whichever side of the " << where << " the rounding took; shadow and "
             << "reflected rays leave both\n";
}

void PixelNarrator::surface_reached(const reference::Hit& hit, const reference::detail::SurfacePoint& surface) {
    surface_hit_ = hit;
    surface_ = surface;
    out_ << "hit point o + t d = " << position(surface.point) << ", normal n = " << explain_vector(surface.normal)
         << (surface.is_mirror ? ", a mirror" : "") << "\n";
}

void PixelNarrator::sun_seen(const reference::detail::SunDirection& sun, double cosine) {
    cosine_ = cosine;
    shadowed_ = false;
    out_ << "sun at " << position(scene_.sun_location) << ": l = unit(sun - point) = " << explain_vector(sun.l)
         << ", distance " << explain_number(sun.distance) << ", n.l = " << explain_number(cosine)
         << (cosine <= 0 ? ": the point faces away from the sun, no shadow ray" : "") << "\n";
}

void PixelNarrator::colour_found(ColourSource source, const Color& colour) {
    switch (source) {
        case ColourSource::Background:
            out_ << "colour: the background " << colour_text(colour) << " (the ray hits nothing)\n";
            break;
        case ColourSource::DepthExhausted:
            out_ << "colour: the background " << colour_text(colour) << " (a mirror, but MaxDepth = "
                 << scene_.max_depth << " reflections are used up)\n";
            break;
        case ColourSource::BackOfMirror:
            out_ << "colour: black (the back of a mirror)\n";
            break;
        case ColourSource::SphereAmbient:
            out_ << "colour: the sphere's ambient colour " << colour_text(colour) << " (unlit)\n";
            break;
        case ColourSource::SunLit: {
            Color ambient;
            for_each_kind([&](auto kind) {
                using Kind = decltype(kind);
                if (surface_hit_.kind == Kind::reference_kind()) ambient = Kind::reference_ambient(scene_, surface_hit_.index);
            });
            out_ << "colour = ambient * max(0, n.l) * s = " << colour_text(ambient) << " * "
                 << explain_number(cosine_ > 0 ? cosine_ : 0) << " * " << (cosine_ > 0 && !shadowed_ ? 1 : 0) << " = "
                 << colour_text(colour) << "\n";
            break;
        }
        case ColourSource::PlaneAmbient:
            out_ << "colour: the plane's ambient colour " << colour_text(colour) << " (unlit)\n";
            break;
        case ColourSource::PhongLit: {
            const Material& material = reference::detail::material_of(scene_, surface_hit_);
            out_ << "colour = ambient + sum over the lights counted of I (k_d n.l + k_s max(0, n.h)^p), k_d = "
                 << colour_text(material.diffuse) << ", k_s = " << colour_text(material.specular)
                 << ", p = " << explain_number(material.phong_exponent) << ": " << colour_text(colour) << "\n";
            if (!(material.mirror == Color{0, 0, 0}))
                out_ << "then k_m = " << colour_text(material.mirror) << " times the reflected ray's colour is added\n";
            break;
        }
        case ColourSource::MeshAmbient:
            out_ << "colour: the mesh's ambient colour " << colour_text(colour) << " (unlit)\n";
            break;
        case ColourSource::BillboardAmbient:
            out_ << "colour: the billboard's flat colour " << colour_text(colour) << "\n";
            break;
        case ColourSource::BillboardTexel: {
            const Image& image = *scene_.billboards[surface_hit_.index].image;
            const auto texel = reference::detail::texel_at(image, surface_hit_.a, surface_hit_.b);
            out_ << "colour: texel (column " << texel.col << ", row " << texel.row << ") = bytes "
                 << static_cast<int>(image.at(texel.col, texel.row, 0)) << " "
                 << static_cast<int>(image.at(texel.col, texel.row, 1)) << " "
                 << static_cast<int>(image.at(texel.col, texel.row, 2)) << ", / 255 = " << colour_text(colour) << "\n";
            break;
        }
    }
}

}  // namespace clr
