// Writes the steps the reference renderer reports for one pixel (reference/trace_observer.h)
// as plain text in the lecture's notation: witness point, ray o + t d, each surface's
// intersection test and its verdict, the sun term, shadow rays and mirror bounces
// (docs/explain-pixel.md).
#pragma once

#include <ostream>
#include <string>

#include "reference/trace_observer.h"

namespace clr {

// A number as --explain-pixel prints it: %.9g, enough digits to tell doubles apart where the
// decisions are made.
std::string explain_number(double value);
std::string explain_vector(const Vec3& value);

class PixelNarrator : public reference::TraceObserver {
public:
    // `placed` is the scene the reference traces (relative to the eye, impostors placed as
    // billboards); `own_billboards` is how many of its billboards are the scene's own, the rest
    // being impostors. Positions are printed in scene coordinates: `eye` added back.
    // (col, row) is the pixel explained.
    PixelNarrator(const Scene& placed, int own_billboards, const reference::CameraFrame& camera, const Vec3& eye,
                  int col, int row, std::ostream& out)
        : scene_(placed), own_billboards_(own_billboards), camera_(camera), eye_(eye), col_(col), row_(row),
          out_(out) {}

    void sample_started(int sample, int samples, double ox, double oy, const Vec3& witness_direction,
                        const reference::Ray& ray) override;
    void sample_finished(int sample, const Color& colour) override;
    void ray_cast(reference::RayRole role, int depth, const reference::Ray& ray, double t_max) override;
    void search_clipped(const reference::Ray& kept, double t_start, double t_end) override;
    void sphere_tested(int index, const reference::detail::SphereRoots& roots, double t_max, double t) override;
    void billboard_tested(int index, const reference::detail::PlaneHit& plane, double t_max, bool accepted) override;
    void triangle_tested(int index, const reference::detail::TriangleTest& test, double t_max, bool accepted) override;
    void plane_tested(int index, double t) override;
    void nearest_found(const reference::Hit& hit) override;
    void light_seen(int index, double cosine, bool hidden, double highlight) override;
    void hit_settled(const reference::Hit& hit, const reference::TieSettled& tie) override;
    void surface_reached(const reference::Hit& hit, const reference::detail::SurfacePoint& surface) override;
    void sun_seen(const reference::detail::SunDirection& sun, double cosine) override;
    void colour_found(reference::ColourSource source, const Color& colour) override;

    // "sphere 2", "billboard 0", "impostor 1 (placed as billboard 3)", "triangle 5 of mesh 0".
    std::string surface_name(reference::HitKind kind, int index) const;

private:
    // Why the nearest distance so far bounds the search: the sun's distance for a shadow ray
    // before any blocker is found, else the nearest hit.
    std::string bound_name() const;
    void describe_billboard_plane(const reference::detail::PlaneHit& plane) const;
    // A position the reference computed relative to the eye, in scene coordinates.
    std::string position(const Vec3& relative) const { return explain_vector(eye_ + relative); }

    const Scene& scene_;
    int own_billboards_;
    const reference::CameraFrame& camera_;
    Vec3 eye_;
    int col_, row_;
    std::ostream& out_;

    reference::RayRole role_ = reference::RayRole::Primary;
    reference::Ray ray_;             // the ray the search runs along (clipped: from the near plane)
    double clip_start_ = 0;          // where a clipped search starts along the primary ray, else 0
    bool found_in_search_ = false;   // some surface already became the nearest in this search
    reference::Hit surface_hit_;     // the last surface a traced ray landed on
    reference::detail::SurfacePoint surface_;
    double cosine_ = 0;              // n.l of the last lit point
    bool shadowed_ = false;          // the last shadow ray met a blocker
    // Triangles whose plane the ray meets outside them, counted rather than narrated one by
    // one (a mesh has thousands): said once when the search ends.
    long long triangles_missed_ = 0;
};

}  // namespace clr
