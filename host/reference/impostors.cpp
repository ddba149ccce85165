// Reference impostor placement and view choice (docs/scene-format.md, Impostors), in double.
#include "reference/impostors.h"

namespace clr::reference {

namespace {

// Below this fraction of |D| the horizontal part of D is taken for rounding noise: the eye is
// straight above or below the centre (the documented 1e-9 thresholds).
constexpr double kDegenerate = 1e-9;

// The rectangle's orientation: front normal n, right r and up s, orthonormal with r x s = n.
struct Frame {
    Vec3 n, r, s;
};

// D = E - C: from the impostor's centre to the eye.
Vec3 towards_eye(const Impostor& impostor, const CameraFrame& camera) { return camera.eye - impostor.center; }

// unit(D), or the camera's backward direction w when the eye sits exactly on the centre.
Vec3 unit_towards_eye(const Impostor& impostor, const CameraFrame& camera) {
    const Vec3 d = towards_eye(impostor, camera);
    return d == Vec3(0, 0, 0) ? camera.w : normalize(d);
}

Vec3 horizontal_part(const Vec3& v, const Vec3& a) { return v - a * dot(v, a); }

// Turns about A only: the normal is the horizontal part of D, so the vertical edges stay along
// A. From straight above or below D has no usable horizontal part; the camera's w has one,
// because up is never parallel to the view direction.
Frame upright_frame(const Impostor& impostor, const CameraFrame& camera, const Vec3& a) {
    const Vec3 d = towards_eye(impostor, camera);
    Vec3 horizontal = horizontal_part(d, a);
    if (length(horizontal) <= kDegenerate * length(d)) horizontal = horizontal_part(camera.w, a);
    Frame frame;
    frame.n = normalize(horizontal);
    frame.r = cross(a, frame.n);  // unit: A and n are unit and perpendicular
    frame.s = a;
    return frame;
}

// Faces the eye in every direction; the right edge is horizontal (A x n) unless the eye is
// straight above or below, where A x n vanishes and the camera's right u takes its place.
Frame free_frame(const Impostor& impostor, const CameraFrame& camera, const Vec3& a) {
    Frame frame;
    frame.n = unit_towards_eye(impostor, camera);
    Vec3 right = cross(a, frame.n);
    if (length(right) <= kDegenerate) right = camera.u;
    frame.r = normalize(right);
    frame.s = cross(frame.n, frame.r);
    return frame;
}

Frame impostor_frame(const Impostor& impostor, const CameraFrame& camera, const Vec3& a) {
    return impostor.facing == Facing::Upright ? upright_frame(impostor, camera, a) : free_frame(impostor, camera, a);
}

}  // namespace

int chosen_view(const Impostor& impostor, const CameraFrame& camera) {
    const Vec3 e = unit_towards_eye(impostor, camera);
    int best = -1;
    double best_score = 0;
    for (int i = 0; i < static_cast<int>(impostor.views.size()); ++i) {
        const double score = dot(e, impostor.views[i].direction);
        // Strictly greater: of exactly equal scores the first in the list stays.
        if (best < 0 || score > best_score) {
            best = i;
            best_score = score;
        }
    }
    return best;
}

Billboard place_impostor(const Impostor& impostor, const CameraFrame& camera, const Vec3& up) {
    const Frame frame = impostor_frame(impostor, camera, normalize(up));
    const Vec3 half_right = frame.r * (impostor.width / 2);
    const Vec3 half_up = frame.s * (impostor.height / 2);

    Billboard billboard;
    billboard.upper_left = impostor.center - half_right + half_up;
    billboard.upper_right = impostor.center + half_right + half_up;
    billboard.lower_left = impostor.center - half_right - half_up;
    billboard.ambient = impostor.ambient;
    const int view = chosen_view(impostor, camera);
    if (view < 0) {
        billboard.has_ambient = true;
    } else {
        billboard.image = impostor.views[view].image;
    }
    billboard.is_mirror = false;
    return billboard;
}

Scene with_impostors_placed(const Scene& scene, const CameraFrame& camera) {
    Scene placed = scene;
    placed.impostors.clear();
    placed.billboards.reserve(scene.billboards.size() + scene.impostors.size());
    for (const Impostor& impostor : scene.impostors) {
        placed.billboards.push_back(place_impostor(impostor, camera, scene.up));
    }
    return placed;
}

}  // namespace clr::reference
