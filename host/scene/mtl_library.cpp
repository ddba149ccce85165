#include "scene/mtl_library.h"

#include <sys/stat.h>

#include "core/printable_text.h"
#include "scene/bounded_file.h"
#include "scene/obj_reader.h"
#include "scene/obj_text_checks.h"
#include "scene/text_encoding.h"

namespace clr {
namespace {

// Reads and checks the .mtl at `path` as an OBJ reader uses it.
MtlFileRead read_mtl_file(const std::string& path) {
    MtlFileRead file;
    std::string text;
    try {
        text = read_bounded_file(path, kMaxMtlFileBytes);
    } catch (const BoundedFileError& failure) {
        file.problem = failure.what();
        return file;
    }
    file.read = true;
    file.digest = sha256(text.data(), text.size());
    // Whatever is wrong with it: with --placeholders the run goes on with a cube in the model's
    // place, and an output must not replace the textures of the model it stands in for.
    file.texture_files = mtl_texture_files(text, &file.texture_files_cut);
    if (const std::string encoding = saved_text_problem(text); !encoding.empty()) {
        file.problem = encoding;
        return file;
    }
    if (const ObjTextProblem colour = check_mtl_text(text); colour.line != 0) {
        file.problem = "line " + std::to_string(colour.line) + ": " + colour.detail;
        return file;
    }
    file.texture_maps = diffuse_texture_maps(text);
    file.miscased = first_miscased_statement(text);
    file.colour_without_material = first_colour_without_material(text);
    file.materials = read_mtl_materials(mtl_statements_used(text), file.problem);
    return file;
}

// About what a file's read holds, for the library's bound.
std::uint64_t bytes_held(const MtlFileRead& file) {
    std::uint64_t bytes = 256 + file.materials.list.size() * sizeof(MtlMaterial);
    for (const MtlDefinition& definition : file.materials.definitions)
        bytes += sizeof(MtlDefinition) + 3 * (definition.name.size() + 64);  // with `defined` and `first`
    for (const auto& [name, map] : file.texture_maps) bytes += name.size() + map.statement.size() + 96;
    bytes += file.miscased.written.size() + file.miscased.meant.size();
    for (const std::string& name : file.texture_files) bytes += name.size() + 32;
    return bytes;
}

// `bytes` in whole MiB, rounded up, for messages.
std::string mib_text(std::uint64_t bytes) { return std::to_string((bytes + (1u << 20) - 1) >> 20) + " MiB"; }

}  // namespace

std::shared_ptr<const MtlFileRead> MtlLibrary::read(const std::string& path) {
    struct stat info {};
    if (::stat(path.c_str(), &info) != 0) {
        ++files_parsed_;
        return std::make_shared<const MtlFileRead>(read_mtl_file(path));  // its read names why
    }
    const std::pair<dev_t, ino_t> identity{info.st_dev, info.st_ino};
    if (const auto known = kept_.find(identity); known != kept_.end()) return known->second;
    ++files_parsed_;
    auto file = std::make_shared<const MtlFileRead>(read_mtl_file(path));
    const std::uint64_t bytes = bytes_held(*file);
    if (kept_bytes_ + bytes > most_held_bytes_) {
        throw MeshMemoryError("the .mtl '" + printable(path) + "' takes about " + mib_text(bytes) +
                              " to hold once read (its material names and texture statements), which brings the "
                              ".mtl files the scene holds past the " + mib_text(most_held_bytes_) +
                              " they may take (docs/robustness.md, Memory)");
    }
    kept_bytes_ += bytes;
    kept_.emplace(identity, file);
    return file;
}

}  // namespace clr
