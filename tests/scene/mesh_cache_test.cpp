// The parsed-mesh cache (scene/mesh_cache.h): a second read of a large OBJ is the stored mesh,
// equal to a fresh parse; an edited OBJ or .mtl is a miss; a damaged entry or one whose mesh the
// reader would refuse is never used; failures and small files are not stored.
#include "scene/mesh_cache.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "scene/mtl_library.h"
#include "support/obj_text.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using testing::TempFolder;

void expect_same_mesh(const ObjMesh& a, const ObjMesh& b) {
    EXPECT_EQ(a.positions, b.positions);
    EXPECT_EQ(a.normals, b.normals);
    EXPECT_EQ(a.triangles, b.triangles);
    EXPECT_EQ(a.triangle_normals, b.triangle_normals);
    EXPECT_EQ(a.faces, b.faces);
    ASSERT_EQ(a.diffuse.has_value(), b.diffuse.has_value());
    if (a.diffuse) {
        EXPECT_EQ(*a.diffuse, *b.diffuse);
    }
    EXPECT_EQ(a.material_files, b.material_files);
    EXPECT_EQ(a.material_digests, b.material_digests);
}

class MeshCacheTest : public ::testing::Test {
protected:
    void SetUp() override {
        obj_ = folder_.write("grid.obj", testing::grid_obj_text(160));
        ASSERT_GE(fs::file_size(obj_), MeshCache::kSmallestStoredBytes);
        folder_.write("grid.mtl", "newmtl green\nKd 0.1 0.7 0.2\n");
    }
    std::string entry() const { return cache_.path(MeshCache::key(obj_, testing::read_bytes(obj_))); }

    TempFolder folder_;
    MeshCache cache_{folder_.file("cache")};
    std::string obj_;
};

TEST_F(MeshCacheTest, TheSecondReadIsTheStoredMeshAndEqualsAFreshParse) {
    const ObjMesh parsed = read_obj(obj_);
    const ObjMesh first = read_obj_through_cache(obj_, cache_);
    ASSERT_TRUE(fs::exists(entry()));
    expect_same_mesh(first, parsed);
    // The stored mesh, not a parse: a parse of a file that is no longer there would fail.
    const std::string text = testing::read_bytes(obj_);
    const std::optional<ObjMesh> stored = cache_.load(MeshCache::key(obj_, text));
    ASSERT_TRUE(stored.has_value());
    expect_same_mesh(*stored, parsed);
    expect_same_mesh(read_obj_through_cache(obj_, cache_), parsed);
    ASSERT_TRUE(parsed.diffuse.has_value());
    EXPECT_NEAR(parsed.diffuse->y, 0.7, 1e-12);
}

TEST_F(MeshCacheTest, AnEditedObjOrMaterialIsAMiss) {
    read_obj_through_cache(obj_, cache_);
    folder_.write("grid.mtl", "newmtl green\nKd 0.9 0.1 0.1\n");
    const std::optional<Vec3> red = read_obj_through_cache(obj_, cache_).diffuse;
    ASSERT_TRUE(red.has_value());
    EXPECT_NEAR(red->x, 0.9, 1e-12);
    fs::remove(folder_.file("grid.mtl"));
    EXPECT_THROW(read_obj_through_cache(obj_, cache_), ObjError) << "a missing .mtl is the reader's error";
    folder_.write("grid.mtl", "newmtl green\nKd 0.1 0.7 0.2\n");
    folder_.write("grid.obj", testing::grid_obj_text(161));
    EXPECT_EQ(read_obj_through_cache(obj_, cache_).triangles.size(), 2u * 161 * 161);
}

// A .mtl named a second way (a link to one named before, read once) is checked under that name
// too: once the name points at another file, or at none, the entry is a miss and the reader's
// verdict stands.
TEST_F(MeshCacheTest, AMaterialNamedASecondWayIsCheckedUnderThatName) {
    const std::string obj = folder_.write("aliased.obj", "mtllib alias.mtl\n" + testing::read_bytes(obj_));
    fs::create_symlink("grid.mtl", folder_.file("alias.mtl"));
    ASSERT_EQ(read_obj_through_cache(obj, cache_).material_files.size(), 2u);
    ASSERT_TRUE(cache_.load(MeshCache::key(obj, testing::read_bytes(obj))).has_value());
    fs::remove(folder_.file("alias.mtl"));
    folder_.write("alias.mtl", "newmtl green\nKd nan 0 0\n");
    EXPECT_THROW(read_obj_through_cache(obj, cache_), ObjError) << "the entry stood for the link's target";
    fs::remove(folder_.file("alias.mtl"));
    EXPECT_THROW(read_obj_through_cache(obj, cache_), ObjError) << "the entry stood for a missing .mtl";
}

// Within one scene's load a .mtl is read once for all its OBJ files (scene/mtl_library.h): a
// stored mesh is checked against the library's read of its .mtl, not a read of its own, so
// that a thousand OBJ files naming one large library do not each hash it.
TEST_F(MeshCacheTest, AStoredMeshIsCheckedAgainstTheScenesReadOfItsMtl) {
    read_obj_through_cache(obj_, cache_);
    const MeshCache::Key key = MeshCache::key(obj_, testing::read_bytes(obj_));
    MtlLibrary library;
    ASSERT_TRUE(library.read(folder_.file("grid.mtl"))->read);
    folder_.write("grid.mtl", "newmtl green\nKd 0.9 0.1 0.1\n");  // after the scene's read of it
    EXPECT_TRUE(cache_.load(key, &library).has_value()) << "the library's read, as the scene's other meshes see it";
    EXPECT_FALSE(cache_.load(key).has_value()) << "a read of its own sees the edit";
}

TEST_F(MeshCacheTest, ADamagedEntryIsNotUsedAndIsReplaced) {
    read_obj_through_cache(obj_, cache_);
    std::string bytes = testing::read_bytes(entry());
    bytes[bytes.size() / 2] ^= 0x10;
    std::ofstream(entry(), std::ios::binary | std::ios::trunc) << bytes;
    expect_same_mesh(read_obj_through_cache(obj_, cache_), read_obj(obj_));
    EXPECT_NE(testing::read_bytes(entry()), bytes) << "stored again, whole";
}

// An entry with correct checksums whose mesh the reader would never make (an index beyond the
// positions, a coordinate beyond the range) is refused and removed.
TEST_F(MeshCacheTest, AStoredMeshTheReaderWouldRefuseIsNotUsed) {
    const MeshCache::Key key = MeshCache::key(obj_, testing::read_bytes(obj_));
    ObjMesh bad = read_obj(obj_);
    bad.triangles[7][1] = static_cast<std::uint32_t>(bad.positions.size());
    cache_.store(key, bad);
    ASSERT_TRUE(fs::exists(cache_.path(key)));
    EXPECT_FALSE(cache_.load(key).has_value());
    EXPECT_FALSE(fs::exists(cache_.path(key)));
    bad = read_obj(obj_);
    bad.positions[3].y = 2e15;
    cache_.store(key, bad);
    EXPECT_FALSE(cache_.load(key).has_value());
    expect_same_mesh(read_obj_through_cache(obj_, cache_), read_obj(obj_));
}

TEST_F(MeshCacheTest, FailuresAndSmallFilesAreNotStored) {
    const std::string small = folder_.write("small.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    read_obj_through_cache(small, cache_);
    const std::string bad = folder_.write("bad.obj", testing::grid_obj_text(160) + "f 1 2 99999999\n");
    EXPECT_THROW(read_obj_through_cache(bad, cache_), ObjError);
    EXPECT_THROW(read_obj_through_cache(bad, cache_), ObjError) << "reported every time";
    EXPECT_FALSE(fs::exists(folder_.file("cache/meshes")) && !fs::is_empty(folder_.file("cache/meshes")));
}

// An entry keeps no warnings: a mesh that has some is parsed, and warns, on every read.
TEST_F(MeshCacheTest, AMeshWithWarningsIsNotStored) {
    const std::string obj = folder_.write("warned.obj", "usemtl nowhere\n" + testing::grid_obj_text(160));
    for (int read = 0; read < 2; ++read) {
        const ObjMesh mesh = read_obj_through_cache(obj, cache_);
        ASSERT_EQ(mesh.warnings.size(), 1u) << "read " << read;
        EXPECT_EQ(mesh.warnings[0].rfind("line 1: usemtl nowhere: ", 0), 0u) << mesh.warnings[0];
    }
    EXPECT_FALSE(fs::exists(cache_.path(MeshCache::key(obj, testing::read_bytes(obj)))));
}

// A mesh larger than the cache's largest is read, and not stored (storing copies it whole).
TEST_F(MeshCacheTest, AMeshLargerThanTheLargestStoredIsReadAndNotStored) {
    const ObjMesh parsed = read_obj(obj_);
    const std::uint64_t bytes = (parsed.positions.size() + parsed.normals.size()) * sizeof(Vec3) +
                                parsed.triangles.size() * 24;
    const MeshCache small(folder_.file("small-cache"), MeshCache::kDefaultSizeLimit, bytes - 1);
    expect_same_mesh(read_obj_through_cache(obj_, small), parsed);
    EXPECT_FALSE(fs::exists(small.path(MeshCache::key(obj_, testing::read_bytes(obj_)))));
    const MeshCache enough(folder_.file("enough-cache"), MeshCache::kDefaultSizeLimit, bytes);
    read_obj_through_cache(obj_, enough);
    EXPECT_TRUE(fs::exists(enough.path(MeshCache::key(obj_, testing::read_bytes(obj_)))));
}

}  // namespace
}  // namespace clr
