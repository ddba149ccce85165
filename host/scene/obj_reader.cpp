#include "scene/obj_reader.h"

#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include "core/memory_budget.h"
#include "core/printable_text.h"
#include "scene/bounded_file.h"
#include "scene/file_names.h"
#include "scene/mtl_library.h"
#include "scene/mtl_texture_maps.h"
#include "scene/obj_text_checks.h"
#include "scene/text_encoding.h"
#include "scene/value_ranges.h"

// tinyobjloader is one header; its implementation is compiled here, in double so that the
// double reference sees the file's coordinates as written.
#define TINYOBJLOADER_IMPLEMENTATION
#define TINYOBJLOADER_USE_DOUBLE
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-parameter"
#if !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <tiny_obj_loader.h>
#pragma GCC diagnostic pop

namespace clr {
namespace {

// The first line of tinyobjloader's message, without its trailing newline.
std::string first_line(const std::string& text) {
    const std::string line = text.substr(0, text.find('\n'));
    return line.empty() ? "tinyobjloader could not read it" : line;
}

// Whether each material that tinyobjloader's LoadMtl makes of an .mtl text gives a `Kd` line
// (the library leaves an unset Kd at 0, which a black material also has), in the order the
// library adds them to its list. This follows LoadMtl's own reading: a line trimmed of
// trailing blanks; "newmtl" and a blank start a material and add the previous one if it has
// a name; the last one is added whatever its name. A name defined twice keeps its first
// definition (the library's map of names), which the list's order lets the caller find.
std::vector<bool> materials_giving_diffuse(const std::string& text) {
    std::vector<bool> gives;
    bool named = false, has_kd = false;
    const auto blank = [](char c) { return c == ' ' || c == '\t'; };
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
        while (!line.empty() && blank(line.back())) line.pop_back();
        if (!line.empty() && line.back() == '\r') line.pop_back();
        std::size_t at = 0;
        while (at < line.size() && blank(line[at])) ++at;
        const std::string_view token = std::string_view(line).substr(at);
        if (token.size() > 6 && token.substr(0, 6) == "newmtl" && blank(token[6])) {
            if (named) gives.push_back(has_kd);
            named = token.size() > 7 && token[7] != '\0';  // the library reads the name as a C string
            has_kd = false;
        } else if (token.size() > 2 && token.substr(0, 2) == "Kd" && blank(token[2])) {
            has_kd = true;
        }
    }
    gives.push_back(has_kd);
    return gives;
}

// The path of the .mtl file `name` (as an `mtllib` statement writes it) of an OBJ in `folder`:
// "./a.mtl" is "a.mtl", one file listed once among the run's inputs, as an OBJ's name is.
std::string material_file_path(const std::filesystem::path& folder, const std::string& name) {
    return path_in_folder(folder, name);
}

// Whether an entry of the OBJ's folder has `name` (obj_text_checks.h, LibraryFileExists): each
// name looked up once, however many `mtllib` lines repeat it, while the names held stay small.
class LibraryFileLookup {
public:
    explicit LibraryFileLookup(const std::filesystem::path& folder)
        : folder_(folder.empty() ? std::string() : folder.string() + "/") {}

    bool exists(const std::string& name) {
        if (const auto known = known_.find(name); known != known_.end()) return known->second;
        // The name as the system resolves it (material_file_path's, without its normalising,
        // which took most of the time of an OBJ of a million such lines).
        struct stat info {};
        const bool found = ::stat((name.front() == '/' ? name : folder_ + name).c_str(), &info) == 0;
        if (held_bytes_ + name.size() + 64 <= kMostHeldBytes) {
            held_bytes_ += name.size() + 64;
            known_.emplace(name, found);
        }
        return found;
    }
    LibraryFileExists as_function() {
        return [this](const std::string& name) { return exists(name); };
    }

private:
    static constexpr std::uint64_t kMostHeldBytes = 16u << 20;
    std::string folder_;  // with its '/', or "" for the current folder
    std::unordered_map<std::string, bool> known_;
    std::uint64_t held_bytes_ = 0;
};

// Reads each .mtl file an OBJ names, relative to the OBJ's folder, with the limits of any
// input file; the first failure is kept for read_obj to report. The materials are combined as
// tinyobjloader's LoadMtl would list them, file after file, a name's first definition kept,
// from each file's materials as the scene's MtlLibrary read them once.
class MaterialFiles {
public:
    MaterialFiles(std::filesystem::path folder, MtlLibrary& library) : folder_(std::move(folder)), library_(library) {}

    // Adds the materials of the .mtl `library` names; false (and problem() says why, from the
    // OBJ's line naming it, as every other problem of the OBJ) where it cannot.
    bool read(const ObjLibraryName& library) {
        const std::string& name = library.name;
        const std::filesystem::path path = material_file_path(folder_, name);  // as the system resolves it
        // One file named several ways ("a.mtl", "./a.mtl") is read once: its materials are
        // in the list already. It is still one of the OBJ's files, with the digest of its first read: the mesh cache
        // checks each name, so that a name later made to point elsewhere is seen.
        struct stat info {};
        const bool identified = ::stat(path.c_str(), &info) == 0;
        if (identified) {
            if (const auto known = read_.find({info.st_dev, info.st_ino}); known != read_.end()) {
                files_.push_back(path.string());
                digests_.push_back(digests_[known->second]);
                return true;
            }
        }
        const std::string shown = "mtllib " + printable(shortened(name, 200)) + ": ";
        const std::string where = "line " + std::to_string(library.line) + ": " + shown;
        if (read_.size() >= kMaxMtlFiles) {
            if (problem_.empty())
                problem_ = where + "the OBJ reads more than " + std::to_string(kMaxMtlFiles) + " .mtl files, the limit";
            return false;
        }
        // Read, checked and its materials listed once for all the scene's OBJ files that name it
        // (MtlLibrary).
        std::shared_ptr<const MtlFileRead> file = library_.read(path.string());
        if (file->read) {
            if (identified) read_.insert({{info.st_dev, info.st_ino}, digests_.size()});
            files_.push_back(path.string());
            digests_.push_back(file->digest);
        }
        if (!file->problem.empty()) {
            if (problem_.empty()) problem_ = where + file->problem;
            return false;
        }
        const MtlMaterials& materials = file->materials;
        if (material_count_ + materials.count > kMaxObjMaterials) {
            if (problem_.empty())
                problem_ = where + "it brings the OBJ's materials to " +
                           std::to_string(material_count_ + materials.count) + ", more than the limit of " +
                           std::to_string(kMaxObjMaterials);
            return false;
        }
        material_count_ += materials.count;
        note_redefinitions(name, materials);
        libraries_.push_back({std::move(file), shown});
        return true;
    }

    const std::string& problem() const { return problem_; }
    const std::filesystem::path& folder() const { return folder_; }
    // A warning for each .mtl file with a statement clrender reads written in another case.
    std::vector<std::string> miscased_statement_warnings() const {
        std::vector<std::string> warnings;
        for (const Library& library : libraries_) {
            const MtlMiscasedStatement& miscased = library.file->miscased;
            if (miscased.line == 0) continue;
            warnings.push_back(library.shown + "line " + std::to_string(miscased.line) + ": '" +
                               printable(miscased.written) + "' is not a .mtl statement (statements are "
                               "case-sensitive: '" + miscased.meant + "'): the line is ignored" +
                               (miscased.more > 0 ? " (and " + std::to_string(miscased.more) + " more such lines)" : ""));
        }
        return warnings;
    }
    // A warning for each .mtl file with a `Kd` before its first `newmtl`, which colours nothing.
    std::vector<std::string> colour_without_material_warnings() const {
        std::vector<std::string> warnings;
        for (const Library& library : libraries_) {
            if (const std::uint64_t line = library.file->colour_without_material; line != 0)
                warnings.push_back(library.shown + "line " + std::to_string(line) +
                                   ": a Kd before the first newmtl is the colour of no material: the line is ignored");
        }
        return warnings;
    }
    // A warning for the first material defined again (tinyobjloader keeps the first
    // definition, so the later one's colour is silently unused), or "".
    std::string redefinition_warning() const {
        if (redefined_ == 0) return "";
        return first_redefinition_ + ": the material is defined again; the first definition is used" +
               (redefined_ > 1 ? " (and " + std::to_string(redefined_ - 1) + " more materials defined again)" : "");
    }
    const std::vector<std::string>& files() const { return files_; }
    const std::vector<Sha256Digest>& digests() const { return digests_; }
    bool defines(const std::string& material) const { return material_named(material) != nullptr; }
    // The `Kd` of material `name` (its first definition, as LoadMtl keeps), where a .mtl file
    // gives it one.
    std::optional<Vec3> diffuse_of(const std::string& material) const {
        const MtlMaterial* found = material_named(material);
        if (!found || !found->gives_diffuse) return std::nullopt;
        return found->diffuse;
    }
    // The first `map_Kd` line of `material` ("mtllib a.mtl: line 3: map_Kd wood.png"), or "".
    std::string texture_map_of(const std::string& material) const {
        for (const Library& library : libraries_) {
            const auto map = library.file->texture_maps.find(material);
            if (map != library.file->texture_maps.end())
                return library.shown + "line " + std::to_string(map->second.line) + ": " +
                       printable(shortened(map->second.statement, 200));
        }
        return "";
    }

private:
    struct Library {
        std::shared_ptr<const MtlFileRead> file;
        std::string shown;  // "mtllib NAME: ", as the OBJ names it
    };

    // Material `name` as tinyobjloader's list would find it: in the first file that defines it.
    const MtlMaterial* material_named(const std::string& name) const {
        for (const Library& library : libraries_) {
            const MtlMaterials& materials = library.file->materials;
            if (const auto found = materials.first.find(name); found != materials.first.end())
                return &materials.list[found->second];
        }
        return nullptr;
    }

    // Counts the `newmtl` lines of .mtl `name` that define a name this OBJ's .mtl files defined
    // already, keeping the first for the warning. The OBJ's first file's own were counted when
    // it was read: an OBJ of one .mtl, the usual, does no work per material here.
    void note_redefinitions(const std::string& name, const MtlMaterials& materials) {
        const auto note = [&](const MtlDefinition& definition) {
            if (redefined_++ == 0)
                first_redefinition_ = "mtllib " + printable(shortened(name, 200)) + ": line " +
                                      std::to_string(definition.line) + ": newmtl " +
                                      printable(shortened(definition.name, 200));
        };
        if (libraries_.empty()) {
            if (materials.defined_again == 0) return;
            note(materials.definitions[materials.first_again]);
            redefined_ += materials.defined_again - 1;
            return;
        }
        if (libraries_.size() == 1) defined_ = libraries_.front().file->materials.defined;
        for (const MtlDefinition& definition : materials.definitions)
            if (!defined_.insert(definition.name).second) note(definition);
    }

    std::unordered_set<std::string> defined_;  // each name a `newmtl` line gave, across 2+ .mtl files
    std::uint64_t redefined_ = 0;
    std::string first_redefinition_;
    std::filesystem::path folder_;
    MtlLibrary& library_;
    std::string problem_;
    std::vector<std::string> files_;  // each .mtl read, for the run's list of inputs
    std::vector<Sha256Digest> digests_;  // of each, as read (the mesh cache's check)
    std::map<std::pair<dev_t, ino_t>, std::size_t> read_;  // each .mtl read, by identity: its digest's index
    std::vector<Library> libraries_;  // each .mtl whose materials the OBJ takes, in order
    std::size_t material_count_ = 0;  // of those files together, as LoadMtl would list them
};

Vec3 triple(const std::vector<tinyobj::real_t>& values, std::size_t index) {
    return {values[3 * index], values[3 * index + 1], values[3 * index + 2]};
}

bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// The line (from 1) of statement `keyword` number `index` (from 0) of `text`, and its words as
// a message quotes them.
std::pair<std::uint64_t, std::string> nth_statement(const std::string& text, std::string_view keyword,
                                                    std::size_t index) {
    std::pair<std::uint64_t, std::string> found{0, ""};
    std::size_t seen = 0;
    for_each_statement(text, keyword, [&](std::uint64_t line, std::string_view statement) {
        if (seen++ != index) return;
        const std::size_t start = statement.find_first_not_of(" \t");
        found = {line, printable(shortened(std::string(statement.substr(start)), 120))};
    });
    return found;
}

// The text checks read each number as correctly rounded and keep tinyobjloader's arithmetic
// finite, but the library rounds numbers of many digits its own way: "9.99...929928e14", within
// the position range, comes out as 1000000000000000.4, and a normal of 1.7976931348623157e308
// written with 48 digits as infinity. This keeps such a value from reaching the scene as NaN or
// a coordinate beyond the range, refused at the line of `text` that gives it.
void check_values_read(const ObjMesh& mesh, const std::string& text) {
    const std::string reader = "tinyobjloader, which builds the mesh, ";
    const std::string advice = "; write its numbers with fewer digits";
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        const Vec3& p = mesh.positions[i];
        if (finite(p) && std::fabs(p.x) <= kMaxCoordinate && std::fabs(p.y) <= kMaxCoordinate &&
            std::fabs(p.z) <= kMaxCoordinate)
            continue;
        const auto [line, statement] = nth_statement(text, "v", i);
        throw ObjError("line " + std::to_string(line) + ": '" + statement + "': " + reader + "reads it as " +
                       number_text(p.x) + " " + number_text(p.y) + " " + number_text(p.z) +
                       " (it rounds long numbers its own way): " + position_range_text() + advice);
    }
    for (std::size_t i = 0; i < mesh.normals.size(); ++i) {
        if (finite(mesh.normals[i])) continue;
        const auto [line, statement] = nth_statement(text, "vn", i);
        throw ObjError("line " + std::to_string(line) + ": '" + statement + "': " + reader +
                       "reads it as not finite (its arithmetic overflows near the largest number)" + advice);
    }
    if (mesh.diffuse && !finite(*mesh.diffuse)) throw ObjError("tinyobjloader read the material's Kd as not finite");
}

// A warning about the `usemtl` lines whose names `concerns` picks: the first such line and
// `problem` with its name, how many more such lines there are, then `consequence`. None where
// no line is picked.
void warn_about_uses(const ObjMaterialStatements& statements, const std::function<bool(const std::string&)>& concerns,
                     const std::string& problem, const std::string& consequence, ObjMesh& mesh) {
    const ObjMaterialStatements::Use* first = nullptr;
    std::uint64_t more = 0;
    for (const auto& use : statements.uses) {  // in the order of their first lines
        if (!concerns(use.name)) continue;
        more += first ? use.lines : use.lines - 1;
        if (!first) first = &use;
    }
    if (!first) return;
    mesh.warnings.push_back("line " + std::to_string(first->first_line) + ": usemtl " +
                            printable(shortened(first->whole, 200)) + ": " + problem +
                            (more > 0 ? " (nor those of " + std::to_string(more) + " more usemtl lines)" : "") +
                            consequence);
}

// A `usemtl` that names no material of the .mtl files leaves the mesh without the colour its
// author chose (tinyobjloader only warns).
void warn_about_undefined_materials(const ObjMaterialStatements& statements, const MaterialFiles& material_files,
                                    ObjMesh& mesh) {
    warn_about_uses(
        statements, [&](const std::string& name) { return !material_files.defines(name); },
        "no .mtl file of the OBJ defines this material", "; its faces take the scene's ambient, else 0.8 grey", mesh);
}

// Reads every .mtl file the OBJ names, each name once, in order, with the first
// problem kept by `material_files`.
void read_material_libraries(const ObjMaterialStatements& statements, MaterialFiles& material_files) {
    std::set<std::string> named;
    for (const ObjLibraryName& library : statements.libraries) {
        if (!named.insert(library.name).second) continue;
        if (!material_files.read(library)) return;
    }
}

// A `usemtl` names its material by its whole name where a .mtl file defines that ("usemtl my
// mat" for a `newmtl my mat`, a name that tinyobjloader's LoadMtl keeps whole), else by its first
// word, as tinyobjloader reads a `usemtl` (`usemtl wood oak` for a `newmtl wood`).
void choose_material_names(ObjMaterialStatements& statements, const MaterialFiles& material_files) {
    for (auto& use : statements.uses)
        if (use.whole != use.name && material_files.defines(use.whole)) use.name = use.whole;
    if (statements.first_face_whole != statements.first_face_material &&
        material_files.defines(statements.first_face_whole))
        statements.first_face_material = statements.first_face_whole;
}

// A mesh takes one colour (docs/scene-format.md, Meshes): a `usemtl` whose material's Kd is not
// the first face's (mesh.diffuse) is a warning.
void warn_about_unused_materials(const ObjMaterialStatements& statements, const MaterialFiles& material_files,
                                 ObjMesh& mesh) {
    const auto unused = [&](const std::string& name) {
        const std::optional<Vec3> diffuse = material_files.diffuse_of(name);
        return name != statements.first_face_material && diffuse && diffuse != mesh.diffuse;
    };
    warn_about_uses(statements, unused,
                    "a mesh takes one colour, the scene's ambient or else its first face's material's Kd; this "
                    "material's Kd is not used",
                    "", mesh);
}

// A mesh takes one colour (docs/scene-format.md, Meshes): the texture map (`map_Kd`) of a
// material that a `usemtl` uses is not drawn, which a warning says, naming the first.
void warn_about_texture_maps(const ObjMaterialStatements& statements, const MaterialFiles& material_files,
                             ObjMesh& mesh) {
    std::string first;
    std::uint64_t more = 0;
    for (const auto& use : statements.uses) {
        const std::string map = material_files.texture_map_of(use.name);
        if (!map.empty() && !first.empty()) ++more;
        if (!map.empty() && first.empty()) first = map;
    }
    if (first.empty()) return;
    mesh.warnings.push_back(first + ": a mesh takes one colour, the scene's ambient or else its first face's "
                                    "material's Kd; this texture is not drawn" +
                            (more > 0 ? " (nor those of " + std::to_string(more) + " more materials it uses)" : ""));
}

// A line whose first word is no OBJ statement is skipped by tinyobjloader in silence: a `v` line
// behind a byte order mark (files joined) or written "V" would shift the corners of every later
// face onto other positions, a typo drop what it meant. A warning names the first such line.
void warn_about_unknown_statements(const ObjTextCounts& counts, ObjMesh& mesh) {
    if (counts.unknown_statements == 0) return;
    const std::uint64_t more = counts.unknown_statements - 1;
    mesh.warnings.push_back("line " + std::to_string(counts.first_unknown_line) + ": '" +
                            printable(counts.first_unknown_keyword) + "' is not an OBJ statement: the line is ignored" +
                            (more > 0 ? " (and " + std::to_string(more) + " more such lines)" : ""));
}

// A mesh takes one colour (docs/scene-format.md, Meshes): colours given with the positions
// (`v x y z r g b`) are not drawn, which a warning says, naming the first such line.
void warn_about_vertex_colours(const ObjTextCounts& counts, ObjMesh& mesh) {
    if (counts.coloured_positions == 0) return;
    const std::uint64_t more = counts.coloured_positions - 1;
    mesh.warnings.push_back("line " + std::to_string(counts.first_coloured_line) +
                            ": a vertex colour after the position (v x y z r g b): a mesh takes one colour, the "
                            "scene's ambient or else its first face's material's Kd; the vertices' colours are not "
                            "drawn" +
                            (more > 0 ? " (nor those of " + std::to_string(more) + " more such lines)" : ""));
}

// Whether the fan of a polygon from its first corner (corners 1, k, k+1) covers the polygon and
// nothing else: every fan triangle turns the way the polygon does as a whole (their area vectors
// add up to the polygon's). A concave polygon whose first corner does not see every other corner
// (a U, an L started at an outer corner) fans into triangles turned the other way, which cover
// area outside its outline. Triangles without area (a corner on an edge) count for nothing.
bool fans_within_outline(const std::vector<Vec3>& positions, const tinyobj::index_t* corner, std::size_t corners) {
    if (corners < 4) return true;
    const Vec3& apex = positions[static_cast<std::size_t>(corner[0].vertex_index)];
    const auto fan_area = [&](std::size_t c) {
        return cross(positions[static_cast<std::size_t>(corner[c].vertex_index)] - apex,
                     positions[static_cast<std::size_t>(corner[c + 1].vertex_index)] - apex);
    };
    Vec3 whole{0, 0, 0};
    double sizes = 0;
    for (std::size_t c = 1; c + 1 < corners; ++c) {
        const Vec3 area = fan_area(c);
        whole = whole + area;
        sizes += length(area);
    }
    if (!(sizes > 0)) return true;  // no area at all: left out as such
    // Turned against the whole by more than rounding (relative to the polygon's size), or areas
    // that cancel out (a bow tie).
    const double tolerance = 1e-9 * sizes;
    if (length(whole) <= tolerance) return false;
    for (std::size_t c = 1; c + 1 < corners; ++c)
        if (dot(fan_area(c), whole) < -tolerance * length(whole)) return false;
    return true;
}

void warn_about_polygons_outside_their_outline(const std::string& text, std::uint64_t bad_faces,
                                                std::uint64_t first_bad_face, std::size_t first_bad_corners,
                                                ObjMesh& mesh) {
    if (bad_faces == 0) return;
    std::uint64_t face = 0, line = 0;
    for_each_statement(text, "f", [&](std::uint64_t number, std::string_view) {
        if (face++ == first_bad_face) line = number;
    });
    const std::uint64_t more = bad_faces - 1;
    mesh.warnings.push_back("line " + std::to_string(line) + ": a polygon of " + std::to_string(first_bad_corners) +
                            " corners that is not convex as seen from its first corner: it is drawn as a fan from "
                            "that corner, which covers area outside its outline" +
                            (more > 0 ? " (and " + std::to_string(more) + " more such faces)" : "") +
                            "; triangulate it when exporting, or start it at a corner that sees every other corner");
}

// parse_obj once the text's checks have passed; `material_files` reads the .mtl files, all of
// them before the faces (docs/scene-format.md, Meshes), which tinyobjloader then reads without
// their `mtllib` and `usemtl` lines.
ObjMesh parse_checked(const std::string& text, const ObjTextCounts& counts, MaterialFiles& material_files) {
    LibraryFileLookup library_files(material_files.folder());
    ObjMaterialStatements statements = material_statements(text, library_files.as_function());
    read_material_libraries(statements, material_files);
    if (!material_files.problem().empty()) throw ObjError(material_files.problem());
    choose_material_names(statements, material_files);

    tinyobj::attrib_t attributes;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> unused_materials;
    std::string warning, error;
    std::istringstream stream(obj_statements_used(text));
    const bool read = tinyobj::LoadObj(&attributes, &shapes, &unused_materials, &warning, &error, &stream,
                                       /*readMatFn=*/nullptr, /*triangulate=*/false, /*default_vcols_fallback=*/false);
    if (!read) throw ObjError(printable(shortened(first_line(error), 200)));

    ObjMesh mesh;
    mesh.material_files = material_files.files();
    mesh.material_digests = material_files.digests();
    const std::size_t positions = attributes.vertices.size() / 3;
    const std::size_t normals = attributes.normals.size() / 3;
    if (positions != counts.positions || normals != counts.normals) {
        throw ObjError("tinyobjloader read " + std::to_string(positions) + " positions and " + std::to_string(normals) +
                       " normals where the file has " + std::to_string(counts.positions) + " and " +
                       std::to_string(counts.normals));
    }
    mesh.positions.reserve(positions);
    for (std::size_t i = 0; i < positions; ++i) mesh.positions.push_back(triple(attributes.vertices, i));
    mesh.normals.reserve(normals);
    for (std::size_t i = 0; i < normals; ++i) mesh.normals.push_back(triple(attributes.normals, i));
    mesh.triangles.reserve(counts.triangles);
    mesh.triangle_normals.reserve(counts.triangles);

    const auto in_range = [](int index, std::size_t count) { return index >= 0 && static_cast<std::size_t>(index) < count; };
    std::uint64_t outside_outline = 0, first_outside = 0;
    std::size_t first_outside_corners = 0;
    for (const tinyobj::shape_t& shape : shapes) {
        std::size_t offset = 0;
        for (std::size_t face = 0; face < shape.mesh.num_face_vertices.size(); ++face) {
            const std::size_t corners = shape.mesh.num_face_vertices[face];
            const tinyobj::index_t* corner = &shape.mesh.indices[offset];
            offset += corners;
            bool every_normal = true;
            for (std::size_t c = 0; c < corners; ++c) {
                if (!in_range(corner[c].vertex_index, positions)) throw ObjError("a face names a missing position");
                every_normal = every_normal && in_range(corner[c].normal_index, normals);
            }
            if (!fans_within_outline(mesh.positions, corner, corners) && outside_outline++ == 0) {
                first_outside = mesh.faces;
                first_outside_corners = corners;
            }
            for (std::size_t c = 1; c + 1 < corners; ++c) {  // a fan from the first corner
                mesh.triangles.push_back({static_cast<std::uint32_t>(corner[0].vertex_index),
                                          static_cast<std::uint32_t>(corner[c].vertex_index),
                                          static_cast<std::uint32_t>(corner[c + 1].vertex_index)});
                if (every_normal) {
                    mesh.triangle_normals.push_back({corner[0].normal_index, corner[c].normal_index, corner[c + 1].normal_index});
                } else {
                    mesh.triangle_normals.push_back({-1, -1, -1});
                }
            }
            ++mesh.faces;
        }
    }
    if (mesh.faces != counts.faces || mesh.triangles.size() != counts.triangles) {
        throw ObjError("tinyobjloader read " + std::to_string(mesh.faces) + " faces of " +
                       std::to_string(mesh.triangles.size()) + " triangles where the file has " +
                       std::to_string(counts.faces) + " of " + std::to_string(counts.triangles));
    }
    mesh.diffuse = material_files.diffuse_of(statements.first_face_material);
    check_values_read(mesh, text);
    if (const std::string redefined = material_files.redefinition_warning(); !redefined.empty())
        mesh.warnings.push_back(redefined);
    warn_about_undefined_materials(statements, material_files, mesh);
    warn_about_unused_materials(statements, material_files, mesh);
    warn_about_texture_maps(statements, material_files, mesh);
    for (std::string& warning : material_files.miscased_statement_warnings()) mesh.warnings.push_back(std::move(warning));
    for (std::string& warning : material_files.colour_without_material_warnings())
        mesh.warnings.push_back(std::move(warning));
    warn_about_unknown_statements(counts, mesh);
    warn_about_vertex_colours(counts, mesh);
    warn_about_polygons_outside_their_outline(text, outside_outline, first_outside, first_outside_corners, mesh);
    return mesh;
}

}  // namespace

MtlMaterials read_mtl_materials(const std::string& used, std::string& problem) {
    MtlMaterials read;
    std::vector<tinyobj::material_t> materials;
    std::map<std::string, int> names;
    const std::vector<bool> gives_diffuse = materials_giving_diffuse(used);
    read.count = gives_diffuse.size();
    // Every OBJ refuses a file of more materials than an OBJ may have, with the limit's message:
    // LoadMtl would first hold about a kilobyte for each.
    if (read.count > kMaxObjMaterials) return read;
    std::istringstream stream(used);
    std::string warning, error;
    tinyobj::LoadMtl(&names, &materials, &stream, &warning, &error);
    if (materials.size() != gives_diffuse.size()) {
        problem = "tinyobjloader read " + std::to_string(materials.size()) + " materials where the file defines " +
                  std::to_string(gives_diffuse.size());
        return read;
    }
    read.list.reserve(materials.size());
    for (std::size_t i = 0; i < materials.size(); ++i) {
        const auto& kd = materials[i].diffuse;
        read.list.push_back({Vec3{kd[0], kd[1], kd[2]}, gives_diffuse[i]});
    }
    // Each name as clrender reads it (mtl_material_name: " red" of "newmtl  red" is "red"), its
    // first definition where two of the library's names are one so.
    read.first.reserve(names.size());
    for (const auto& [name, index] : names) {
        if (index < 0 || static_cast<std::size_t>(index) >= materials.size()) continue;
        const auto [entry, added] = read.first.emplace(trimmed_material_name(name), index);
        if (!added) entry->second = std::min<std::size_t>(entry->second, index);
    }
    for_each_statement(used, "newmtl", [&](std::uint64_t line, std::string_view statement) {
        std::string material = mtl_material_name(statement);
        if (material.empty()) return;
        const bool again = !read.defined.insert(material).second;
        if (again && read.defined_again++ == 0) read.first_again = read.definitions.size();
        read.definitions.push_back({line, std::move(material)});
    });
    return read;
}

std::vector<std::string> mtl_texture_files(std::string_view text, bool* cut) {
    // Each statement LoadMtl reads a texture from, and the texture of the material it sets
    // (`map_bump`, `map_Bump` and `bump` set one, `map_disp`, `map_Disp` and `disp` another).
    static constexpr std::pair<std::string_view, int> kTextures[] = {
        {"map_Ka", 0},  {"map_Kd", 1},  {"map_Ks", 2},   {"map_Ns", 3},   {"map_bump", 4}, {"map_Bump", 4},
        {"bump", 4},    {"map_d", 5},   {"map_disp", 6}, {"map_Disp", 6}, {"disp", 6},     {"refl", 7},
        {"map_Pr", 8},  {"map_Pm", 9},  {"map_Ps", 10},  {"map_Ke", 11},  {"norm", 12}};
    std::vector<std::string> names;  // each slot's name, in the order of the slots' first statements
    std::map<std::pair<std::uint64_t, int>, std::size_t> slots;  // (material, texture): its slot in `names`
    std::uint64_t material = 0;
    for_each_keyword(text, [&](std::uint64_t, std::string_view keyword, std::string_view line) {
        if (keyword == "newmtl") ++material;
        const auto texture = std::find_if(std::begin(kTextures), std::end(kTextures),
                                          [&](const auto& statement) { return statement.first == keyword; });
        if (texture == std::end(kTextures)) return;
        // A file of more materials than an OBJ may have is refused; the textures of its first
        // ones are still listed, and the list stays bounded (at most 13 names a material).
        if (material > kMaxObjMaterials) {
            if (cut) *cut = true;
            return;
        }
        // The rest of the line, without the trailing blanks LoadMtl trims, read up to a NUL.
        std::string rest(line.substr(line.find(keyword) + keyword.size()));
        while (!rest.empty() && (rest.back() == ' ' || rest.back() == '\t')) rest.pop_back();
        std::string name;
        tinyobj::texture_option_t options;
        if (!tinyobj::ParseTextureNameAndOption(&name, &options, rest.c_str()) || name.empty()) return;
        const auto [slot, added] = slots.try_emplace({material, texture->second}, names.size());
        if (added)
            names.push_back(std::move(name));
        else
            names[slot->second] = std::move(name);  // LoadMtl keeps the last
    });
    std::vector<std::string> files;
    std::unordered_set<std::string> listed;
    for (std::string& name : names)
        if (listed.insert(name).second) files.push_back(std::move(name));
    return files;
}

namespace {

// The counts of an OBJ text that passes clrender's checks of its encoding and lines; ObjError
// (with the line) where it does not.
ObjTextCounts checked_counts(const std::string& text) {
    if (const std::string encoding = saved_text_problem(text); !encoding.empty()) throw ObjError(encoding);
    ObjTextProblem problem;
    const ObjTextCounts counts = check_obj_text(text, kMaxObjTriangles, problem);
    if (problem.line != 0) throw ObjError("line " + std::to_string(problem.line) + ": " + problem.detail);
    return counts;
}

// MeshMemoryError where parsing a text of `text_bytes` and `counts` would take more than
// `memory_budget` (obj_reader.h).
void check_parse_memory(std::uint64_t text_bytes, const ObjTextCounts& counts, std::uint64_t memory_budget) {
    const std::uint64_t vertex_lines = counts.positions + counts.texcoords + counts.normals;
    const std::uint64_t needed = 2 * text_bytes + counts.triangles * kParsedTriangleBytes +
                                 counts.named_statements * kStatementBytes +
                                 counts.grouping_statement_bytes * kStatementTextBytes + vertex_lines * kVertexLineBytes;
    if (needed > memory_budget) {
        const std::uint64_t grouping = counts.grouping_statement_bytes;
        throw MeshMemoryError("its " + std::to_string(counts.triangles) + " triangles and " +
                              std::to_string(vertex_lines) + " v, vt and vn lines" +
                              (grouping > 0 ? " (and " + std::to_string(grouping) + " bytes of o, g, s, usemtl and "
                                              "mtllib lines)" : "") +
                              " would take about " + gib_text(needed) + " to read, more than the " +
                              gib_text(memory_budget) +
                              " a scene's meshes may take: half of this machine's memory (docs/robustness.md, Memory)");
    }
}

// Every .mtl file the OBJ `text` names, whichever line it fails at: they are the model's files,
// which no output may replace. Each file once however many names reach it (its key, as the
// output check compares files), in the order of first mention; `error` gets them, or why they
// could not all be listed: more than kMaxMtlFiles files, or names past kMaxMtlNameBytes (a list
// cut there left a later file unprotected, which an output then replaced).
void list_named_material_files(const std::string& text, const std::filesystem::path& folder, ObjError& error) {
    std::unordered_set<std::string> names;
    std::uint64_t name_bytes = 0;
    std::set<FileInFolderKey> files;
    LibraryFileLookup library_files(folder);
    for_each_library_name(text, [&](std::uint64_t line, std::string name) {
        if (names.count(name) > 0) return true;
        name_bytes += name.size() + 64;  // with the set's node
        if (name_bytes > kMaxMtlNameBytes) {
            error.material_files_incomplete = "its mtllib names up to line " + std::to_string(line) +
                                              " take more than " + std::to_string(kMaxMtlNameBytes >> 20) + " MiB";
            return false;
        }
        std::string path = material_file_path(folder, name);
        names.insert(std::move(name));
        if (!files.insert(file_in_folder_key(path)).second) return true;
        if (files.size() > kMaxMtlFiles) {
            error.material_files_incomplete = "it names more than " + std::to_string(kMaxMtlFiles) +
                                              " .mtl files (line " + std::to_string(line) + ")";
            return false;
        }
        error.material_files.push_back(std::move(path));
        return true;
    }, library_files.as_function());
}

}  // namespace

ObjMesh parse_obj(const std::string& text, const std::string& path, std::uint64_t memory_budget, MtlLibrary* library) {
    const std::filesystem::path folder = std::filesystem::path(path).parent_path();
    try {
        const ObjTextCounts counts = checked_counts(text);
        check_parse_memory(text.size(), counts, memory_budget);
        MtlLibrary own_library;
        MaterialFiles material_files(folder, library ? *library : own_library);
        return parse_checked(text, counts, material_files);
    } catch (ObjError& failure) {
        failure.material_files.clear();
        list_named_material_files(text, folder, failure);
        throw;
    }
}

std::string read_obj_text(const std::string& path) {
    try {
        return read_bounded_file(path, kMaxObjFileBytes);
    } catch (const BoundedFileError& failure) {
        throw ObjError(failure.what());
    }
}

ObjMesh read_obj(const std::string& path, std::uint64_t memory_budget) {
    return parse_obj(read_obj_text(path), path, memory_budget);
}

}  // namespace clr
