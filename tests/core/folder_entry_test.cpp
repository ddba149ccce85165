// FolderEntry removes a file through its folder held open, also after the folder was renamed.
#include "core/folder_entry.h"

#include <gtest/gtest.h>

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

TEST(FolderEntry, AnEmptyEntryRemovesNothing) {
    const FolderEntry entry;
    EXPECT_FALSE(entry.remove());
}

}  // namespace
}  // namespace clr
