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

constexpr std::size_t kHeaderBytes = 40;

using testing::ScopedEnv;

// A binary PPM of width x height whose samples depend on `seed`: 512 x 512 decodes to exactly
// 1 MiB of RGBA, the smallest size the cache stores. PPM keeps the test free of an encoder.
std::string write_ppm(const TempFolder& folder, const std::string& name, int width, int height, int seed = 0) {
    std::string bytes = "P6\n" + std::to_string(width) + " " + std::to_string(height) + "\n255\n";
    for (int i = 0; i < width * height * 3; ++i) bytes += static_cast<char>((i * 7 + seed) % 251);
    return folder.write(name, bytes);
}

std::string entry_path(const ImageCache& cache, const std::string& image_path) {
    const std::string bytes = read_bytes(image_path);
    return cache.path(ImageCache::key(std::vector<unsigned char>(bytes.begin(), bytes.end())));
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
    const ImageCache cache(folder.file("cache/images"));  // created on the first store
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

    // Proof that the pixels come from the entry: change one in the entry, and the load shows it.
    std::string doctored = read_bytes(entry);
    doctored[kHeaderBytes] = static_cast<char>(doctored[kHeaderBytes] + 1);
    folder.write("cache/images/" + fs::path(entry).filename().string(), doctored);
    EXPECT_EQ(load_image_through_cache(image_path, cache)->rgba[0], static_cast<std::uint8_t>(decoded->rgba[0] + 1));
}

TEST(ImageCache, ChangingTheFileChangesTheKey) {
    TempFolder folder;
    const ImageCache cache(folder.file("images"));
    const std::string image_path = write_ppm(folder, "big.ppm", 512, 512, 1);
    load_image_through_cache(image_path, cache);
    const std::string old_entry = entry_path(cache, image_path);

    write_ppm(folder, "big.ppm", 512, 512, 2);  // same size, other content
    EXPECT_NE(entry_path(cache, image_path), old_entry);
    const auto reloaded = load_image_through_cache(image_path, cache);
    expect_same_image(*reloaded, *load_image(image_path));
    EXPECT_EQ(entries_in(cache.folder()), 2);
}

TEST(ImageCache, ABadEntryIsAMissAndTheImageIsStillRight) {
    TempFolder folder;
    const ImageCache cache(folder.file("images"));
    const std::string image_path = write_ppm(folder, "big.ppm", 512, 512);
    const auto decoded = load_image(image_path);
    load_image_through_cache(image_path, cache);
    const std::string entry = entry_path(cache, image_path);
    const std::string whole = read_bytes(entry);

    std::string wrong_magic = whole, wrong_version = whole, wrong_key = whole, wrong_width = whole;
    wrong_magic[0] = 'X';
    wrong_version[8] = 99;
    wrong_key[24] ^= 1;   // the content hash
    wrong_width[12] = 1;  // width 513: the file is then shorter than the header says
    for (const std::string& bad : {whole.substr(0, 0), whole.substr(0, 20), whole.substr(0, whole.size() - 1),
                                   wrong_magic, wrong_version, wrong_key, wrong_width, whole + "x"}) {
        std::ofstream(entry, std::ios::binary | std::ios::trunc) << bad;
        const auto image = load_image_through_cache(image_path, cache);
        expect_same_image(*image, *decoded);
        EXPECT_EQ(read_bytes(entry), whole) << "a miss decodes and stores the entry again";
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
    const ImageCache cache(folder.file("images"));
    const std::string image_path = write_ppm(folder, "small.ppm", 511, 512);  // just under 1 MiB decoded
    expect_same_image(*load_image_through_cache(image_path, cache), *load_image(image_path));
    EXPECT_EQ(entries_in(cache.folder()), 0);
}

TEST(ImageCache, AnUnreadableImageIsStillAnErrorAndLeavesNoEntry) {
    TempFolder folder;
    const ImageCache cache(folder.file("images"));
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
    const ImageCache cache(folder.file("images"), 2 * entry_bytes + entry_bytes / 2);  // room for two entries
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

TEST(ImageCache, SceneLoadingStoresAndReusesBillboardImages) {
    TempFolder folder;
    ScopedEnv dir("CLRENDER_CACHE_DIR", folder.file("cache").c_str());
    const std::string image_path = write_ppm(folder, "big.ppm", 512, 512);
    const std::string scene_path = folder.write("scene.json", R"({
        "eye": [0, 0, 5], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60, "width": 8, "height": 8,
        "billboards": [{"UpperLeft": [-1, 1, 0], "LowerLeft": [-1, -1, 0], "UpperRight": [1, 1, 0],
                        "filename": "big.ppm"}]})");
    const ImageCache cache(folder.file("cache/images"));
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
