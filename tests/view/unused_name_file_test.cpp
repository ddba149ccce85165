// The viewer's writes under the first free name of a series: never over a file, a folder or a
// link, also when the name is taken between the look and the rename.
#include "view/unused_name_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "core/errors.h"
#include "support/taken_temp_names.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using testing::read_bytes;
using testing::take_the_next_usual_temp_names;
using testing::TempFolder;

const auto kAnyName = [](const std::string&) {};

TEST(UnusedNameFile, TakesTheFirstNameOfTheSeriesThatNoEntryHolds) {
    TempFolder folder;
    folder.write("tour.json", "mine");
    fs::create_directory(folder.file("tour-2.json"));
    fs::create_symlink("nowhere", folder.file("tour-3.json"));
    const UnusedNameFile written = write_under_unused_name(folder.path(), "tour", ".json", {}, "new", kAnyName);
    EXPECT_EQ(written.name, "tour-4");
    EXPECT_EQ(written.path, folder.file("tour-4.json"));
    EXPECT_EQ(read_bytes(folder.file("tour-4.json")), "new");
    EXPECT_EQ(read_bytes(folder.file("tour.json")), "mine");
    EXPECT_FALSE(fs::exists(folder.file("nowhere")));
    EXPECT_EQ(folder.entry_count(), 4) << "no temporary file is left";
}

TEST(UnusedNameFile, SkipsANameWhoseCompanionIsTaken) {
    TempFolder folder;
    folder.write("clip.mp4", "a video");
    const UnusedNameFile written = write_under_unused_name(folder.path(), "clip", ".json", {".mp4"}, "{}", kAnyName);
    EXPECT_EQ(written.name, "clip-2");
    EXPECT_FALSE(fs::exists(folder.file("clip.json")));
}

// A file made under the chosen name after it was found free is not replaced: the rename
// itself refuses, and the next name is taken.
TEST(UnusedNameFile, ANameTakenBeforeTheRenameIsNotReplaced) {
    TempFolder folder;
    const auto someone_else_writes = [&folder](const std::string& path) {
        if (path == folder.file("race.json")) folder.write("race.json", "theirs");
    };
    const UnusedNameFile written = write_under_unused_name(folder.path(), "race", ".json", {}, "ours", someone_else_writes);
    EXPECT_EQ(written.name, "race-2");
    EXPECT_EQ(read_bytes(folder.file("race.json")), "theirs");
    EXPECT_EQ(read_bytes(folder.file("race-2.json")), "ours");
    EXPECT_EQ(folder.entry_count(), 2) << "no temporary file is left";
}

// A name that no file holds but that the check passes over (an input of the run that need not
// exist: a texture a .mtl names) is skipped as a taken one; any other refusal ends the write.
TEST(UnusedNameFile, ANameTheCheckPassesOverIsSkipped) {
    TempFolder folder;
    const auto an_input = [&folder](const std::string& path) {
        if (path == folder.file("tour.json")) throw UnusableName("tour.json: a texture of the model");
    };
    const UnusedNameFile written = write_under_unused_name(folder.path(), "tour", ".json", {}, "new", an_input);
    EXPECT_EQ(written.name, "tour-2");
    EXPECT_FALSE(fs::exists(folder.file("tour.json")));
    EXPECT_EQ(read_bytes(folder.file("tour-2.json")), "new");
    const auto refused = [](const std::string&) { throw OutputError("no"); };
    EXPECT_THROW(write_under_unused_name(folder.path(), "clip", ".json", {}, "new", refused), OutputError);
    EXPECT_EQ(folder.entry_count(), 1) << "no temporary file is left";
}

TEST(UnusedNameFile, RefusesWhenEveryNameIsTakenOrTheFolderIsMissing) {
    TempFolder folder;
    for (int n = 1; n <= kMostNameTries; ++n) folder.write(series_name("full", n) + ".json", "");
    EXPECT_THROW(write_under_unused_name(folder.path(), "full", ".json", {}, "x", kAnyName), OutputError);
    EXPECT_THROW(write_under_unused_name(folder.file("missing"), "x", ".json", {}, "x", kAnyName), OutputError);
    EXPECT_EQ(folder.entry_count(), kMostNameTries);
}

// A folder that cannot be looked in (a file in its place, a link that leads round in a circle,
// one that may not be searched) is named with the reason, rather than its 1000 names reported
// taken.
TEST(UnusedNameFile, AFolderThatCannotBeLookedInIsNamedWithTheReason) {
    TempFolder folder;
    folder.write("file", "a file where the folder was");
    fs::create_symlink("circle", folder.file("circle"));
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"file", "Not a directory"}, {"circle", "Too many levels of symbolic links"}};
    for (const auto& [name, reason] : cases) {
        std::string message = "written";
        try {
            write_under_unused_name(folder.file(name), "tour", ".json", {}, "x", kAnyName);
        } catch (const OutputError& error) {
            message = error.what();
        }
        EXPECT_NE(message.find(folder.file(name) + ": cannot look for a free name in the folder: " + reason),
                  std::string::npos)
            << message;
        EXPECT_EQ(message.find("taken"), std::string::npos) << message;
    }
    EXPECT_EQ(folder.entry_count(), 2);
}

// A series whose first name just fits (a scene's long name with "_path") but whose next one
// does not is refused naming the name as too long, not the folder, which is fine.
TEST(UnusedNameFile, ANameTooLongForTheFolderIsNamedAsSuch) {
    TempFolder folder;
    const std::string base(250, 'a');  // base.json: 255 characters, the most a name may have
    EXPECT_EQ(write_under_unused_name(folder.path(), base, ".json", {}, "first", kAnyName).name, base);
    std::string message = "written";
    try {
        write_under_unused_name(folder.path(), base, ".json", {}, "second", kAnyName);
    } catch (const OutputError& error) {
        message = error.what();
    }
    EXPECT_NE(message.find(base + "-2.json: the name is longer than the folder's file system allows"), std::string::npos)
        << message;
    EXPECT_EQ(message.find("cannot look for a free name in the folder"), std::string::npos) << message;
    EXPECT_EQ(folder.entry_count(), 1) << "no temporary file is left";
}

// Another user who may write into the output folder can guess the usual temporary names and
// make them first: the export is written all the same, and their files stay as they were.
TEST(UnusedNameFile, IsWrittenWhenTheUsualTemporaryNamesAreTaken) {
    TempFolder folder;
    const int taken = take_the_next_usual_temp_names(folder, 64);
    const UnusedNameFile written = write_under_unused_name(folder.path(), "tour", ".json", {}, "ours", kAnyName);
    EXPECT_EQ(read_bytes(written.path), "ours");
    EXPECT_EQ(folder.entry_count(), taken + 1) << "no temporary file is left, and none of theirs removed";
}
}  // namespace
}  // namespace clr
