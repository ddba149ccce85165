// FolderEntry removes a file through its folder held open, also after the folder was renamed.
#include "core/folder_entry.h"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <unistd.h>

#include <filesystem>

#include "support/temp_folder.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using testing::TempFolder;

TEST(FolderEntry, RemovesTheFileAfterItsFolderWasRenamed) {
    TempFolder folder;
    fs::create_directory(folder.file("out"));
    folder.write("out/.clrender-x.tmp", "partial");
    const FolderEntry entry(folder.file("out/.clrender-x.tmp"));
    fs::rename(folder.file("out"), folder.file("moved"));
    fs::create_directory(folder.file("out"));
    folder.write("out/.clrender-x.tmp", "someone else's file under the old path");
    EXPECT_TRUE(entry.remove());
    EXPECT_FALSE(fs::exists(folder.file("moved/.clrender-x.tmp")));
    EXPECT_TRUE(fs::exists(folder.file("out/.clrender-x.tmp"))) << "the file now under the old path is not ours";
    EXPECT_FALSE(entry.remove()) << "already gone";
}

// The file is made in the folder held open, wherever that folder is by then: a temporary
// file made after its folder was renamed is still the one remove() finds and removes.
TEST(FolderEntry, MakesTheFileInTheFolderItHolds) {
    TempFolder folder;
    fs::create_directory(folder.file("out"));
    const FolderEntry entry(folder.file("out/.clrender-y.tmp"));
    fs::rename(folder.file("out"), folder.file("moved"));
    const int fd = entry.open(O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
    ASSERT_GE(fd, 0);
    ::close(fd);
    EXPECT_TRUE(fs::exists(folder.file("moved/.clrender-y.tmp")));
    EXPECT_FALSE(fs::exists(folder.file("out"))) << "the old path is not made again";
    EXPECT_TRUE(entry.remove());
    EXPECT_FALSE(fs::exists(folder.file("moved/.clrender-y.tmp")));
}

TEST(FolderEntry, AnEmptyEntryRemovesNothing) {
    const FolderEntry entry;
    EXPECT_FALSE(entry.remove());
}

}  // namespace
}  // namespace clr
