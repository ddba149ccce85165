// The validated scene model: what a scene file says, in the course's terms, with defaults
// applied. Nothing here knows about OpenCL; render/ turns a Scene into device data.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "core/image.h"
#include "core/vec3.h"

namespace clr {

namespace reference {
class TriangleTree;  // reference/triangle_tree.h
}

using Color = Vec3;  // display-referred RGB in [0,1] (values outside are clamped on output)

struct Sphere {
    Vec3 center;
    double radius = 1;
    Color ambient;  // base colour
    bool is_mirror = false;
    std::uint32_t material = 0;  // Scene::materials; 0: the default
};

// The Blinn-Phong coefficients of a surface of the fall 2019 format (docs/scene-format.md,
// Lights and materials); its ambient coefficient is the object's `ambient`. The default
// (Scene::materials[0]) adds nothing to the ambient colour.
struct Material {
    Color diffuse;   // k_d
    Color specular;  // k_s
    double phong_exponent = 0;  // p
    Color mirror;    // k_m: the share of the reflected ray's colour added
    bool operator==(const Material& other) const {
        return diffuse == other.diffuse && specular == other.specular && phong_exponent == other.phong_exponent &&
               mirror == other.mirror;
    }
};

// A point light of the Blinn-Phong model.
struct PointLight {
    Vec3 position;
    Color color;
};

// An infinite plane through `point` with unit normal `normal`, seen from both sides.
struct Plane {
    Vec3 point;
    Vec3 normal;  // unit length
    Color ambient;
    std::uint32_t material = 0;  // Scene::materials
};

struct Billboard {
    Vec3 upper_left;   // UL: the image's top-left texel
    Vec3 lower_left;   // LL: the image's left column runs UL -> LL
    Vec3 upper_right;  // UR: the image's top row runs UL -> UR
    bool has_ambient = false;
    Color ambient;
    std::shared_ptr<const Image> image;  // null: flat `ambient` colour (or a mirror)
    bool is_mirror = false;
};

// One `obj` object of a scene: a Wavefront OBJ model placed as p * scale + position
// (docs/scene-format.md, Meshes). Its triangles are Scene::triangles[first_triangle, +count).
struct Mesh {
    std::string filename;  // as the scene names it, for messages and --check
    // The file read (relative to the scene's folder), also when a placeholder stands in for
    // it: every file the scene tried to read is an input that no output may replace.
    std::string path;
    // The .mtl files it named, as far as it was read (null for a triangle of the scene): one list
    // for every placement of a file, not a copy each, since one `mtllib` line may name thousands
    // (a .mtl spelt many ways); inputs are checked once per list (add_scene_inputs).
    std::shared_ptr<const std::vector<std::string>> material_paths;
    Vec3 position;
    Vec3 scale{1, 1, 1};
    Color ambient;  // the scene's, else the OBJ material's Kd, else 0.8 grey
    bool is_mirror = false;
    bool placeholder = false;  // --placeholders stood in a cube for a missing file
    // A `triangle` surface of the scene (the fall 2019 format): all of them share edges and
    // corners as one mesh (compute_triangle_ties(), scene/triangle_ties.h).
    bool surface_triangle = false;
    bool tied = false;  // its Scene::triangle_ties were found as it was placed (tie_placed_mesh())
    std::uint32_t material = 0;  // Scene::materials, for every triangle of the mesh
    std::size_t first_triangle = 0;
    std::size_t triangle_count = 0;
};

// One triangle of a mesh, in scene coordinates. Corners in the face's order; the geometric
// normal is (c1 - c0) x (c2 - c0), and a mesh is seen from both sides.
struct Triangle {
    std::array<Vec3, 3> corners;
    std::uint32_t mesh = 0;      // index in Scene::meshes
    std::int32_t normals = -1;   // index in Scene::corner_normals, or -1: the geometric normal
};

// Which way a camera-facing billboard may turn (docs/scene-format.md, Impostors).
enum class Facing {
    Upright,  // about the scene's up vector only, as a tree does: its vertical edges stay parallel to up
    Free,     // towards the eye in every direction, its top edge towards the camera's up
};

// One picture of an impostor's object, and the direction from the object towards the point
// it was seen from.
struct ImpostorView {
    Vec3 direction;  // unit length; zero for an impostor's single `filename` (always shown)
    std::shared_ptr<const Image> image;
};

// A billboard that faces the camera (clrender extension): each frame, its corners are
// recomputed from the eye, and with several views it shows the one whose direction is
// closest to the direction from its centre to the eye.
struct Impostor {
    Vec3 center;
    double width = 1;
    double height = 1;
    Facing facing = Facing::Upright;
    std::vector<ImpostorView> views;  // empty: the flat colour `ambient`
    Color ambient;
};

// One key of the camera path. A still scene has one key.
struct CameraKey {
    Vec3 eye;
    Vec3 lookat;
};

enum class Interpolation { Linear, CatmullRom };

// Most frames an animation may have, however its length is given. Frame numbers are ints
// throughout (file names, --frames, the kernels' sample seeds), and a million frames is
// over a day of video at 10 fps: more is a typo, not an intent.
constexpr int kMaxAnimationFrames = 1000000;

// How a camera path becomes frames: clrender's extension keys under "clrender" in the scene.
struct AnimationSettings {
    int frames_per_segment = 10;  // frames from one key to the next; the last key adds one
    int frame_count = 0;          // > 0: total frames, spread evenly over the path instead
    double fps = 10;              // frames per second of the video
    Interpolation interpolation = Interpolation::Linear;
};

// How pixels are sampled: clrender's extension keys under "clrender", or --spp.
struct SamplingSettings {
    int samples_per_pixel = 1;  // 1: the pixel's centre; more: anti-aliasing (kernels/shared/clr_samples.h)
    unsigned seed = 0;          // varies the sample pattern; with the frame index it fixes it
};

// One image file a scene shows, as its header describes it (scene/image_library.h).
struct ImageFileInfo {
    std::string path;
    std::string format;  // "PNG", "JPEG", "PPM", or "placeholder" (--placeholders)
    long long width = 0, height = 0;
    bool alpha_channel = false;  // texels may be transparent: only decoding tells
};

struct Scene {
    std::string path;  // the scene file, for messages and default output names
    std::string name;  // file name without folder and extension

    std::vector<CameraKey> camera_path;  // at least one key
    AnimationSettings animation;
    SamplingSettings sampling;
    Vec3 up;
    double fov_degrees = 60;  // full field of view across the larger image dimension
    int width = 0;
    int height = 0;

    Color background;  // DefaultColor / DefaulColor
    bool only_ambient = false;
    bool has_sun = false;
    Vec3 sun_location;
    int max_depth = 5;
    // Primary rays see depths along the view direction from clip_near to clip_far (`near`,
    // `far`): 0 and infinity see everything.
    double clip_near = 0;
    double clip_far = std::numeric_limits<double>::infinity();
    bool clips() const { return clip_near > 0 || clip_far < std::numeric_limits<double>::infinity(); }
    // The depth the renderers keep hits below: clip_far lowered by one part in 2^20, so that a
    // surface lying exactly on the far plane (a wall at the far distance) is dropped by the
    // kernels and the reference alike, not kept or dropped pixel by pixel as their different
    // roundings of its depth fall (docs/scene-format.md, Near and far clipping).
    double kept_far() const { return clip_far * (1 - 0x1p-20); }

    std::vector<Sphere> spheres;
    std::vector<Plane> planes;         // "surfaces" of type "plane"
    std::vector<PointLight> lights;    // "lights": the Blinn-Phong model instead of the sun
    // Every distinct material the objects name; [0] is the default, which adds nothing.
    std::vector<Material> materials{Material{}};
    std::vector<Billboard> billboards;
    std::vector<Impostor> impostors;  // "clrender"/"impostors"; shown after the billboards
    std::vector<Mesh> meshes;          // "obj"
    std::vector<Triangle> triangles;   // every mesh's, mesh by mesh
    // Unit normals at a triangle's three corners, where its face names one for every corner
    // (transformed by the mesh's scale as normals are: divided by it, then normalised).
    std::vector<std::array<Vec3, 3>> corner_normals;
    // Which triangle a hit on a shared edge or vertex is shaded as (kernels/kinds/triangle.cl,
    // reference/shade.cpp): for each triangle, [k] (k = 0..2) the lowest index other than its own
    // among the triangles of its mesh placement sharing its edge opposite corner k (corners k+1,
    // k+2), [3 + k] the same around its corner k, by exact corner positions; its own index where
    // none shares it, or where every triangle there has the same corner normal at that vertex
    // (at both ends of that edge): a smooth surface shades alike on both sides
    // (compute_triangle_ties(), scene/triangle_ties.h). A settled hit is shaded as the lower of
    // the two and its secondary rays leave both. Empty, or another size than `triangles` (scenes
    // built in code that did not ask for it): no settling.
    std::vector<std::array<std::int32_t, 6>> triangle_ties;
    // Whether any entry of triangle_ties names another triangle: without, nothing is settled
    // and the kernels leave the rule out (FeatureSet::triangle_ties).
    bool has_triangle_ties = false;
    // The double-precision reference's own index over `triangles` (reference/triangle_tree.h),
    // made for the eye-relative copy it traces; null: the reference tests every triangle.
    std::shared_ptr<const reference::TriangleTree> triangle_tree;

    // What decides the pixels, as a label for image descriptions (scene/scene_digest.h); ""
    // when the images were not decoded (--check).
    std::string digest;

    std::vector<std::string> warnings;  // unknown keys and similar, one line each
    // Every warning found, also those past the first hundred that `warnings` only counts in
    // its last line: what --check and --strict report.
    std::size_t warning_count = 0;
    std::vector<ImageFileInfo> image_files;  // each distinct image file shown, once
    // The image files that the meshes' .mtl files name as textures (`map_Kd`, `bump`, ...),
    // relative to their .mtl's folder, each once: never read, but the models' own files, which no
    // output may replace.
    std::vector<std::string> mesh_texture_paths;

    // Sun lighting applies when a sun is given and OnlyAmbient is not 1 (docs/scene-format.md,
    // Conventions: Lighting and shadows).
    bool lit() const { return has_sun && !only_ambient; }
    // The lights apply unless OnlyAmbient is 1 (docs/scene-format.md, Lights and materials).
    bool lit_by_lights() const { return !lights.empty() && !only_ambient; }
    bool is_animated() const { return camera_path.size() >= 2; }
};

}  // namespace clr
