#include "render/impostor_placement.h"

#include <cmath>

namespace clr {
namespace {

// Below this (relative) size a direction is taken as zero and the documented fallback
// applies: the eye is straight above or below the centre, where the facing is undefined.
constexpr double kDegenerate = 1e-9;

// The impostor's frame for this camera: n towards the eye, r its right, s its up.
struct Facing3 {
    Vec3 n, r, s;
};

Facing3 upright_frame(const Vec3& to_eye, const PlacementCamera& camera) {
    Vec3 horizontal = to_eye - camera.up * dot(to_eye, camera.up);
    if (!(length(horizontal) > kDegenerate * length(to_eye)))
        horizontal = camera.backward - camera.up * dot(camera.backward, camera.up);
    Vec3 n = normalize(horizontal);
    return {n, cross(camera.up, n), camera.up};
}

Facing3 free_frame(const Vec3& to_eye, const PlacementCamera& camera) {
    Vec3 n = to_eye == Vec3{} ? camera.backward : normalize(to_eye);
    Vec3 right = cross(camera.up, n);
    if (!(length(right) > kDegenerate)) right = camera.right;
    Vec3 r = normalize(right);
    return {n, r, cross(n, r)};
}

}  // namespace

PlacementCamera::PlacementCamera(const CameraKey& key, const Vec3& scene_up)
    : eye(key.eye), up(normalize(scene_up)), backward(normalize(key.eye - key.lookat)),
      right(normalize(cross(up, backward))) {}

int choose_view(const Impostor& impostor, const PlacementCamera& camera) {
    Vec3 to_eye = camera.eye - impostor.center;
    Vec3 seen_from = to_eye == Vec3{} ? camera.backward : normalize(to_eye);
    int best = -1;
    double best_score = -INFINITY;
    for (std::size_t i = 0; i < impostor.views.size(); ++i) {
        double score = dot(seen_from, impostor.views[i].direction);
        if (best < 0 || score > best_score) {  // strictly higher: ties keep the first
            best = static_cast<int>(i);
            best_score = score;
        }
    }
    return best;
}

void place_impostor(const Impostor& impostor, const PlacementCamera& camera, Billboard& placed) {
    Vec3 to_eye = camera.eye - impostor.center;
    Facing3 frame = impostor.facing == Facing::Upright ? upright_frame(to_eye, camera) : free_frame(to_eye, camera);
    Vec3 half_right = frame.r * (impostor.width / 2);
    Vec3 half_up = frame.s * (impostor.height / 2);
    // Relative to the eye, as the reference places them (reference/eye_relative.h): the centre
    // less the eye is exact near the eye, and so are the corners built on it.
    Vec3 center = impostor.center - camera.eye;
    placed.upper_left = center - half_right + half_up;
    placed.upper_right = center + half_right + half_up;
    placed.lower_left = center - half_right - half_up;
    int view = choose_view(impostor, camera);
    const Image* shown = view >= 0 ? impostor.views[static_cast<std::size_t>(view)].image.get() : nullptr;
    // Copying a shared_ptr is an atomic increment and its release an atomic decrement: with
    // thousands of impostors sharing a few images these were most of the placement's time
    // (docs/benchmarks.md, Impostor frames). Most frames keep each impostor's view.
    if (placed.image.get() != shown) {
        if (view >= 0)
            placed.image = impostor.views[static_cast<std::size_t>(view)].image;
        else
            placed.image.reset();
    }
    placed.has_ambient = view < 0;
    placed.ambient = impostor.ambient;
    placed.is_mirror = false;
}

Billboard place_impostor(const Impostor& impostor, const PlacementCamera& camera) {
    Billboard billboard;
    place_impostor(impostor, camera, billboard);
    return billboard;
}

void place_impostors(const Scene& scene, const PlacementCamera& camera, std::vector<Billboard>& placed) {
    placed.resize(scene.impostors.size());
    for (std::size_t i = 0; i < scene.impostors.size(); ++i) place_impostor(scene.impostors[i], camera, placed[i]);
}

}  // namespace clr
