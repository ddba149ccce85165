// The primitive kinds on the host, in one list: each kind's unit (kinds/<name>_kind.h) says
// which objects of a frame are of that kind, their bounds, screen bounds, device struct and
// shading rule, and every phase that handles objects by kind (the BVH, the screen tiles, the
// feature set, the reference's lighting) goes through this list. The kernels' list is
// kernels/kinds/kinds.cl; both are in the order of the kinds' CLR_HIT_* values, the order
// that ranks equally near hits (docs/architecture.md, Adding a primitive kind).
#pragma once

#include "kinds/billboard_kind.h"
#include "kinds/plane_kind.h"
#include "kinds/sphere_kind.h"
#include "kinds/triangle_kind.h"

namespace clr {

// Calls visit(Kind{}) for each kind, in the order of their CLR_HIT_* values.
template <typename Visit>
void for_each_kind(Visit&& visit) {
    visit(SphereKind{});
    visit(BillboardKind{});
    visit(TriangleKind{});
    visit(PlaneKind{});
}

// Calls visit(Kind{}) for each kind with bounds (kBounded), the kinds that the BVH and the
// screen tiles hold, in the same order.
template <typename Visit>
void for_each_bounded_kind(Visit&& visit) {
    for_each_kind([&](auto kind) {
        if constexpr (decltype(kind)::kBounded) visit(kind);
    });
}

// Whether the sun lights surfaces of hit kind `hit` (CLR_HIT_*); CLR_HIT_NONE is not lit.
inline bool kind_is_lit(int hit) {
    bool lit = false;
    for_each_kind([&](auto kind) { lit |= decltype(kind)::kHit == hit && decltype(kind)::kLit; });
    return lit;
}

// Whether `scene` has an object of a kind that the sun lights.
inline bool has_lit_objects(const Scene& scene) {
    bool lit = false;
    for_each_kind([&](auto kind) { lit |= decltype(kind)::kLit && decltype(kind)::count(scene) > 0; });
    return lit;
}

}  // namespace clr
