#include "scene/mesh_cache.h"

#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>
#include <memory>
#include <type_traits>
#include <vector>

#include "core/cache_folder.h"
#include "core/code_file.h"
#include "scene/bounded_file.h"
#include "scene/mtl_library.h"
#include "scene/value_ranges.h"

namespace clr {
namespace {

// The most .mtl files an entry lists: a mesh that read more is not stored.
constexpr std::uint64_t kMostMaterialFiles = 1024;

CacheEntryKind mesh_entries(std::uint64_t size_limit) {
    // A header claiming more than a stored mesh and its .mtl list (kMostMaterialFiles paths) is
    // refused before anything is allocated, as one larger than the whole cache.
    const std::uint64_t largest = MeshCache::kLargestStoredBytes + (std::uint64_t(8) << 20);
    return {"mesh", {'c', 'l', 'r', 'm', 'e', 's', 'h', '1'}, MeshCache::kFormatVersion, std::min(size_limit, largest)};
}

// The clrender build that parses: the file holding read_obj, its size and modification time.
const std::string& build_identity() {
    static const std::string identity = code_file_identity(reinterpret_cast<const void*>(&parse_obj));
    return identity;
}

// The payload: counts, then the arrays as the reader made them (doubles and 32-bit indices,
// in this machine's byte order: an entry never leaves the machine's cache folder), then each
// .mtl file's path and SHA-256.
class PayloadWriter {
public:
    // `size`: the whole payload's, allocated once (a grown vector would copy the mesh again).
    explicit PayloadWriter(std::size_t size) { out_.reserve(size); }

    template <typename T>
    void put(const T& value) {
        static_assert(std::is_trivially_copyable_v<T>);
        const auto* bytes = reinterpret_cast<const unsigned char*>(&value);
        out_.insert(out_.end(), bytes, bytes + sizeof(T));
    }
    template <typename T>
    void put_all(const std::vector<T>& values) {
        static_assert(std::is_trivially_copyable_v<T>);
        const auto* bytes = reinterpret_cast<const unsigned char*>(values.data());
        out_.insert(out_.end(), bytes, bytes + values.size() * sizeof(T));
    }
    void put_text(const std::string& text) {
        put<std::uint64_t>(text.size());
        out_.insert(out_.end(), text.begin(), text.end());
    }
    std::vector<unsigned char>& bytes() { return out_; }

private:
    std::vector<unsigned char> out_;
};

// Reads what PayloadWriter wrote; every read is checked against what is left, so a payload
// that says more than it holds fails (false) instead of reading beyond it.
class PayloadReader {
public:
    explicit PayloadReader(const std::vector<unsigned char>& bytes) : bytes_(bytes) {}

    template <typename T>
    bool get(T& value) {
        if (left() < sizeof(T)) return false;
        std::memcpy(&value, bytes_.data() + at_, sizeof(T));
        at_ += sizeof(T);
        return true;
    }
    template <typename T>
    bool get_all(std::vector<T>& values, std::uint64_t count) {
        if (count > left() / sizeof(T)) return false;
        values.resize(count);
        // memcpy's pointers must not be null even for no bytes, and an empty vector's may be.
        if (count > 0) std::memcpy(values.data(), bytes_.data() + at_, count * sizeof(T));
        at_ += count * sizeof(T);
        return true;
    }
    bool get_text(std::string& text) {
        std::uint64_t size = 0;
        if (!get(size) || size > left()) return false;
        text.assign(reinterpret_cast<const char*>(bytes_.data() + at_), size);
        at_ += size;
        return true;
    }
    bool at_end() const { return at_ == bytes_.size(); }

private:
    std::size_t left() const { return bytes_.size() - at_; }
    const std::vector<unsigned char>& bytes_;
    std::size_t at_ = 0;
};

Sha256Digest file_digest(const std::string& path, std::uint64_t max_bytes) {
    const std::string text = read_bounded_file(path, max_bytes);
    return sha256(text.data(), text.size());
}

bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// What parse_obj guarantees of a mesh it returns (obj_reader.cpp's checks).
bool as_the_reader_makes_them(const ObjMesh& mesh) {
    if (mesh.triangles.size() != mesh.triangle_normals.size() || mesh.triangles.size() > kMaxObjTriangles ||
        mesh.faces > mesh.triangles.size() || (mesh.faces == 0) != mesh.triangles.empty())
        return false;
    for (const Vec3& p : mesh.positions) {
        if (!finite(p) || std::fabs(p.x) > kMaxCoordinate || std::fabs(p.y) > kMaxCoordinate ||
            std::fabs(p.z) > kMaxCoordinate)
            return false;
    }
    for (const Vec3& n : mesh.normals)
        if (!finite(n)) return false;
    if (mesh.diffuse && !finite(*mesh.diffuse)) return false;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const bool with_normals = mesh.triangle_normals[t][0] >= 0;
        for (int c = 0; c < 3; ++c) {
            if (mesh.triangles[t][c] >= mesh.positions.size()) return false;
            const std::int32_t normal = mesh.triangle_normals[t][c];
            if (with_normals ? (normal < 0 || static_cast<std::uint64_t>(normal) >= mesh.normals.size()) : normal != -1)
                return false;
        }
    }
    return true;
}

}  // namespace

MeshCache MeshCache::from_environment() { return MeshCache(cache_folder_from_environment()); }

MeshCache::MeshCache(std::string cache_folder, std::uint64_t size_limit, std::uint64_t largest_mesh)
    : entries_(std::move(cache_folder), "meshes", mesh_entries(size_limit), size_limit), largest_mesh_(largest_mesh) {}

MeshCache::Key MeshCache::key(const std::string& path, const std::string& text) {
    return Sha256()
        .add_field(std::string("clrender parsed OBJ mesh"))
        .add_number(kFormatVersion)
        .add_field(build_identity())
        // The working folder and the path as given: relative paths, the .mtl files' too, then
        // name the same files.
        .add_field(std::filesystem::current_path().string())
        .add_field(path)
        .add_field(text.data(), text.size())
        .finish();
}

std::optional<ObjMesh> MeshCache::load(const Key& key, MtlLibrary* library) const {
    std::optional<CacheEntry> entry = entries_.load(key);
    if (!entry) return std::nullopt;
    ObjMesh mesh;
    PayloadReader in(entry->payload);
    std::uint64_t positions = 0, normals = 0, triangles = 0, has_diffuse = 0, materials = 0;
    Vec3 diffuse;
    bool read = in.get(positions) && in.get(normals) && in.get(triangles) && in.get(mesh.faces) &&
                in.get(has_diffuse) && in.get(diffuse) && in.get(materials) && in.get_all(mesh.positions, positions) &&
                in.get_all(mesh.normals, normals) && in.get_all(mesh.triangles, triangles) &&
                in.get_all(mesh.triangle_normals, triangles) && materials <= kMostMaterialFiles;
    for (std::uint64_t i = 0; read && i < materials; ++i) {
        mesh.material_files.emplace_back();
        mesh.material_digests.emplace_back();
        read = in.get_text(mesh.material_files.back()) && in.get(mesh.material_digests.back());
    }
    if (has_diffuse) mesh.diffuse = diffuse;
    if (!read || !in.at_end() || has_diffuse > 1 || !as_the_reader_makes_them(mesh)) {
        entries_.remove(key);  // a verified entry cannot say this; ours all the same, and useless
        return std::nullopt;
    }
    // Each .mtl as the parse read it; otherwise a miss (the entry stays for the files it fits).
    // A file named several ways ("a.mtl", "./a.mtl") is hashed once, by its identity.
    std::map<std::pair<dev_t, ino_t>, Sha256Digest> hashed;
    for (std::size_t i = 0; i < mesh.material_files.size(); ++i) {
        if (library) {  // read once for all the scene's OBJ files that name it
            const std::shared_ptr<const MtlFileRead> file = library->read(mesh.material_files[i]);
            if (!file->read || file->digest != mesh.material_digests[i]) return std::nullopt;
            continue;
        }
        struct stat info {};
        if (::stat(mesh.material_files[i].c_str(), &info) != 0) return std::nullopt;
        auto known = hashed.find({info.st_dev, info.st_ino});
        if (known == hashed.end()) {
            try {
                known = hashed.insert({{info.st_dev, info.st_ino}, file_digest(mesh.material_files[i], kMaxMtlFileBytes)}).first;
            } catch (const BoundedFileError&) {
                return std::nullopt;
            }
        }
        if (known->second != mesh.material_digests[i]) return std::nullopt;
    }
    return mesh;
}

void MeshCache::store(const Key& key, const ObjMesh& mesh) const {
    if (!enabled() || mesh.material_digests.size() != mesh.material_files.size() ||
        mesh.material_files.size() > kMostMaterialFiles)
        return;
    // The payload is built whole before it is written: a copy of the mesh, so a mesh too large
    // to copy without pressing on the machine's memory is not stored.
    const std::uint64_t bytes = (mesh.positions.size() + mesh.normals.size()) * sizeof(Vec3) +
                                mesh.triangles.size() * (sizeof(mesh.triangles[0]) + sizeof(mesh.triangle_normals[0]));
    if (bytes > largest_mesh_) return;
    std::uint64_t listed = 0;
    for (const std::string& path : mesh.material_files) listed += sizeof(std::uint64_t) + path.size() + sizeof(Sha256Digest);
    PayloadWriter out(6 * sizeof(std::uint64_t) + sizeof(Vec3) + bytes + listed);  // counts, colour, arrays, list
    out.put<std::uint64_t>(mesh.positions.size());
    out.put<std::uint64_t>(mesh.normals.size());
    out.put<std::uint64_t>(mesh.triangles.size());
    out.put<std::uint64_t>(mesh.faces);
    out.put<std::uint64_t>(mesh.diffuse ? 1 : 0);
    out.put(mesh.diffuse.value_or(Vec3{}));
    out.put<std::uint64_t>(mesh.material_files.size());
    out.put_all(mesh.positions);
    out.put_all(mesh.normals);
    out.put_all(mesh.triangles);
    out.put_all(mesh.triangle_normals);
    for (std::size_t i = 0; i < mesh.material_files.size(); ++i) {
        out.put_text(mesh.material_files[i]);
        out.put(mesh.material_digests[i]);
    }
    entries_.store(key, {0, 0}, out.bytes().data(), out.bytes().size());
}

ObjMesh read_obj_through_cache(const std::string& path, const MeshCache& cache, std::uint64_t memory_budget,
                               MtlLibrary* library) {
    const std::string text = read_obj_text(path);
    if (!cache.enabled() || text.size() < MeshCache::kSmallestStoredBytes)
        return parse_obj(text, path, memory_budget, library);
    std::optional<MeshCache::Key> key;
    try {
        key = MeshCache::key(path, text);
        if (std::optional<ObjMesh> cached = cache.load(*key, library)) return std::move(*cached);
    } catch (const std::exception&) {  // no hashing (libcrypto refused), or no memory for the entry: no caching
        key.reset();
    }
    ObjMesh mesh = parse_obj(text, path, memory_budget, library);
    if (key && !mesh.triangles.empty() && mesh.warnings.empty()) {  // an entry does not keep warnings
        try {
            cache.store(*key, mesh);
        } catch (const std::exception&) {  // best effort
        }
    }
    return mesh;
}

}  // namespace clr
