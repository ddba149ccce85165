// Fuzzes the OBJ reader: clr::parse_obj on the input as the text of an OBJ file.
//
// The contract under test (scene/obj_reader.h): any text either becomes a mesh that keeps the
// reader's promises (checked below) or is refused with a clr::ObjError of one printable line.
// Anything else is a bug: another exception type, a crash, a hang or a sanitizer report.
//
// The "file" is <work folder>/mesh.obj, beside a material file named as the seeds name it
// (materials.mtl); a mutated `mtllib` name that misses it is an error, which is fine. An
// absolute or "../" name can reach other files, which are only ever read, never written.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>
#include <typeinfo>

#include "fuzz_support.h"
#include "scene/obj_reader.h"
#include "scene/value_ranges.h"

namespace {

using clr::fuzz::report_bug;

const std::string& obj_path() {
    static const std::string path = clr::fuzz::work_folder() + "/mesh.obj";
    return path;
}

bool finite(const clr::Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

void check_mesh(const clr::ObjMesh& mesh) {
    for (const clr::Vec3& p : mesh.positions) {
        if (!finite(p) || std::fabs(p.x) > clr::kMaxCoordinate || std::fabs(p.y) > clr::kMaxCoordinate ||
            std::fabs(p.z) > clr::kMaxCoordinate)
            report_bug("position not finite or out of range", "");
    }
    for (const clr::Vec3& n : mesh.normals)
        if (!finite(n)) report_bug("normal not finite", "");
    if (mesh.triangle_normals.size() != mesh.triangles.size()) report_bug("a normal triple per triangle", "");
    if (mesh.triangles.size() > clr::kMaxObjTriangles) report_bug("more triangles than the limit", "");
    if (mesh.triangles.size() < mesh.faces) report_bug("fewer triangles than faces", "");
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        for (std::uint32_t index : mesh.triangles[t])
            if (index >= mesh.positions.size()) report_bug("position index out of range", std::to_string(index));
        const auto& normals = mesh.triangle_normals[t];
        const bool none = normals[0] == -1 && normals[1] == -1 && normals[2] == -1;
        for (std::int32_t index : normals)
            if (!none && (index < 0 || static_cast<std::size_t>(index) >= mesh.normals.size()))
                report_bug("normal index out of range", std::to_string(index));
    }
    if (mesh.diffuse && !finite(*mesh.diffuse)) report_bug("diffuse colour not finite", "");
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    const std::string material = "newmtl red\nKd 1 0 0\nnewmtl grey\nKd 0.5 0.5 0.5\nKs 1 1 1\nNs 20\n";
    clr::fuzz::write_file(clr::fuzz::work_folder() + "/materials.mtl", material.data(), material.size());
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        check_mesh(clr::parse_obj(text, obj_path()));
    } catch (const clr::ObjError& error) {
        if (std::string(error.what()).empty()) report_bug("ObjError without a reason", "");
        if (!clr::fuzz::is_one_printable_line(error.what())) report_bug("ObjError is not one printable line", error.what());
    } catch (const std::exception& error) {
        report_bug(std::string("parse_obj threw ") + typeid(error).name() + " instead of clr::ObjError", error.what());
    }
    return 0;
}
