// The scene format is documented in docs/scene-format.md (and docs/scene.schema.json);
// keep the three in step.
#include "scene/scene_loader.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>

#include "core/errors.h"
#include "core/memory_budget.h"
#include "scene/bounded_file.h"
#include "scene/camera_checks.h"
#include "scene/image_budget.h"
#include "scene/image_library.h"
#include "scene/json_reader.h"
#include "scene/key_hints.h"
#include "scene/mesh_loader.h"
#include "scene/scene_digest.h"
#include "scene/surfaces_loader.h"
#include "scene/triangle_ties.h"
#include "scene/scene_overrides.h"
#include "core/printable_text.h"
#include "scene/value_ranges.h"

namespace clr {
namespace {

namespace fs = std::filesystem;

constexpr int kDefaultMaxDepth = 5;  // (docs/scene-format.md, Keys)
// More reflections than this change no visible pixel in any sensible scene, and each one
// costs a full trace per pixel: a larger value is a typo, not an intent.
constexpr int kMaxMaxDepth = 64;
// Billboard corners are degenerate when the sine of the angle between the two edges at UL is
// at most this, computed from unit edges so that it does not depend on the billboard's size.
constexpr double kDegenerateSine = 1e-12;

// Unit vector along `v`, of any finite length (normalize() scales before squaring). Zero
// stays zero.
Vec3 direction(const Vec3& v) { return v == Vec3{} ? v : normalize(v); }

// --------------------------------------------------------------------------------------
// Camera

// Camera positions given either as one point under `single_key` ("eye") or as a list under
// `list_key` ("eyeLocations"), with each point's location for messages.
struct PathPoints {
    std::vector<Vec3> points;
    std::vector<std::string> locations;
    std::string location;  // of the key itself
    bool from_list = false;
};

std::optional<PathPoints> read_path_points(ObjectReader& file, const std::string& single_key,
                                           const std::string& list_key) {
    const std::optional<Node> single = file.optional(single_key);
    const std::optional<Node> list = file.optional(list_key);
    if (single && list) list->fail("give either '" + single_key + "' or '" + list_key + "', not both");
    PathPoints path;
    if (single) {
        path.points.push_back(read_position(*single));
        path.locations.push_back(single->location());
        path.location = single->location();
    } else if (list) {
        for (const Node& entry : list->elements()) {
            path.points.push_back(read_position(entry));
            path.locations.push_back(entry.location());
        }
        if (path.points.empty()) list->fail(list_key + " must hold at least one [x, y, z] position");
        path.location = list->location();
        path.from_list = true;
    } else {
        return std::nullopt;
    }
    return path;
}

std::string count_of_entries(std::size_t n) {
    return std::to_string(n) + (n == 1 ? " entry" : " entries");
}

// lookatLocations pairs with the eye positions one to one (a single `lookat` serves all).
void check_lookat_count(const PathPoints& eyes, const PathPoints& lookats, const Diagnostics& diagnostics) {
    if (!lookats.from_list || lookats.points.size() == eyes.points.size()) return;
    const std::string eye_count =
        eyes.from_list ? "eyeLocations has " + count_of_entries(eyes.points.size()) : "there is a single 'eye'";
    diagnostics.fail(lookats.location, "lookatLocations has " + count_of_entries(lookats.points.size()) + " but " +
                                           eye_count +
                                           "; give one look-at point per eye position, or one 'lookat' for all");
}

// The view must have a direction and `up` must fix the camera's roll, at every path key.
void check_camera_key(const Scene& scene, std::size_t key, const std::string& key_location,
                      const std::string& up_location, const Diagnostics& diagnostics) {
    const std::string at_key = scene.is_animated() ? " at camera key " + std::to_string(key) : "";
    const std::optional<std::string> problem = camera_problem(scene.camera_path[key], scene.up, at_key);
    if (!problem) return;
    const bool no_view_direction = scene.camera_path[key].eye == scene.camera_path[key].lookat;
    diagnostics.fail(no_view_direction ? key_location : up_location, *problem);
}

// Returns the location of each camera key, for messages about the frames between keys.
std::vector<std::string> read_camera(ObjectReader& file, Scene& scene, const Diagnostics& diagnostics) {
    const std::optional<PathPoints> eyes = read_path_points(file, "eye", "eyeLocations");
    if (!eyes)
        file.node().fail("scene needs 'eye' (a camera position) or 'eyeLocations' (a camera path)" + file.mistake_note("eye"));
    const std::optional<PathPoints> lookats = read_path_points(file, "lookat", "lookatLocations");
    if (!lookats)
        file.node().fail("scene needs 'lookat' (or 'lookatLocations', one per eye position)" + file.mistake_note("lookat"));

    check_lookat_count(*eyes, *lookats, diagnostics);
    const std::size_t key_count = eyes->points.size();
    for (std::size_t key = 0; key < key_count; ++key)
        scene.camera_path.push_back({eyes->points[key], lookats->points[lookats->from_list ? key : 0]});

    const Node up = file.required("up");
    scene.up = up.vec3();
    if (scene.up == Vec3{}) up.fail("up must not be the zero vector");

    // A problem at one key of a path is best found at that key's entry.
    const PathPoints& per_key = eyes->from_list || !lookats->from_list ? *eyes : *lookats;
    for (std::size_t key = 0; key < key_count; ++key) {
        const std::string& key_location = per_key.locations[key];
        check_camera_key(scene, key, key_location, scene.is_animated() ? key_location : up.location(), diagnostics);
    }

    const Node fov = file.required("fov_angle");
    scene.fov_degrees = fov.number();
    if (!(scene.fov_degrees > 0 && scene.fov_degrees < 180))
        fov.fail("fov_angle must be between 0 and 180 degrees, both excluded (got " + fov.shown() + ")");
    return per_key.locations;
}

// --------------------------------------------------------------------------------------
// Image size

// The scene's width or height, or the command line's value, which replaces it (the scene's
// value is then not read at all).
int read_image_side(ObjectReader& file, const std::string& key, const std::optional<int>& override_value) {
    if (override_value) {
        file.has(key);  // known, so not warned about
        if (*override_value < 1 || *override_value > kMaxImageSide) {
            file.node().fail("image " + key + " " + std::to_string(*override_value) +
                             " given on the command line must be from 1 to " + std::to_string(kMaxImageSide));
        }
        return *override_value;
    }
    const Node side = file.required(key, " (or give the size on the command line: --size WxH)");
    return static_cast<int>(side.integer(1, kMaxImageSide));
}

void read_image_size(ObjectReader& file, const LoadOptions& options, Scene& scene) {
    scene.width = read_image_side(file, "width", options.width_override);
    scene.height = read_image_side(file, "height", options.height_override);
    const long long pixels = static_cast<long long>(scene.width) * scene.height;
    if (pixels > kMaxImagePixels) {
        const std::string location = !options.height_override ? "/height" : !options.width_override ? "/width" : "";
        file.node().diagnostics().fail(
            location, "the image has " + std::to_string(scene.width) + " x " + std::to_string(scene.height) + " = " +
                          std::to_string(pixels) + " pixels, more than the limit of " +
                          std::to_string(kMaxImagePixels) + " (" + max_square_image_text() + ")");
    }
}

// `value` (> 0) rounded up to two significant digits: a suggested minimum that, written as
// shown, still passes.
double round_up_to_two_digits(double value) {
    const double unit = std::pow(10.0, std::floor(std::log10(value)) - 1);
    return std::ceil(value / unit) * unit;
}

// A narrow field of view over many pixels can ask for rays closer together than float32
// directions resolve (value_ranges.h); the smallest fov_angle that works for this size is
// the actionable part of the message.
void check_pixel_span(ObjectReader& file, const Scene& scene) {
    constexpr double kPi = 3.14159265358979323846;
    const double larger_side = std::max(scene.width, scene.height);
    const double span = 2 * std::tan(scene.fov_degrees * kPi / 360) / larger_side;
    if (span >= kMinPixelSpan) return;
    const double smallest_fov = std::atan(kMinPixelSpan * larger_side / 2) * 360 / kPi;
    char smallest[32], shown_span[32];
    std::snprintf(smallest, sizeof smallest, "%.2g", round_up_to_two_digits(smallest_fov * 1.0001));
    std::snprintf(shown_span, sizeof shown_span, "%.2g", span);
    file.required("fov_angle")
        .fail("fov_angle " + number_text(scene.fov_degrees) + " is too narrow for a " + std::to_string(scene.width) +
              " x " + std::to_string(scene.height) + " image: neighbouring pixels' rays would be " + number_text(std::strtod(shown_span, nullptr)) +
              " apart, below the " + number_text(kMinPixelSpan) +
              " that clrender renders exactly enough; use a fov_angle of at least " + smallest +
              " degrees for this size, or a smaller image");
}

// --------------------------------------------------------------------------------------
// Background and lighting

void read_background(ObjectReader& file, Scene& scene) {
    // The course's scenes spell it "DefaulColor" as often as "DefaultColor".
    const bool has_correct = file.has("DefaultColor");
    const bool has_misspelt = file.has("DefaulColor");
    if (has_correct && has_misspelt) {
        file.required("DefaulColor")
            .fail("both 'DefaultColor' and 'DefaulColor' (the course's spelling) are given; keep one");
    }
    if (has_correct || has_misspelt)
        scene.background = file.required(has_correct ? "DefaultColor" : "DefaulColor").color();
}

void read_lighting(ObjectReader& file, Scene& scene) {
    if (const auto only_ambient = file.optional("OnlyAmbient")) scene.only_ambient = only_ambient->flag();
    if (const auto sun = file.optional("SunLocation")) {
        scene.has_sun = true;
        scene.sun_location = read_position(*sun);
    }
    scene.max_depth = kDefaultMaxDepth;
    if (const auto depth = file.optional("MaxDepth"))
        scene.max_depth = static_cast<int>(depth->integer(0, kMaxMaxDepth));
}

// --------------------------------------------------------------------------------------
// Spheres and billboards

// "type" may be left out, but when given it must name what the list holds: a sphere in
// "billboards" is a mistake to report, not an object to skip.
void check_type(ObjectReader& fields, const std::vector<std::string>& accepted, const std::string& expected) {
    const std::optional<Node> type = fields.optional("type");
    if (!type) return;
    const std::string value = type->string();
    if (std::find(accepted.begin(), accepted.end(), value) == accepted.end())
        type->fail("type must be " + expected + " here, got " + type->shown());
}

Sphere read_sphere(const Node& node) {
    ObjectReader fields(node, "sphere");
    hint_sphere_keys(fields);
    check_type(fields, {"sphere"}, "\"sphere\"");
    Sphere sphere;
    sphere.center = read_position(fields.required("center"));
    sphere.radius = read_length(fields.required("radius"));
    sphere.ambient = fields.required("ambient").color();
    if (const auto mirror = fields.optional("IsMirror")) sphere.is_mirror = mirror->flag();
    fields.warn_about_unknown_keys();
    return sphere;
}

// An edge from UpperLeft to `corner` must be long enough for the kernels (value_ranges.h):
// a 1e-200 edge is not a line, it is a billboard too small to render.
void check_billboard_edge(const Vec3& edge, const std::string& corner, const Node& node) {
    if (edge == Vec3{}) node.fail("billboard has no area: " + corner + " is the same point as UpperLeft");
    const double edge_length = length(edge);
    if (edge_length < kMinLength || edge_length > kMaxLength)
        node.fail("billboard edge from UpperLeft to " + corner + " is " + number_text(edge_length) +
                  " long, outside the range clrender renders exactly enough: " + length_range_text());
}

// Corners UL, LL, UR must span a parallelogram of non-zero area (docs/scene-format.md,
// Validation).
void check_billboard_corners(const Billboard& billboard, const Node& node) {
    const Vec3 across = billboard.upper_right - billboard.upper_left;
    const Vec3 down = billboard.lower_left - billboard.upper_left;
    check_billboard_edge(across, "UpperRight", node);
    check_billboard_edge(down, "LowerLeft", node);
    const double sine = length(cross(normalize(across), normalize(down)));
    if (!(sine > kDegenerateSine))
        node.fail("billboard has no area: its corners UpperLeft, LowerLeft and UpperRight are collinear");
}

// A billboard and, when it shows an image, the "filename" value naming it. `always_mirror`
// is for the course's top-level "mirror" key, whose billboard is a mirror without saying so.
std::pair<Billboard, std::optional<Node>> read_billboard(const Node& node, bool always_mirror) {
    ObjectReader fields(node, "billboard");
    hint_billboard_keys(fields);
    check_type(fields, {"billboard", "billboards"}, "\"billboard\" (or \"billboards\")");
    Billboard billboard;
    billboard.upper_left = read_position(fields.required("UpperLeft"));
    billboard.lower_left = read_position(fields.required("LowerLeft"));
    billboard.upper_right = read_position(fields.required("UpperRight"));
    if (const auto ambient = fields.optional("ambient")) {
        billboard.has_ambient = true;
        billboard.ambient = ambient->color();
    }
    billboard.is_mirror = always_mirror;
    if (const auto mirror = fields.optional("IsMirror")) {
        billboard.is_mirror = mirror->flag();
        if (always_mirror && !billboard.is_mirror)
            mirror->fail("a 'mirror' is always a mirror: remove IsMirror or set it to 1");
    }
    const std::optional<Node> filename = fields.optional("filename");
    if (filename && filename->string().empty()) filename->fail("filename must not be empty");
    if (!billboard.is_mirror && !filename && !billboard.has_ambient)
        node.fail("billboard needs 'filename' (an image) or 'ambient' (a flat colour), unless IsMirror is 1" +
                  fields.mistake_note("filename") + fields.mistake_note("ambient"));
    check_billboard_corners(billboard, node);
    fields.warn_about_unknown_keys();
    // A mirror shows what it reflects, never its image (docs/scene-format.md, Conventions:
    // Mirrors), so that image is not even read: a missing file does no harm there.
    return {billboard, billboard.is_mirror ? std::nullopt : filename};
}

// An image still to be read, once every other part of the scene is valid, and where it goes.
// The destinations are taken only after all objects are read, so that they stay valid.
struct PendingImage {
    Node filename;
    std::shared_ptr<const Image>* destination;
};

// A billboard's image still to be read: its index and its "filename" value.
using PendingBillboardImages = std::vector<std::pair<std::size_t, Node>>;

void read_objects(ObjectReader& file, Scene& scene, PendingBillboardImages& pending_images) {
    if (const auto spheres = file.optional("spheres")) {
        for (const Node& sphere : spheres->elements()) scene.spheres.push_back(read_sphere(sphere));
    }
    const auto add_billboard = [&](const Node& node, bool always_mirror) {
        auto [billboard, filename] = read_billboard(node, always_mirror);
        if (filename) pending_images.emplace_back(scene.billboards.size(), *filename);
        scene.billboards.push_back(std::move(billboard));
    };
    if (const auto billboards = file.optional("billboards")) {
        for (const Node& billboard : billboards->elements()) add_billboard(billboard, false);
    }
    // Variants of the 2025 WebGL assignment: one billboard, and one mirror, each on its own key.
    if (const auto billboard = file.optional("billboard")) add_billboard(*billboard, false);
    if (const auto mirror = file.optional("mirror")) add_billboard(*mirror, true);
}

// --------------------------------------------------------------------------------------
// Images

void attach_images(Scene& scene, const std::vector<PendingImage>& pending_images, const LoadOptions& options) {
    const std::uint64_t memory_limit = options.image_memory_limit ? *options.image_memory_limit
                                                                  : image_memory_limit_from_environment();
    ImageLibrary library(scene.path, options.placeholder_images, memory_limit, options.decode_images);
    std::vector<Node> filenames;
    for (const PendingImage& pending : pending_images) filenames.push_back(pending.filename);
    library.read_all(filenames);
    for (const PendingImage& pending : pending_images) *pending.destination = library.image_for(pending.filename);
    scene.image_files = library.files();
}

// --------------------------------------------------------------------------------------
// Impostors: billboards that face the camera (clrender extension, under "clrender")

// Views read from the file, with their "filename" values until the images are read.
struct ViewList {
    std::vector<ImpostorView> views;
    std::vector<Node> filenames;
    bool used = false;  // only the images of lists that some impostor shows are read
};

// What the impostors need once their images are read: named lists are read once and shared.
struct ImpostorViews {
    std::map<std::string, ViewList> sets;  // "view_sets"
    std::vector<ViewList> own;             // per impostor: its own list (empty when it uses a set)
    std::vector<std::string> set_of;       // per impostor: the set it shows, or ""
};

ViewList read_view_list(const Node& node) {
    ViewList list;
    for (const Node& entry : node.elements()) {
        ObjectReader fields(entry, "view");
        const Node filename = fields.required("filename");
        if (filename.string().empty()) filename.fail("filename must not be empty");
        const Node direction_node = fields.required("direction");
        const Vec3 view_direction = direction_node.vec3();
        if (view_direction == Vec3{}) direction_node.fail("direction must not be the zero vector");
        fields.warn_about_unknown_keys();
        list.views.push_back({direction(view_direction), nullptr});
        list.filenames.push_back(filename);
    }
    if (list.views.empty()) node.fail("a list of views must hold at least one view");
    return list;
}

std::map<std::string, ViewList> read_view_sets(ObjectReader& extensions) {
    std::map<std::string, ViewList> sets;
    const std::optional<Node> node = extensions.optional("view_sets");
    if (!node) return sets;
    if (!node->json().is_object()) node->fail("view_sets must be an object mapping names to lists of views");
    for (const auto& [name, value] : node->json().items())
        sets[name] = read_view_list(Node(value, node->location() + "/" + json_pointer_token(name), name, node->diagnostics()));
    return sets;
}

Facing read_facing(const Node& node) {
    const std::string name = node.string();
    if (name == "upright") return Facing::Upright;
    if (name == "free") return Facing::Free;
    node.fail("facing must be \"upright\" or \"free\" (got " + node.shown() + ")");
}

// The views an impostor shows: a list of its own, the name of a set, or one picture.
void read_impostor_views(ObjectReader& fields, ImpostorViews& views) {
    const std::optional<Node> list = fields.optional("views");
    const std::optional<Node> filename = fields.optional("filename");
    if (list && filename) filename->fail("give either 'views' or 'filename', not both");
    ViewList own;
    std::string set_name;
    if (list && list->json().is_string()) {
        set_name = list->string();
        auto set = views.sets.find(set_name);
        if (set == views.sets.end()) list->fail("no view set named " + list->shown() + " under /clrender/view_sets");
        set->second.used = true;
    } else if (list) {
        own = read_view_list(*list);
    } else if (filename) {
        if (filename->string().empty()) filename->fail("filename must not be empty");
        own.views.push_back({Vec3{}, nullptr});  // one picture, whatever the direction
        own.filenames.push_back(*filename);
    }
    views.own.push_back(std::move(own));
    views.set_of.push_back(set_name);
}

Impostor read_impostor(const Node& node, ImpostorViews& views) {
    ObjectReader fields(node, "impostor");
    hint_impostor_keys(fields);
    Impostor impostor;
    impostor.center = read_position(fields.required("center"));
    impostor.width = read_length(fields.required("width"));
    impostor.height = read_length(fields.required("height"));
    if (const auto facing = fields.optional("facing")) impostor.facing = read_facing(*facing);
    const std::optional<Node> ambient = fields.optional("ambient");
    if (ambient) impostor.ambient = ambient->color();
    read_impostor_views(fields, views);
    if (views.own.back().views.empty() && views.set_of.back().empty() && !ambient)
        node.fail("impostor needs 'views' (pictures), 'filename' (one picture) or 'ambient' (a flat colour)" +
                  fields.mistake_note("filename") + fields.mistake_note("ambient"));
    fields.warn_about_unknown_keys();
    return impostor;
}

void read_impostors(ObjectReader& extensions, Scene& scene, ImpostorViews& views) {
    views.sets = read_view_sets(extensions);
    if (const auto list = extensions.optional("impostors")) {
        for (const Node& node : list->elements()) scene.impostors.push_back(read_impostor(node, views));
    }
    for (const auto& [name, set] : views.sets) {
        if (!set.used) extensions.node().warn("view set '" + name + "' is not used by any impostor (its images are not read)");
    }
}

// Where every image goes: billboards, impostors' own views, and each view set in use once.
std::vector<PendingImage> images_to_read(Scene& scene, const PendingBillboardImages& billboards, ImpostorViews& views) {
    std::vector<PendingImage> pending;
    for (const auto& [index, filename] : billboards) pending.push_back({filename, &scene.billboards[index].image});
    const auto add_list = [&](ViewList& list, std::vector<ImpostorView>& destination) {
        for (std::size_t i = 0; i < list.filenames.size(); ++i) pending.push_back({list.filenames[i], &destination[i].image});
    };
    for (auto& [name, set] : views.sets) {
        if (set.used) add_list(set, set.views);
    }
    for (std::size_t i = 0; i < scene.impostors.size(); ++i) {
        scene.impostors[i].views = views.own[i].views;
        add_list(views.own[i], scene.impostors[i].views);
    }
    return pending;
}

// Impostors that show a set get its views, images included, once the images are read.
void share_view_sets(Scene& scene, const ImpostorViews& views) {
    for (std::size_t i = 0; i < scene.impostors.size(); ++i) {
        if (!views.set_of[i].empty()) scene.impostors[i].views = views.sets.at(views.set_of[i]).views;
    }
}

// The step after validation, and the only one that reads image files: every image the valid
// scene shows is read and decoded (scene/image_library.h, within the memory budget) and put
// where it is shown. Validation only collected the "filename" values.
void load_scene_images(Scene& scene, const PendingBillboardImages& billboards, ImpostorViews& views,
                       const LoadOptions& options) {
    attach_images(scene, images_to_read(scene, billboards, views), options);
    share_view_sets(scene, views);
}

// --------------------------------------------------------------------------------------

// The 2025 WebGL scenes' clip distances: primary rays see only depths from `near` to `far`
// along the view direction (docs/scene-format.md, Near and far clipping).
void read_clip_distances(ObjectReader& file, Scene& scene) {
    const auto near = file.optional("near");
    const auto far = file.optional("far");
    if (near) {
        scene.clip_near = near->number();
        if (scene.clip_near < 0 || scene.clip_near > kMaxLength)
            near->fail("near must be from 0 to " + number_text(kMaxLength) + ", got " + number_text(scene.clip_near));
    }
    if (far) {
        scene.clip_far = far->number();
        if (!(scene.clip_far > scene.clip_near) || scene.clip_far > kMaxLength)
            far->fail("far must be greater than near (" + number_text(scene.clip_near) + ") and at most " +
                      number_text(kMaxLength) + ", got " + number_text(scene.clip_far));
    }
}

Interpolation read_interpolation(const Node& node) {
    const std::string name = node.string();
    if (name == "linear") return Interpolation::Linear;
    if (name == "catmull-rom") return Interpolation::CatmullRom;
    node.fail("interpolation must be \"linear\" or \"catmull-rom\" (got \"" + name + "\")");
}

// clrender's own keys, all under "clrender" so they never clash with the course's. The
// animation's length is given at most one way: frames per segment, total frames, or a
// duration in seconds at the frame rate.
void read_extensions(ObjectReader& file, Scene& scene, ImpostorViews& impostor_views) {
    std::optional<Node> node = file.optional("clrender");
    if (!node) return;
    ObjectReader extensions(*node, "clrender settings");
    hint_extension_keys(extensions);
    AnimationSettings& animation = scene.animation;
    if (auto fps = extensions.optional("fps")) {
        animation.fps = fps->number();
        if (!(animation.fps > 0 && animation.fps <= 1000)) fps->fail("fps must be in (0, 1000] (got " + fps->shown() + ")");
    }
    if (auto interpolation = extensions.optional("interpolation")) animation.interpolation = read_interpolation(*interpolation);
    if (auto spp = extensions.optional("spp")) scene.sampling.samples_per_pixel = static_cast<int>(spp->integer(1, kMaxSamplesPerPixel));
    if (auto seed = extensions.optional("seed")) scene.sampling.seed = static_cast<unsigned>(seed->integer(0, 4294967295LL));
    std::vector<std::string> length_keys;
    if (auto per_segment = extensions.optional("frames_per_segment")) {
        animation.frames_per_segment = static_cast<int>(per_segment->integer(1, 100000));
        length_keys.push_back("frames_per_segment");
    }
    if (auto frames = extensions.optional("frames")) {
        animation.frame_count = static_cast<int>(frames->integer(2, kMaxAnimationFrames));
        length_keys.push_back("frames");
    }
    if (auto duration = extensions.optional("duration")) {
        double seconds = duration->number();
        double frames = std::round(seconds * animation.fps);
        if (!(seconds > 0 && frames >= 2 && frames <= kMaxAnimationFrames))
            duration->fail("duration must give from 2 to " + std::to_string(kMaxAnimationFrames) + " frames at " + std::to_string(animation.fps) + " fps (got " +
                           duration->shown() + " s)");
        animation.frame_count = static_cast<int>(frames);
        length_keys.push_back("duration");
    }
    if (length_keys.size() > 1)
        node->fail("give the animation's length one way only, not both '" + length_keys[0] + "' and '" + length_keys[1] + "'");
    read_impostors(extensions, scene, impostor_views);
    extensions.warn_about_unknown_keys();
}

// Frames per segment times the number of segments can pass any limit (and int's range, which
// once made the frame count negative or 1): the product is formed in 64 bits and checked.
void check_animation_length(ObjectReader& file, const Scene& scene) {
    const std::uint64_t keys = scene.camera_path.size();
    if (keys < 2 || scene.animation.frame_count > 0) return;
    const std::uint64_t per_segment = static_cast<std::uint64_t>(scene.animation.frames_per_segment);
    const std::uint64_t frames = (keys - 1) * per_segment + 1;  // both factors are far below 2^32
    if (frames <= static_cast<std::uint64_t>(kMaxAnimationFrames)) return;
    const bool per_segment_given = file.has("clrender") && file.required("clrender").json().contains("frames_per_segment");
    const std::string location = per_segment_given ? "/clrender/frames_per_segment" : "/eyeLocations";
    file.node().diagnostics().fail(
        location, "the animation would have (" + std::to_string(keys) + " keys - 1) x " + std::to_string(per_segment) +
                      " frames per segment + 1 = " + std::to_string(frames) + " frames, more than the limit of " +
                      std::to_string(kMaxAnimationFrames) + "; lower frames_per_segment, or give 'frames' or 'duration'");
}

std::string read_scene_text(const std::string& path) {
    try {
        return read_bounded_file(path, kMaxSceneFileBytes);
    } catch (const BoundedFileError& error) {
        throw SceneError(printable(path), "", std::string("cannot read scene file: ") + printable(error.what()));
    }
}

}  // namespace

Scene parse_scene(const std::string& text, const std::string& path, const LoadOptions& options) {
    Scene scene;
    scene.path = path;
    scene.name = fs::path(path).stem().string();
    Diagnostics diagnostics{path, &scene.warnings};
    Json document = parse_json_text(text, diagnostics);
    // -D values replace the file's before anything is read, so that they are checked as the
    // file's own are. A document that is no object fails below, as it does without them.
    if (document.is_object()) {
        try {
            diagnostics.overridden = apply_scene_overrides(document, options.overrides);
            for (const SceneOverride& set : options.overrides)
                scene.warnings.insert(scene.warnings.end(), set.warnings.begin(), set.warnings.end());
        } catch (const UsageError& error) {
            throw UsageError(printable(path) + ": " + error.what());
        }
    }

    ObjectReader file(Node(document, "", "scene", diagnostics), "scene");
    hint_scene_keys(file);
    const std::vector<std::string> camera_key_locations = read_camera(file, scene, diagnostics);
    if (options.count_frames_only) {
        file.has("width");  // known keys, not read: the count does not depend on them
        file.has("height");
    } else {
        read_image_size(file, options, scene);
        check_pixel_span(file, scene);
    }
    read_background(file, scene);
    read_lighting(file, scene);
    PendingBillboardImages billboard_images;
    read_objects(file, scene, billboard_images);
    std::vector<PendingMesh> meshes = read_surfaces_and_lights(file, scene);
    const std::vector<PendingMesh> obj_meshes = read_mesh_objects(file);
    meshes.insert(meshes.end(), obj_meshes.begin(), obj_meshes.end());
    ImpostorViews impostor_views;
    read_extensions(file, scene, impostor_views);
    check_animation_length(file, scene);
    check_frames_between_keys(scene, camera_key_locations, diagnostics);
    if (options.samples_override) {
        if (*options.samples_override < 1 || *options.samples_override > kMaxSamplesPerPixel)
            throw SceneError(printable(path), "", "--spp must be from 1 to " + std::to_string(kMaxSamplesPerPixel));
        scene.sampling.samples_per_pixel = *options.samples_override;
    }
    if (options.seed_override) scene.sampling.seed = *options.seed_override;
    read_clip_distances(file, scene);
    file.warn_about_unknown_keys();
    // Images last: reading them is the slow part, and pointless if the scene is invalid.
    if (!options.count_frames_only) {
        load_scene_images(scene, billboard_images, impostor_views, options);
        if (options.read_meshes)
            load_meshes(scene, meshes, options.placeholder_images,
                        options.mesh_memory_budget ? *options.mesh_memory_budget : default_memory_budget());
    }
    if (!scene.triangles.empty()) compute_triangle_ties(scene);
    if (options.decode_images) scene.digest = scene_digest(text, options.overrides, scene);
    scene.warning_count = scene.warnings.size() + diagnostics.unshown_warnings;
    diagnostics.summarise_warnings();
    return scene;
}

Scene load_scene(const std::string& path, const LoadOptions& options) {
    const char* on_stdin = std::getenv(kSceneOnStdinVariable);
    if (on_stdin == nullptr || std::string(on_stdin) != "1") return parse_scene(read_scene_text(path), path, options);
    std::string text;
    try {
        text = read_bounded_file("/proc/self/fd/0", kMaxSceneFileBytes);
    } catch (const BoundedFileError& error) {
        throw SceneError(printable(path), "",
                         std::string("cannot read the scene from standard input (") + kSceneOnStdinVariable +
                             "=1): " + printable(error.what()));
    }
    return parse_scene(text, path, options);
}

}  // namespace clr
