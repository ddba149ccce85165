// A hook into the reference renderer that is told each step of a pixel's computation: the
// samples, every ray cast, every surface tested and why it was kept or rejected, the sun term,
// mirror bounces and the colour each ray returns. `clrender --explain-pixel` prints these steps
// (docs/explain-pixel.md), so its numbers are the reference's own and can never disagree with
// the reference image. The reference calls an observer only when one is given: without one it
// computes exactly what it did before.
#pragma once

#include "reference/geometry.h"

namespace clr::reference {

// Why a ray was cast.
enum class RayRole {
    Primary,    // from the eye through a sample of the pixel
    Reflected,  // leaving a mirror
    Shadow,     // from a lit point towards the sun
};

// How trace() arrived at the colour a ray returns.
enum class ColourSource {
    Background,        // the ray hit nothing
    DepthExhausted,    // a mirror would reflect once more than MaxDepth allows: the background
    BackOfMirror,      // black
    SphereAmbient,     // an unlit sphere's colour
    SunLit,            // a lit sphere or mesh: ambient * max(0, n.l) * s
    BillboardAmbient,  // a flat billboard's colour
    BillboardTexel,    // the texel under (alpha, beta)
    MeshAmbient,       // an unlit mesh's colour
    PlaneAmbient,      // an unlit plane's colour
    PhongLit,          // a surface lit by the scene's lights (Blinn-Phong), mirror share not yet added
};

// A triangle hit on a shared edge or corner of its mesh, shaded as the lowest triangle there
// (reference/shade.cpp; docs/scene-format.md, Meshes, "Shared edges and vertices").
struct TieSettled {
    bool at_corner = false;  // a corner of the triangle hit, else one of its edges
    int k = 0;               // that corner k, or the edge opposite corner k
    double measure = 0;      // |P - c_k|_1, or |(P - a) x e|_1 / |e|_1 for the edge from a along e
    double band = 0;         // t 2^-20: the measure is at most this
    int other = -1;          // the lowest triangle there other than the one hit (itself if none)
    int shaded = -1;         // the one shaded: the lower of the two
};

class TraceObserver {
public:
    virtual ~TraceObserver() = default;

    // A sample of the pixel at image point (col + ox, row + oy); `witness_direction` is the
    // witness point minus the eye (the image plane at distance 1), `ray` the ray through it.
    virtual void sample_started(int /*sample*/, int /*samples*/, double /*ox*/, double /*oy*/,
                                const Vec3& /*witness_direction*/, const Ray& /*ray*/) {}
    virtual void sample_finished(int /*sample*/, const Color& /*colour*/) {}

    // A nearest-hit search over (0, t_max) begins; `depth` counts the reflections so far.
    virtual void ray_cast(RayRole /*role*/, int /*depth*/, const Ray& /*ray*/, double /*t_max*/) {}
    // The primary ray sees only the depths from t_start to t_end that the camera's clip
    // distances keep: the search runs along `kept`, from the ray's point at t_start on the near
    // plane, over (0, t_end - t_start); its t count from there (intersect_in_view()).
    virtual void search_clipped(const Ray& /*kept*/, double /*t_start*/, double /*t_end*/) {}
    // Sphere `index` tested against a nearest distance of `t_max`: the quadratic's roots and
    // the t intersect() took from them (kInfinity: rejected).
    virtual void sphere_tested(int /*index*/, const detail::SphereRoots& /*roots*/, double /*t_max*/,
                               double /*t*/) {}
    // Billboard `index` tested against a nearest distance of `t_max`; `accepted` is whether it
    // became the nearest hit.
    virtual void billboard_tested(int /*index*/, const detail::PlaneHit& /*plane*/, double /*t_max*/,
                                  bool /*accepted*/) {}
    // Triangle `index` tested against a nearest distance of `t_max`; `accepted` is whether it
    // became the nearest hit.
    virtual void triangle_tested(int /*index*/, const detail::TriangleTest& /*test*/, double /*t_max*/,
                                 bool /*accepted*/) {}
    // Plane `index` tested: the t intersect() took (kInfinity: parallel, behind or too far).
    virtual void plane_tested(int /*index*/, double /*t*/) {}
    // What the search found (kind None: nothing).
    virtual void nearest_found(const Hit& /*hit*/) {}

    // The triangle hit lies on a shared edge or corner: `tie.shaded` is shaded in its place.
    virtual void hit_settled(const Hit& /*hit*/, const TieSettled& /*tie*/) {}
    // The surface a hit landed on.
    virtual void surface_reached(const Hit& /*hit*/, const detail::SurfacePoint& /*surface*/) {}
    // The direction to the sun from a lit point and the cosine n.l.
    virtual void sun_seen(const detail::SunDirection& /*sun*/, double /*cosine*/) {}
    // Light `index` of the Blinn-Phong model seen from a point: the cosine n.l, whether an
    // opaque surface hides it, and the highlight max(0, n.h)^p (0 when it is not counted).
    virtual void light_seen(int /*index*/, double /*cosine*/, bool /*hidden*/, double /*highlight*/) {}
    // The colour the ray returns, and why.
    virtual void colour_found(ColourSource /*source*/, const Color& /*colour*/) {}
};

}  // namespace clr::reference
