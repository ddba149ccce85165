// The image cache: a large image decoded once is read back from the cache, byte for byte, only
// while its file is unchanged; a bad entry is a miss; failures and small images are never stored;
// and the folder stays under its size limit by dropping the least recently used entries.
#include "scene/image_cache.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "scene/image_loader.h"
#include "scene/scene_loader.h"
#include "support/scoped_env.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using testing::read_bytes;
using testing::TempFolder;

constexpr std::size_t kHeaderBytes = 128;  // core/cache_entry.h

using testing::ScopedEnv;

// A binary PPM of width x height whose samples depend on `seed`: 512 x 512 decodes to exactly
// 1 MiB of RGBA, the smallest size the cache stores. PPM keeps the test free of an encoder.
std::string write_ppm(const TempFolder& folder, const std::string& name, int width, int height, int seed = 0) {
    std::string bytes = "P6\n" + std::to_string(width) + " " + std::to_string(height) + "\n255\n";
    for (int i = 0; i < width * height * 3; ++i) bytes += static_cast<char>((i * 7 + seed) % 251);
    return folder.write(name, bytes);
}

std::vector<unsigned char> testing_bytes(const std::string& path) {
    const std::string bytes = read_bytes(path);
    return std::vector<unsigned char>(bytes.begin(), bytes.end());
}

std::string entry_path(const ImageCache& cache, const std::string& image_path) {
    return cache.path(ImageCache::key(testing_bytes(image_path)));
}

int entries_in(const std::string& folder) {
    std::error_code error;
    if (!fs::is_directory(folder, error)) return 0;
    return static_cast<int>(std::distance(fs::directory_iterator(folder), fs::directory_iterator()));
}

void set_age(const std::string& path, std::chrono::seconds age) {
    fs::last_write_time(path, fs::file_time_type::clock::now() - age);
}

void expect_same_image(const Image& actual, const Image& expected) {
    EXPECT_EQ(actual.width, expected.width);
    EXPECT_EQ(actual.height, expected.height);
    EXPECT_TRUE(actual.rgba == expected.rgba) << "pixels differ";
    EXPECT_EQ(actual.path, expected.path);
}

TEST(ImageCache, FolderIsImagesUnderTheCacheFolder) {
    {
        ScopedEnv dir("CLRENDER_CACHE_DIR", "/some/where");
        EXPECT_EQ(ImageCache::from_environment().folder(), "/some/where/images");
    }
    for (const char* off : {"off", ""}) {
        ScopedEnv dir("CLRENDER_CACHE_DIR", off);
        EXPECT_FALSE(ImageCache::from_environment().enabled()) << "'" << off << "'";
    }
    ScopedEnv dir("CLRENDER_CACHE_DIR", nullptr);
    ScopedEnv xdg("XDG_CACHE_HOME", "/xdg");
    EXPECT_EQ(ImageCache::from_environment().folder(), "/xdg/clrender/images");
}

TEST(ImageCache, ASecondLoadComesFromTheCacheByteForByte) {
    TempFolder folder;
    const ImageCache cache(folder.file("cache"));  // created on the first store
    const std::string image_path = write_ppm(folder, "big.ppm", 512, 512);
    const auto decoded = load_image(image_path);

    const auto first = load_image_through_cache(image_path, cache);
    expect_same_image(*first, *decoded);
    const std::string entry = entry_path(cache, image_path);
    ASSERT_TRUE(fs::is_regular_file(entry));
    EXPECT_EQ(fs::file_size(entry), kHeaderBytes + decoded->rgba.size());
    EXPECT_EQ(entries_in(cache.folder()), 1) << "no temporary file left behind";

    set_age(entry, std::chrono::hours(1));
    const auto before = fs::last_write_time(entry);
    const auto second = load_image_through_cache(image_path, cache);
    expect_same_image(*second, *decoded);
    EXPECT_GT(fs::last_write_time(entry), before) << "a hit refreshes the entry";

    // Proof that the pixels come from the entry: a whole, valid entry of other pixels stored
    // under this key is what the load shows.
    Image other = *decoded;
    other.rgba[0] = static_cast<std::uint8_t>(other.rgba[0] + 1);
    cache.store(ImageCache::key(testing_bytes(image_path)), other);
    EXPECT_EQ(load_image_through_cache(image_path, cache)->rgba[0], other.rgba[0]);
}

TEST(ImageCache, EntriesArePrivateAndNamedByTheirSha256) {
    TempFolder folder;
    const ImageCache cache(folder.file("cache"));
    const std::string image_path = write_ppm(folder, "big.ppm", 512, 512);
    load_image_through_cache(image_path, cache);
    const std::string name = fs::path(entry_path(cache, image_path)).filename().string();
    EXPECT_EQ(name.size(), 64u + 5u) << name;  // <64 hex>.rgba
    EXPECT_EQ(name.substr(64), ".rgba");
    for (const std::string& created : {folder.file("cache"), cache.folder()})
        EXPECT_EQ(fs::status(created).permissions() & fs::perms::all, fs::perms::owner_all) << created;
}

TEST(ImageCache, ChangingTheFileChangesTheKey) {
    TempFolder folder;
    const ImageCache cache(folder.file("cache"));
    const std::string image_path = write_ppm(folder, "big.ppm", 512, 512, 1);
    load_image_through_cache(image_path, cache);
    const std::string old_entry = entry_path(cache, image_path);

    write_ppm(folder, "big.ppm", 512, 512, 2);  // same size, other content
    EXPECT_NE(entry_path(cache, image_path), old_entry);
    const auto reloaded = load_image_through_cache(image_path, cache);
    expect_same_image(*reloaded, *load_image(image_path));
    EXPECT_EQ(entries_in(cache.folder()), 2);
}

TEST(ImageCache, AnImageEditedByOneByteIsANewKey) {
    TempFolder folder;
    const ImageCache cache(folder.file("cache"));
    const std::string image_path = write_ppm(folder, "big.ppm", 512, 512);
    load_image_through_cache(image_path, cache);
    const std::string old_entry = entry_path(cache, image_path);

    std::string edited = read_bytes(image_path);
    edited[edited.size() / 2] ^= 1;  // one bit of one pixel
    folder.write("big.ppm", edited);
    EXPECT_NE(entry_path(cache, image_path), old_entry);
    expect_same_image(*load_image_through_cache(image_path, cache), *load_image(image_path));
}

TEST(ImageCache, AnEntryRenamedToAnotherKeysNameIsAMiss) {
    TempFolder folder;
    const ImageCache cache(folder.file("cache"));
    const std::string a = write_ppm(folder, "a.ppm", 512, 512, 1);
    const std::string b = write_ppm(folder, "b.ppm", 512, 512, 2);
    load_image_through_cache(a, cache);
    load_image_through_cache(b, cache);
    const std::string a_entry = read_bytes(entry_path(cache, a));
    fs::copy_file(entry_path(cache, b), entry_path(cache, a), fs::copy_options::overwrite_existing);

    expect_same_image(*load_image_through_cache(a, cache), *load_image(a));
    EXPECT_EQ(read_bytes(entry_path(cache, a)), a_entry) << "the wrong entry is replaced";
}

TEST(ImageCache, ABadEntryIsAMissAndTheImageIsStillRight) {
    TempFolder folder;
    const ImageCache cache(folder.file("cache"));
    const std::string image_path = write_ppm(folder, "big.ppm", 512, 512);
    const auto decoded = load_image(image_path);
    load_image_through_cache(image_path, cache);
    const std::string entry = entry_path(cache, image_path);
    const std::string whole = read_bytes(entry);

    // Header (core/cache_entry.h): magic 0-7, layout 8-11, version 12-15, width 16-19, height
    // 20-23, payload size 24-31, key 32-63, payload SHA-256 64-95, header SHA-256 96-127.
    auto damaged = [&](std::size_t at) {
        std::string bad = whole;
        bad[at] ^= 1;
        return bad;
    };
    const std::vector<std::string> bad_entries = {
        whole.substr(0, 0), whole.substr(0, 20), whole.substr(0, kHeaderBytes), whole.substr(0, whole.size() - 1),
        whole + "x",
        damaged(0),                  // magic
        damaged(12),                 // version
        damaged(16),                 // width
        damaged(24),                 // payload size
        damaged(40),                 // key
        damaged(70),                 // payload checksum
        damaged(100),                // header checksum
        damaged(kHeaderBytes),       // the first pixel
        damaged(whole.size() - 1)};  // the last pixel
    for (const std::string& bad : bad_entries) {
        std::ofstream(entry, std::ios::binary | std::ios::trunc) << bad;
        const auto image = load_image_through_cache(image_path, cache);
        expect_same_image(*image, *decoded);
        EXPECT_EQ(read_bytes(entry), whole) << "a miss decodes and stores the entry again (" << bad.size() << " bytes)";
    }
}

TEST(ImageCache, OffStoresNothing) {
    TempFolder folder;
    ScopedEnv dir("CLRENDER_CACHE_DIR", "off");
    ScopedEnv xdg("XDG_CACHE_HOME", folder.file("xdg").c_str());
    ScopedEnv home("HOME", folder.file("home").c_str());
    const ImageCache cache = ImageCache::from_environment();
    const std::string image_path = write_ppm(folder, "big.ppm", 512, 512);
    expect_same_image(*load_image_through_cache(image_path, cache), *load_image(image_path));
    EXPECT_EQ(folder.entry_count(), 1) << "only the image itself";
}

TEST(ImageCache, ASmallImageIsNotStored) {
    TempFolder folder;
    const ImageCache cache(folder.file("cache"));
    const std::string image_path = write_ppm(folder, "small.ppm", 511, 512);  // just under 1 MiB decoded
    expect_same_image(*load_image_through_cache(image_path, cache), *load_image(image_path));
    EXPECT_EQ(entries_in(cache.folder()), 0);
}

TEST(ImageCache, AnUnreadableImageIsStillAnErrorAndLeavesNoEntry) {
    TempFolder folder;
    const ImageCache cache(folder.file("cache"));
    // A header for 1024 x 1024 pixels (4 MiB decoded) over a cut-short raster.
    const std::string truncated = write_ppm(folder, "big.ppm", 1024, 1024);
    fs::resize_file(truncated, fs::file_size(truncated) / 2);
    for (const std::string& path : {truncated, folder.file("missing.png")}) {
        std::string expected;
        try {
            load_image(path);
        } catch (const ImageError& error) {
            expected = error.what();
        }
        ASSERT_FALSE(expected.empty());
        for (int attempt = 0; attempt < 2; ++attempt) {
            try {
                load_image_through_cache(path, cache);
                ADD_FAILURE() << "no ImageError for " << path;
            } catch (const ImageError& error) {
                EXPECT_EQ(std::string(error.what()), expected);
            }
        }
    }
    EXPECT_EQ(entries_in(cache.folder()), 0);
}

TEST(ImageCache, TheSizeLimitEvictsTheLeastRecentlyUsed) {
    TempFolder folder;
    const std::uintmax_t entry_bytes = kHeaderBytes + 512 * 512 * 4;
    const ImageCache cache(folder.file("cache"), 2 * entry_bytes + entry_bytes / 2);  // room for two entries
    const std::string a = write_ppm(folder, "a.ppm", 512, 512, 1);
    const std::string b = write_ppm(folder, "b.ppm", 512, 512, 2);
    const std::string c = write_ppm(folder, "c.ppm", 512, 512, 3);
    load_image_through_cache(a, cache);
    load_image_through_cache(b, cache);
    set_age(entry_path(cache, a), std::chrono::seconds(300));
    set_age(entry_path(cache, b), std::chrono::seconds(200));
    load_image_through_cache(a, cache);  // a hit: now a is the most recently used
    load_image_through_cache(c, cache);  // a third entry: the oldest, b, goes

    EXPECT_TRUE(fs::exists(entry_path(cache, a)));
    EXPECT_FALSE(fs::exists(entry_path(cache, b)));
    EXPECT_TRUE(fs::exists(entry_path(cache, c)));
    EXPECT_EQ(entries_in(cache.folder()), 2);
}

TEST(ImageCache, EvictionRemovesOnlyClrendersOwnFiles) {
    TempFolder folder;
    const std::uintmax_t entry_bytes = kHeaderBytes + 512 * 512 * 4;
    const ImageCache cache(folder.file("cache"), entry_bytes + entry_bytes / 2);  // room for one entry
    const std::string a = write_ppm(folder, "a.ppm", 512, 512, 1);
    const std::string b = write_ppm(folder, "b.ppm", 512, 512, 2);
    load_image_through_cache(a, cache);
    const std::string a_entry = entry_path(cache, a);
    const std::string a_name = fs::path(a_entry).filename().string();
    set_age(a_entry, std::chrono::hours(2));

    // Old, large things in images/ that clrender did not write, some named like its entries.
    const std::string big(2 * entry_bytes, 'x');
    const std::string images = "cache/images/";
    const std::vector<std::string> foreign = {
        folder.write(images + "notes.txt", big),
        folder.write(images + std::string(64, '0') + ".rgba", big),     // our name, not our magic
        folder.write(images + a_name + ".tmp-1-1", big),                // our temporary name, not our magic
        folder.write(images + std::string(64, '3') + ".rgba.old", big),  // not quite our name
    };
    const std::string outside = folder.write("outside.rgba", read_bytes(a_entry));  // ours, but elsewhere
    const std::string link = folder.file(images + std::string(64, '2') + ".rgba");
    fs::create_symlink(outside, link);
    const std::string subfolder = folder.file(images + std::string(64, '1') + ".rgba");
    fs::create_directory(subfolder);
    for (const std::string& path : foreign) set_age(path, std::chrono::hours(3));
    // Temporary files of ours: one left by a run that died long ago, one being written now.
    const std::string stale = folder.write(images + a_name + ".tmp-7-0", read_bytes(a_entry).substr(0, 1000));
    set_age(stale, std::chrono::hours(1));
    const std::string fresh = folder.write(images + a_name + ".tmp-8-0", "clrim");

    load_image_through_cache(b, cache);  // stores b, then trims: a, the older of ours, goes

    EXPECT_FALSE(fs::exists(a_entry));
    EXPECT_TRUE(fs::exists(entry_path(cache, b)));
    EXPECT_FALSE(fs::exists(stale)) << "left by a crash";
    EXPECT_TRUE(fs::exists(fresh)) << "another run may be writing it";
    for (const std::string& path : foreign) EXPECT_EQ(read_bytes(path), big) << path;
    EXPECT_TRUE(fs::is_symlink(link));
    EXPECT_TRUE(fs::is_regular_file(outside));
    EXPECT_TRUE(fs::is_directory(subfolder));
}

TEST(ImageCache, AnUnsafeOrUnusableCacheFolderMeansNoCaching) {
    TempFolder folder;
    const std::string image_path = write_ppm(folder, "big.ppm", 512, 512);
    const auto decoded = load_image(image_path);
    const std::string file = folder.write("file", "x");  // the cache folder is a file
    const std::string shared = folder.file("shared");    // writable by everyone
    fs::create_directory(shared);
    fs::permissions(shared, fs::perms::all);
    const std::string linked = folder.file("linked");  // images/ is a symlink to another folder
    const std::string elsewhere = folder.file("elsewhere");
    fs::create_directories(elsewhere);
    fs::create_directories(linked);
    fs::permissions(linked, fs::perms::owner_all);
    fs::create_directory_symlink(elsewhere, linked + "/images");

    for (const std::string& root : {file, shared, linked, file + "/below"}) {
        const ImageCache cache(root);
        expect_same_image(*load_image_through_cache(image_path, cache), *load_image(image_path));
        expect_same_image(*load_image_through_cache(image_path, cache), *load_image(image_path));
    }
    EXPECT_EQ(read_bytes(file), "x");
    EXPECT_EQ(entries_in(shared), 0);
    EXPECT_EQ(entries_in(elsewhere), 0);
}

TEST(ImageCache, SceneLoadingStoresAndReusesBillboardImages) {
    TempFolder folder;
    ScopedEnv dir("CLRENDER_CACHE_DIR", folder.file("cache").c_str());
    const std::string image_path = write_ppm(folder, "big.ppm", 512, 512);
    const std::string scene_path = folder.write("scene.json", R"({
        "eye": [0, 0, 5], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60, "width": 8, "height": 8,
        "billboards": [{"UpperLeft": [-1, 1, 0], "LowerLeft": [-1, -1, 0], "UpperRight": [1, 1, 0],
                        "filename": "big.ppm"}]})");
    const ImageCache cache(folder.file("cache"));
    const Scene first = load_scene(scene_path);
    ASSERT_TRUE(fs::is_regular_file(entry_path(cache, image_path)));
    set_age(entry_path(cache, image_path), std::chrono::hours(1));
    const auto before = fs::last_write_time(entry_path(cache, image_path));
    const Scene second = load_scene(scene_path);
    EXPECT_GT(fs::last_write_time(entry_path(cache, image_path)), before) << "the second load hit the entry";
    ASSERT_EQ(second.billboards.size(), 1u);
    expect_same_image(*second.billboards[0].image, *first.billboards[0].image);
}

}  // namespace
}  // namespace clr
