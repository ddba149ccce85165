#include "scene/mtl_library.h"

#include <sys/stat.h>

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
    if (const std::string encoding = saved_text_problem(text); !encoding.empty()) {
        file.problem = encoding;
        return file;
    }
    if (const ObjTextProblem colour = check_mtl_text(text); colour.line != 0) {
        file.problem = "line " + std::to_string(colour.line) + ": " + colour.detail;
        return file;
    }
    file.texture_maps = diffuse_texture_maps(text);
    file.used = mtl_statements_used(text);
    return file;
}

}  // namespace

const MtlFileRead& MtlLibrary::read(const std::string& path) {
    struct stat info {};
    if (::stat(path.c_str(), &info) != 0) return last_ = read_mtl_file(path);  // its read names why
    const std::pair<dev_t, ino_t> identity{info.st_dev, info.st_ino};
    if (const auto known = kept_.find(identity); known != kept_.end()) return known->second;
    MtlFileRead file = read_mtl_file(path);
    const std::uint64_t bytes = file.used.size() + 256;
    if (kept_bytes_ + bytes > kMostKeptBytes) return last_ = std::move(file);
    kept_bytes_ += bytes;
    return kept_.emplace(identity, std::move(file)).first->second;
}

}  // namespace clr
