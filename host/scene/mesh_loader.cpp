#include "scene/mesh_loader.h"

#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <new>
#include <set>
#include <tuple>
#include <vector>

#include "core/errors.h"
#include "core/memory_budget.h"
#include "core/printable_text.h"
#include "scene/file_names.h"
#include "scene/key_hints.h"
#include "scene/mesh_cache.h"
#include "scene/mtl_library.h"
#include "scene/obj_reader.h"
#include "scene/triangle_ties.h"
#include "scene/value_ranges.h"

namespace clr {
namespace fs = std::filesystem;

namespace {

// The course's default colour for a mesh whose scene and material give none.
const Color kDefaultMeshColor{0.8, 0.8, 0.8};

// A scale is a number (the same on every axis) or [sx, sy, sz]; each factor non-zero and
// within the length range, so that a scaled mesh keeps an area and stays renderable.
Vec3 read_scale(const Node& node) {
    if (!node.json().is_number() && !node.json().is_array())
        node.fail("scale must be a number or [sx, sy, sz], got " + node.shown());
    const Vec3 scale = node.json().is_number() ? Vec3{1, 1, 1} * node.number() : node.vec3("[sx, sy, sz]");
    for (int axis = 0; axis < 3; ++axis) {
        const double factor = std::fabs(scale[axis]);
        if (!(factor >= kMinLength && factor <= kMaxLength))
            node.fail("scale must be a non-zero factor on every axis, of magnitude from " + number_text(kMinLength) +
                      " to " + number_text(kMaxLength) + " (got " + number_text(scale[axis]) + ")");
    }
    return scale;
}

}  // namespace

PendingMesh read_mesh_placement(ObjectReader& fields, const Node& node) {
    const Node filename = fields.required("filename");
    if (filename.string().empty()) filename.fail("filename must not be empty");
    if (filename.string().find('\0') != std::string::npos)
        filename.fail("filename contains a NUL character (\\u0000), which no file name can hold");
    PendingMesh pending{Mesh{}, filename, node, false};
    Mesh& mesh = pending.mesh;
    mesh.filename = filename.string();
    if (const auto position = fields.optional("position")) mesh.position = read_position(*position);
    if (const auto scale = fields.optional("scale")) mesh.scale = read_scale(*scale);
    return pending;
}

namespace {

PendingMesh read_mesh_object(const Node& node) {
    ObjectReader fields(node, "obj");
    hint_mesh_keys(fields);
    if (const auto type = fields.optional("type"); type && type->string() != "obj")
        type->fail("type must be \"obj\" here, got " + type->shown());
    PendingMesh pending = read_mesh_placement(fields, node);
    Mesh& mesh = pending.mesh;
    if (const auto ambient = fields.optional("ambient")) {
        mesh.ambient = ambient->color();
        pending.ambient_given = true;
    }
    if (const auto mirror = fields.optional("IsMirror")) mesh.is_mirror = mirror->flag();
    fields.warn_about_unknown_keys();
    return pending;
}

// The placeholder's model: a unit cube centred on the origin, twelve triangles facing out.
ObjMesh placeholder_cube() {
    ObjMesh cube;
    for (int i = 0; i < 8; ++i) cube.positions.push_back({i & 1 ? 0.5 : -0.5, i & 2 ? 0.5 : -0.5, i & 4 ? 0.5 : -0.5});
    const std::uint32_t faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& face : faces) {
        cube.triangles.push_back({face[0], face[1], face[2]});
        cube.triangles.push_back({face[0], face[2], face[3]});
        cube.triangle_normals.push_back({-1, -1, -1});
        cube.triangle_normals.push_back({-1, -1, -1});
    }
    cube.faces = 6;
    return cube;
}

// A file's model as its placements place it: the positions its faces use, and the number each
// has in the file (1 for the first `v` line), which messages name; `numbers` is empty where the
// faces use every position, each then its own number.
struct Model {
    ObjMesh mesh;
    std::vector<std::uint32_t> numbers;
};

// `mesh` without the positions that no face uses, read once for all its placements: each
// placement scaled, placed and checked every position of the file, and a file may hold millions
// that no face uses (a point cloud or a scan with one face, a model whose faces were deleted but
// not their vertices), which the scene's triangle limit does not bound: 400 placements of a
// million such positions and one face took 6 s where one took 0.6 s.
Model used_positions_only(ObjMesh mesh) {
    constexpr std::uint32_t kUnused = std::numeric_limits<std::uint32_t>::max();
    std::vector<std::uint32_t> slot(mesh.positions.size(), kUnused);
    for (const auto& corners : mesh.triangles)
        for (const std::uint32_t corner : corners) slot[corner] = 0;
    std::uint32_t used = 0;
    for (std::uint32_t& each : slot)
        if (each != kUnused) each = used++;
    Model model;
    if (used < mesh.positions.size()) {
        std::vector<Vec3> positions(used);
        model.numbers.resize(used);
        for (std::size_t i = 0; i < slot.size(); ++i) {
            if (slot[i] == kUnused) continue;
            positions[slot[i]] = mesh.positions[i];
            model.numbers[slot[i]] = static_cast<std::uint32_t>(i + 1);
        }
        for (auto& corners : mesh.triangles)
            for (std::uint32_t& corner : corners) corner = slot[corner];
        mesh.positions = std::move(positions);
    }
    model.mesh = std::move(mesh);
    return model;
}

// Normals transform by the inverse of the scale (then made unit again); a zero normal in the
// file has no direction, and leaves its triangle to the geometric normal.
bool transformed_normal(const Vec3& normal, const Vec3& scale, Vec3& out) {
    const Vec3 scaled{normal.x / scale.x, normal.y / scale.y, normal.z / scale.z};
    const double size = length(scaled);
    if (!(size > 0) || !std::isfinite(size)) return false;
    out = scaled / size;
    return true;
}

// The longest edge of a triangle's corners.
double longest_edge(const std::array<Vec3, 3>& corners) {
    return std::max({length(corners[1] - corners[0]), length(corners[2] - corners[1]), length(corners[0] - corners[2])});
}

// Whether a placed triangle is one the kernels render as the reference does: it has an area,
// and its longest edge is within the length range. The kernels' hit weights are cubes of
// lengths relative to the ray's origin: for a triangle of edges near 1e-21 seen from as near,
// they underflow float and the triangle vanishes from the image (or loses pixels) while the
// double reference draws it; 1e-15 leaves a margin of a million, as a sphere's radius does.
bool renders_exactly_enough(const std::array<Vec3, 3>& corners) {
    const Vec3 area = cross(corners[1] - corners[0], corners[2] - corners[0]);
    return dot(area, area) > 0 && longest_edge(corners) >= kMinLength;
}

// The longest edge of the triangles `corners` names among `positions`.
double longest_edge(const std::vector<Vec3>& positions, const std::vector<std::array<std::uint32_t, 3>>& corners) {
    double longest = 0;
    for (const auto& triangle : corners)
        for (int k = 0; k < 3; ++k)
            longest = std::max(longest, length(positions[triangle[(k + 1) % 3]] - positions[triangle[k]]));
    return longest;
}

// Why triangles whose longest edge is `longest` have no area, or none that renders: corners so
// close that the square of their distance underflows double (1e-160 apart) or closer than the
// length range, or repeated or collinear ones.
std::string no_area_reason(double longest, const std::string& collinear) {
    if (longest > 0 && longest < kMinLength)
        return "its longest edge is " + number_text(longest) +
               " long, outside the range clrender renders exactly enough: " + length_range_text();
    return collinear;
}

// Whether any triangle of `model` has an area: a mesh whose faces all have repeated or collinear
// corners draws nothing, which is never the model a scene means.
bool any_triangle_has_area(const ObjMesh& model) {
    for (const auto& corners : model.triangles) {
        const Vec3& a = model.positions[corners[0]];
        const Vec3 area = cross(model.positions[corners[1]] - a, model.positions[corners[2]] - a);
        if (dot(area, area) > 0) return true;
    }
    return false;
}

// Refuses a model that was read but is no mesh the scene can use, with the reason `why`: its
// .mtl files stay inputs of the run all the same (ObjError::material_files).
[[noreturn]] void refuse_model(const ObjMesh& model, const std::string& why) {
    ObjError error(why);
    error.material_files = model.material_files;
    throw error;
}

// Ends the run with exit 6 and a message at `node`, as a scene error names its place.
[[noreturn]] void fail_out_of_memory(const Node& node, const std::string& detail) {
    throw Error(SceneError(node.diagnostics().file, node.location(), "out of memory: " + detail).what(), kExitOutOfMemory);
}

// Makes room for `extra` more elements, at least doubling the capacity when it grows.
template <typename T>
void reserve_more(std::vector<T>& values, std::size_t extra) {
    if (values.size() + extra > values.capacity()) values.reserve(std::max(values.size() + extra, 2 * values.capacity()));
}

// How far a + b, rounded to a double, lies from the exact sum (Knuth's TwoSum).
double rounding_of_sum(double a, double b) {
    const double sum = a + b;
    const double b_part = sum - a;
    return (a - (sum - b_part)) + (b - b_part);
}

// Placed vertices are doubles in scene coordinates, 1/64 apart near 1e14 and 1/8 near 1e15: a
// model placed there is rounded to that grid (a unit ball of 2,304 triangles at 9e14 lost a
// third of them and a third of its pixels changed), which no other object suffers. A triangle
// a corner of which the rounding moves by more than this share of its longest edge is counted
// as changed; slivers thinner than the rounding near the origin are not.
constexpr double kPlacementTolerance = 1e-3;

// What placing a model did to its triangles: `moved` per vertex, the largest rounding of its
// coordinates; the triangles changed beyond kPlacementTolerance, and those of them left without
// an area.
struct PlacementRounding {
    std::vector<float> moved;  // float: a share of an edge needs no more, and a large mesh's copy is half as big
    std::size_t changed = 0;
    std::size_t lost = 0;

    // Counts triangle f of `model`, placed at `corners` (kept: it renders).
    void count(const ObjMesh& model, std::size_t f, const Vec3& scale, const std::array<Vec3, 3>& corners, bool kept) {
        const auto& corner = model.triangles[f];
        const double most = std::max({moved[corner[0]], moved[corner[1]], moved[corner[2]]});
        // Nearly every triangle moves far less than the tolerance: decided from its placed
        // corners, without scaling it again (a mesh's load made 10% slower otherwise).
        if (most == 0 || most <= 0.5 * kPlacementTolerance * longest_edge(corners)) return;
        std::array<Vec3, 3> scaled;
        for (int k = 0; k < 3; ++k) {
            const Vec3& p = model.positions[corner[k]];
            scaled[k] = Vec3{p.x * scale.x, p.y * scale.y, p.z * scale.z};
        }
        if (!renders_exactly_enough(scaled) || most <= kPlacementTolerance * longest_edge(scaled)) return;
        ++changed;
        lost += !kept;
    }
};

void warn_about_placement_rounding(const Node& filename, const std::string& what, const PlacementRounding& rounding,
                                   std::size_t triangles, const std::vector<Vec3>& placed) {
    if (rounding.changed == 0) return;
    double largest = 0;
    for (const Vec3& p : placed) largest = std::max({largest, std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
    const double spacing = std::ldexp(1.0, std::ilogb(largest) - std::numeric_limits<double>::digits + 1);
    filename.warn(what + ": " + std::to_string(rounding.changed) + " of its " + std::to_string(triangles) +
                  " triangles move by more than a thousandth of their size once placed, where coordinates are " +
                  number_text(spacing) + " apart (doubles near " + number_text(largest) + "), and " +
                  std::to_string(rounding.lost) +
                  " of them lose their area: the model's detail finer than that is rounded away; place it nearer "
                  "the origin (docs/scene-format.md, Numeric ranges)");
}

// Appends `model`, scaled and placed as `mesh` says, to the scene. Triangles without area
// once placed are left out: no ray can hit them, and their plane has no normal. So are
// triangles smaller than the length range (renders_exactly_enough()), which only a camera
// closer than they are long could see, and the kernels would not draw as the reference does.
// `what` names the model in messages ("mesh 'bunny.obj'"), `numbers` its positions (Model).
void add_mesh(Scene& scene, Mesh mesh, const ObjMesh& model, const std::vector<std::uint32_t>& numbers,
              const Node& filename, const std::string& what, std::uint64_t memory_budget) {
    const std::uint64_t triangles = scene.triangles.size() + model.triangles.size();
    if (triangles > memory_budget / kPlacedTriangleBytes)
        fail_out_of_memory(filename, what + " brings the scene's triangles to " + std::to_string(triangles) +
                                         ", about " + gib_text(triangles * kPlacedTriangleBytes) +
                                         " to load and render, more than the " + gib_text(memory_budget) +
                                         " a scene's meshes may take: half of this machine's memory "
                                         "(docs/robustness.md, Memory)");
    std::vector<Vec3> placed(model.positions.size());
    PlacementRounding rounding;
    rounding.moved.resize(placed.size());
    for (std::size_t i = 0; i < placed.size(); ++i) {
        const Vec3& p = model.positions[i];
        const Vec3 scaled{p.x * mesh.scale.x, p.y * mesh.scale.y, p.z * mesh.scale.z};
        placed[i] = scaled + mesh.position;
        for (int axis = 0; axis < 3; ++axis) {
            const double moved = std::fabs(rounding_of_sum(scaled[axis], mesh.position[axis]));
            rounding.moved[i] = std::max(rounding.moved[i], static_cast<float>(moved));
            if (!(std::fabs(placed[i][axis]) <= kMaxCoordinate))
                filename.fail(what + ": vertex " + std::to_string(numbers.empty() ? i + 1 : numbers[i]) +
                              " lies at " + number_text(placed[i][axis]) + " once scaled and placed; " +
                              position_range_text());
        }
    }
    const std::uint32_t mesh_index = static_cast<std::uint32_t>(scene.meshes.size());
    mesh.first_triangle = scene.triangles.size();
    if (scene.triangles.size() + model.triangles.size() > kMaxSceneTriangles)
        filename.fail(what + " brings the scene's triangles to " +
                      std::to_string(scene.triangles.size() + model.triangles.size()) + ", more than the limit of " +
                      std::to_string(kMaxSceneTriangles));
    // Room for the whole model at once (a million triangles grown one at a time would be
    // copied about twenty times), doubling as before when many models are placed.
    reserve_more(scene.triangles, model.triangles.size());
    if (!model.triangle_normals.empty() && model.triangle_normals.front()[0] >= 0)
        reserve_more(scene.corner_normals, model.triangles.size());
    std::vector<std::array<std::uint32_t, 3>> kept_faces;  // the vertices of each triangle kept
    kept_faces.reserve(model.triangles.size());
    for (std::size_t f = 0; f < model.triangles.size(); ++f) {
        Triangle triangle;
        for (int k = 0; k < 3; ++k) triangle.corners[k] = placed[model.triangles[f][k]];
        const bool kept = renders_exactly_enough(triangle.corners);
        rounding.count(model, f, mesh.scale, triangle.corners, kept);
        if (!kept) continue;
        kept_faces.push_back(model.triangles[f]);
        triangle.mesh = mesh_index;
        const auto& normal_indices = model.triangle_normals[f];
        std::array<Vec3, 3> normals;
        bool has_normals = normal_indices[0] >= 0;
        for (int k = 0; k < 3 && has_normals; ++k)
            has_normals = transformed_normal(model.normals[normal_indices[k]], mesh.scale, normals[k]);
        if (has_normals) {
            triangle.normals = static_cast<std::int32_t>(scene.corner_normals.size());
            scene.corner_normals.push_back(normals);
        }
        scene.triangles.push_back(triangle);
    }
    mesh.triangle_count = scene.triangles.size() - mesh.first_triangle;
    if (mesh.triangle_count == 0) {
        const double longest = longest_edge(placed, model.triangles);
        filename.fail(what + ": all its faces " + (longest > 0 && longest < kMinLength ? "are too small" : "have zero area") +
                      " once scaled and placed (" + no_area_reason(longest, "repeated or collinear corners") +
                      "): it draws nothing");
    }
    warn_about_placement_rounding(filename, what, rounding, model.triangles.size(), placed);
    // A scene's `triangle` surfaces share edges with each other: compute_triangle_ties() ties them.
    if (!mesh.surface_triangle) {
        tie_placed_mesh(scene, mesh.first_triangle, placed, kept_faces);
        mesh.tied = true;
    }
    scene.meshes.push_back(std::move(mesh));
}

// The model a mesh's file gives, by what its read depends on (file_in_folder_key): "m.obj",
// "d/../m.obj" and a link beside m.obj name one model, read once (each spelling read it again:
// 20 of a 100 MB OBJ took 20 reads); a link from another folder reads its .mtl files from
// there, so it is another model.
using ModelKey = FileInFolderKey;

ModelKey model_key(const std::string& path) { return file_in_folder_key(path); }

}  // namespace

void add_triangle(Scene& scene, Mesh mesh, const std::array<Vec3, 3>& corners, const Node& node) {
    if (!renders_exactly_enough(corners))
        node.fail("triangle has no area: " + no_area_reason(longest_edge(corners), "its vertices are collinear or repeated"));
    ObjMesh model;
    model.positions.assign(corners.begin(), corners.end());
    model.triangles.push_back({0, 1, 2});
    model.triangle_normals.push_back({-1, -1, -1});
    model.faces = 1;
    const std::string what = "mesh '" + printable(mesh.filename) + "'";
    add_mesh(scene, std::move(mesh), model, {}, node, what, std::numeric_limits<std::uint64_t>::max());
}

std::vector<PendingMesh> read_mesh_objects(ObjectReader& file) {
    std::vector<PendingMesh> meshes;
    const std::optional<Node> node = file.optional("obj");
    if (!node) return meshes;
    if (node->json().is_array()) {
        for (const Node& element : node->elements()) meshes.push_back(read_mesh_object(element));
    } else {
        meshes.push_back(read_mesh_object(*node));
    }
    return meshes;
}

void load_meshes(Scene& scene, const std::vector<PendingMesh>& pending, bool placeholders, std::uint64_t memory_budget) {
    const fs::path folder = fs::path(scene.path).parent_path();
    const MeshCache cache = MeshCache::from_environment();
    MtlLibrary materials;  // a .mtl that several of the OBJ files name is read once
    std::vector<std::string> paths;
    for (const PendingMesh& each : pending) {
        // "models/../m.obj" is opened as the system resolves it (through a symbolic link
        // `models`, or not at all when there is no folder `models`): scene/file_names.h.
        paths.push_back(path_in_folder(folder, each.mesh.filename));
    }
    // A file that several meshes place (one model, many copies), under one name or several, is
    // read once, and its model kept only until the last of them is placed.
    std::vector<ModelKey> keys;
    std::map<ModelKey, std::size_t> uses_left;
    for (const std::string& path : paths) ++uses_left[keys.emplace_back(model_key(path))];
    std::map<ModelKey, Model> kept;
    // Each model's .mtl names, one list for all its placements: an `mtllib` line of 131,072
    // spellings of one .mtl copied for each of 300 placements took 4.4 GB, and the output check
    // 88 s to look at every name of every copy.
    std::map<ModelKey, std::shared_ptr<const std::vector<std::string>>> material_lists;
    // The textures that each .mtl file names, listed in the scene once for every OBJ file and
    // every name that reach it (.mtl files told apart by their identity and their folder's, as
    // models are): 500 OBJ files naming one library of 10,000 materials list its textures once.
    std::set<ModelKey> textures_listed;
    std::set<std::string> texture_paths;
    // Returns why the textures could not all be listed ("" when they are): the run may not go
    // on with a model's files that it could not keep safe from its outputs.
    const auto list_textures = [&](const std::vector<std::string>& material_files,
                                   const Node& filename) -> std::string {
        // The textures of as many .mtl files as an OBJ may read, no more, so that a broken file
        // costs no more reads than a good one; past them the list is not complete.
        std::size_t files_read = 0;
        for (const std::string& material : material_files) {
            if (!textures_listed.insert(model_key(material)).second) continue;
            if (files_read++ == kMaxMtlFiles)
                return "its .mtl files, told apart with their folders, number more than " +
                       std::to_string(kMaxMtlFiles);
            const fs::path folder = fs::path(material).parent_path();
            // Held here: the library may keep no other reference (a file it could not read),
            // and a loop over a member of the returned temporary read it after it was freed.
            std::shared_ptr<const MtlFileRead> read;
            try {
                read = materials.read(material);
            } catch (const MeshMemoryError& error) {
                fail_out_of_memory(filename, error.what());
            }
            for (const std::string& name : read->texture_files) {
                std::string texture = path_in_folder(folder, name);  // "./wood.png" is "wood.png"
                if (texture_paths.insert(texture).second) scene.mesh_texture_paths.push_back(std::move(texture));
            }
            if (read->texture_files_cut)
                return "its .mtl '" + printable(material) + "' names textures past its first " +
                       std::to_string(kMaxObjMaterials) + " materials";
        }
        return "";
    };
    const auto unsafe = [](const std::string& why) {
        return why + ", more than a run keeps as inputs that no output may replace";
    };
    // A file that cannot be read, for its later placements (a placeholder each, with
    // --placeholders): 40 placements of a broken 50 MB OBJ read it 40 times.
    std::map<ModelKey, ObjError> failed;
    for (std::size_t m = 0; m < pending.size(); ++m) {
        const PendingMesh& each = pending[m];
        const std::string& path = paths[m];
        const ModelKey& key = keys[m];
        const bool used_again = --uses_left[key] > 0;
        Mesh mesh = each.mesh;
        Model read;  // a model for this mesh alone
        const Model* model = &read;
        std::string what = "mesh '" + printable(mesh.filename) + "'";
        try {
            if (const auto failure = failed.find(key); failure != failed.end()) throw failure->second;
            auto found = kept.find(key);
            if (found == kept.end()) {
                read = used_positions_only(read_obj_through_cache(path, cache, memory_budget, &materials));
                if (used_again) found = kept.emplace(key, std::move(read)).first;
            }
            if (found != kept.end()) model = &found->second;
            // Any text reads as an OBJ of unknown statements: a file without one face is
            // not the mesh the scene asks for (a wrong file, or points and lines only).
            if (model->mesh.triangles.empty())
                refuse_model(model->mesh, "it has no faces ('f' lines): it is not a mesh, or not an OBJ file");
            if (!any_triangle_has_area(model->mesh))
                refuse_model(model->mesh, "all its faces have zero area (" +
                                              no_area_reason(longest_edge(model->mesh.positions, model->mesh.triangles),
                                                             "repeated or collinear corners") +
                                              "): it draws nothing");
        } catch (const MeshMemoryError& error) {
            fail_out_of_memory(each.filename, "OBJ '" + printable(path) + "': " + error.what());
        } catch (const std::bad_alloc&) {
            // Memory ran out all the same (a limit below the budget, such as `ulimit -v`).
            fail_out_of_memory(each.filename, "OBJ '" + printable(path) + "': reading it took more memory than the "
                                              "system gives (docs/robustness.md, Memory)");
        } catch (const ObjError& error) {
            if (used_again) failed.emplace(key, error);
            const std::string problem = "cannot read OBJ '" + printable(path) + "': " + error.what();
            if (!placeholders) each.filename.fail(problem);
            // A cube stands in only for a model whose every .mtl and texture the run keeps as
            // inputs: the list of 1,024 names left a later .mtl out, which an output replaced.
            std::shared_ptr<const std::vector<std::string>>& list = material_lists[key];
            if (!list) {
                list = std::make_shared<const std::vector<std::string>>(error.material_files);
                std::string unlisted = error.material_files_incomplete;
                if (unlisted.empty()) unlisted = list_textures(*list, each.filename);
                if (!unlisted.empty())
                    each.filename.fail(problem + "; no placeholder can stand in for it: " + unsafe(unlisted));
            }
            each.filename.warn(problem + "; rendering a placeholder cube instead");
            read = Model{placeholder_cube(), {}};
            model = &read;
            mesh.placeholder = true;
            mesh.material_paths = list;
            // A placement the cube cannot take must still say why there is a cube at all.
            what = "the placeholder cube for " + what + " (" + problem + ")";
        }
        for (const std::string& warning : model->mesh.warnings)
            each.filename.warn("OBJ '" + printable(path) + "': " + warning);
        // The files are inputs of the run whatever happened: an output must never replace a
        // model (or its .mtl) that failed to load and that a placeholder stands in for.
        mesh.path = path;
        if (!mesh.placeholder) {
            std::shared_ptr<const std::vector<std::string>>& list = material_lists[key];
            if (!list) {
                list = std::make_shared<const std::vector<std::string>>(model->mesh.material_files);
                if (const std::string unlisted = list_textures(*list, each.filename); !unlisted.empty())
                    each.filename.fail(what + ": " + unsafe(unlisted));
            }
            mesh.material_paths = list;
        }
        if (!each.ambient_given)
            mesh.ambient = model->mesh.diffuse && !mesh.placeholder ? *model->mesh.diffuse : kDefaultMeshColor;
        add_mesh(scene, std::move(mesh), model->mesh, model->numbers, each.filename, what, memory_budget);
        if (!used_again) {
            kept.erase(key);
            material_lists.erase(key);
            failed.erase(key);
        }
    }
}

}  // namespace clr
