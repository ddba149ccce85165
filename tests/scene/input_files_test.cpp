// Scene and image files that are not what they claim: FIFOs, devices, huge or sparse files,
// text in UTF-16, and file names holding a NUL. Each must be refused at once, with little
// memory, and with a message that says what the file is.
#include <gtest/gtest.h>

#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "core/errors.h"
#include "scene/bounded_file.h"
#include "scene/image_loader.h"
#include "scene/scene_loader.h"
#include "support/address_space_child.h"
#include "support/scene_json.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using testing::TempFolder;
using namespace testing::scene_json;

// Runs `check` in a child whose address space may grow by at most 4 GiB and which may take 10
// seconds, so that a reader that waits forever or reads gigabytes fails the test instead of
// hanging it or exhausting the machine. True when `check` returned true. Under
// AddressSanitizer only the time is bounded (support/address_space_child.h); the plain build
// checks the memory bound.
bool passes_within_bounds(const std::function<bool()>& check) {
#ifdef __SANITIZE_ADDRESS__
    const testing::ChildBounds bounds{std::nullopt, 10};
#else
    const testing::ChildBounds bounds{std::uint64_t(4) << 30, 10};
#endif
    return testing::passes_in_bounded_child(bounds, check);
}

// Whether loading the scene at `path` fails with a SceneError whose message holds `fragment`.
bool scene_fails_with(const std::string& path, const std::string& fragment) {
    try {
        load_scene(path);
    } catch (const SceneError& error) {
        return std::string(error.what()).find(fragment) != std::string::npos;
    }
    return false;
}

TEST(InputFiles, FifoAsTheSceneIsRefusedAtOnce) {
    TempFolder folder;
    const std::string fifo = folder.file("scene.json");
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    // No writer ever opens it: a blocking open would wait forever.
    EXPECT_TRUE(passes_within_bounds(
        [&] { return scene_fails_with(fifo, "cannot read scene file: it is a FIFO (named pipe), not a regular file"); }));
}

TEST(InputFiles, DeviceAsTheSceneIsRefusedWithoutReading) {
    EXPECT_TRUE(passes_within_bounds(
        [] { return scene_fails_with("/dev/zero", "cannot read scene file: it is a character device, not a regular file"); }));
}

TEST(InputFiles, SparseHugeSceneIsRefusedFromItsSize) {
    TempFolder folder;
    const std::string sparse = folder.file("scene.json");
    fs::resize_file(folder.write("scene.json", "{"), std::uint64_t(5) << 30);  // 5 GiB, no blocks on disk
    EXPECT_TRUE(passes_within_bounds(
        [&] { return scene_fails_with(sparse, "the file is 5 GiB, more than the limit of 64 MiB"); }));
}

TEST(InputFiles, SparseHugeImageIsRefusedFromItsSize) {
    TempFolder folder;
    const std::string sparse = folder.write("huge.png", "\x89PNG");
    fs::resize_file(sparse, std::uint64_t(3) << 30);
    EXPECT_TRUE(passes_within_bounds([&] {
        try {
            load_image(sparse);
        } catch (const ImageError& error) {
            return std::string(error.what()) == "the file is 3 GiB, more than the limit of 1 GiB";
        }
        return false;
    }));
}

TEST(InputFiles, FifoAsAnImageIsRefused) {
    TempFolder folder;
    const std::string fifo = folder.file("image.png");
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_TRUE(passes_within_bounds([&] {
        try {
            load_image(fifo);
        } catch (const ImageError& error) {
            return std::string(error.what()) == "not a file";
        }
        return false;
    }));
}

// A socket cannot be opened (ENXIO: "No such device or address", which said nothing of the
// file that is there): it is named for what it is, as a FIFO or a device is.
TEST(InputFiles, ASocketIsNamedAsSuch) {
    TempFolder folder;
    const std::string path = folder.file("scene.json");
    const int listener = ::socket(AF_UNIX, SOCK_STREAM, 0);
    ASSERT_GE(listener, 0);
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    ASSERT_LT(path.size(), sizeof address.sun_path);
    path.copy(address.sun_path, path.size());
    ASSERT_EQ(::bind(listener, reinterpret_cast<const sockaddr*>(&address), sizeof address), 0);
    EXPECT_TRUE(scene_fails_with(path, "cannot read scene file: it is a socket, not a regular file"));
    try {
        read_bounded_file(path, 1 << 20);
        ADD_FAILURE() << "a socket read as a file";
    } catch (const BoundedFileError& error) {
        EXPECT_STREQ(error.what(), "it is a socket, not a regular file");
    }
    ::close(listener);
}

TEST(InputFiles, ReadsUpToTheLimitAndNoFurther) {
    TempFolder folder;
    const std::string path = folder.write("ten.txt", "0123456789");
    EXPECT_EQ(read_bounded_file(path, 10), "0123456789");
    try {
        read_bounded_file(path, 9);
        FAIL() << "a file one byte over the limit was read";
    } catch (const BoundedFileError& error) {
        EXPECT_STREQ(error.what(), "the file is 10 bytes, more than the limit of 9 bytes");
    }
}

TEST(InputFiles, FileWhoseSizeIsUnknownIsReadOnlyToTheLimit) {
    // Files under /proc claim a size of 0 but have content: the limit still holds.
    EXPECT_THROW(read_bounded_file("/proc/self/maps", 16), BoundedFileError);
    EXPECT_FALSE(read_bounded_file("/proc/self/maps", 1 << 20).empty());
}

// A file just over its limit, whose size rounds to the limit's, is named in bytes (it said
// "the file is 1 GiB, more than the limit of 1 GiB").
TEST(InputFiles, AFileJustOverItsLimitIsNamedInBytes) {
    TempFolder folder;
    const std::string path = folder.write("scene.json", "{");
    fs::resize_file(path, (std::uint64_t(1) << 20) + 1);
    try {
        read_bounded_file(path, std::uint64_t(1) << 20);
        ADD_FAILURE() << "read";
    } catch (const BoundedFileError& error) {
        EXPECT_EQ(std::string(error.what()), "the file is 1048577 bytes, more than the limit of 1 MiB (1048576 bytes)");
    }
}

TEST(InputFiles, ByteCountsForMessages) {
    EXPECT_EQ(describe_bytes(1), "1 byte");
    EXPECT_EQ(describe_bytes(1023), "1023 bytes");
    EXPECT_EQ(describe_bytes(64ull << 20), "64 MiB");
    EXPECT_EQ(describe_bytes(3ull << 29), "1.5 GiB");
}

// ---------------------------------------------------------------------------------------
// Text encodings

std::string as_utf16le(const std::string& ascii) {
    std::string wide;
    for (char c : ascii) wide += {c, '\0'};
    return wide;
}

std::string as_utf16be(const std::string& ascii) {
    std::string wide;
    for (char c : ascii) wide += {'\0', c};
    return wide;
}

std::string as_utf32le(const std::string& ascii) {
    std::string wide;
    for (char c : ascii) wide += {c, '\0', '\0', '\0'};
    return wide;
}

TEST(InputFiles, Utf16SceneIsNamedAsSuch) {
    const std::string scene = minimal_scene().dump();
    EXPECT_TRUE(TextFailsAt("\xFF\xFE" + as_utf16le(scene), "", "the file is UTF-16 (little-endian) text; save it as UTF-8"));
    EXPECT_TRUE(TextFailsAt("\xFE\xFF" + as_utf16be(scene), "", "the file is UTF-16 (big-endian) text; save it as UTF-8"));
    EXPECT_TRUE(TextFailsAt(as_utf16le("\r\n" + scene), "", "UTF-16 (little-endian)"));  // no byte order mark
    EXPECT_TRUE(TextFailsAt(as_utf16be(scene), "", "UTF-16 (big-endian)"));
}

TEST(InputFiles, Utf32SceneIsNamedAsSuch) {
    const std::string scene = minimal_scene().dump();
    EXPECT_TRUE(TextFailsAt(std::string("\xFF\xFE\0\0", 4) + as_utf32le(scene), "", "UTF-32 (little-endian)"));
    EXPECT_TRUE(TextFailsAt(as_utf32le(scene), "", "UTF-32 (little-endian) text; save it as UTF-8"));
}

TEST(InputFiles, Utf8WithByteOrderMarkIsStillRead) {
    EXPECT_EQ(parse_scene("\xEF\xBB\xBF" + minimal_scene().dump(), "test.json").width, 4);
}

// ---------------------------------------------------------------------------------------
// Repeated keys

// `depth` objects nested under "x", the innermost holding key "k" `repeats` times.
std::string nested_repeats(int depth, int repeats) {
    std::string text = minimal_scene().dump();
    text.pop_back();
    text += ", \"x\": ";
    for (int i = 0; i < depth; ++i) text += "{\"a\": ";
    text += "{";
    for (int i = 0; i < repeats; ++i) text += std::string(i ? ", " : "") + "\"k\": 1";
    text += "}" + std::string(depth, '}') + "}";
    return text;
}

TEST(InputFiles, RepeatedKeysDeepDownCostMemoryLinearInTheFile) {
    const std::string text = nested_repeats(3000, 3000);
    const Scene scene = parse_scene(text, "test.json");
    std::size_t warning_bytes = 0;
    for (const std::string& warning : scene.warnings) warning_bytes += warning.size();
    // One warning per repeat, each naming a 6000-character location, would be 18 MB.
    EXPECT_LT(warning_bytes, 20 * text.size());
    EXPECT_TRUE(has_warning(scene, "2989 more duplicate keys (the last value of each is used)")) << scene.warnings.size();
}

// The scene digest (scene/scene_digest.h) hashes the file's text: writing the parsed document
// out would recurse once per level and overflow the stack on a scene that nests deeply in a
// key clrender ignores, which is a valid scene (a warning).
TEST(InputFiles, DeepNestingInAnIgnoredKeyIsDigestedWithoutRecursion) {
    std::string text = minimal_scene().dump();
    text.pop_back();
    const int depth = 400000;
    text += ", \"x\": " + std::string(depth, '[') + std::string(depth, ']') + "}";
    const Scene scene = parse_scene(text, "test.json");
    EXPECT_EQ(scene.digest.size(), 16u);
    EXPECT_NE(scene.digest, parse_scene(minimal_scene().dump(), "test.json").digest);
}

TEST(InputFiles, FirstRepeatedKeysAreStillNamed) {
    const Scene scene = parse_scene(R"({"eye": [0, 0, 5], "eye": [0, 0, 6], "lookat": [0, 0, 0], "up": [0, 1, 0],
                                        "fov_angle": 60, "width": 4, "height": 3})",
                                    "test.json");
    EXPECT_EQ(scene.camera_path.at(0).eye, Vec3(0, 0, 6));
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_EQ(scene.warnings[0], "/eye: duplicate key (the last value is used)");
}

// ---------------------------------------------------------------------------------------
// File names

TEST(InputFiles, NulInAnImageFileNameIsRefused) {
    TempFolder folder;
    write_ppm(folder, "a.ppm", 2, 2);  // what a name cut at the NUL would open
    Json scene = minimal_scene();
    Json billboard = flat_billboard();
    billboard.erase("ambient");
    billboard["filename"] = std::string("a.ppm\0.txt", 10);
    scene["billboards"] = {billboard};
    try {
        parse_scene(scene.dump(), folder.file("scene.json"));
        FAIL() << "the file name was cut at its NUL";
    } catch (const SceneError& error) {
        EXPECT_EQ(error.location(), "/billboards/0/filename");
        EXPECT_EQ(error.detail(), "filename contains a NUL character (\\u0000), which no file name can hold");
    }
}

}  // namespace
}  // namespace clr
