// The write-then-rename primitive that the caches and the outputs share: a reader sees the
// earlier file or the whole new one, and nothing is left behind when the writer gives up.
#include "core/replacement_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <string>

#include "support/temp_folder.h"

namespace clr {
namespace {

using testing::read_bytes;
using testing::TempFolder;

void write_all(const ReplacementFile& file, const std::string& bytes) {
    ASSERT_EQ(::write(file.descriptor(), bytes.data(), bytes.size()), static_cast<ssize_t>(bytes.size()));
}

TEST(ReplacementFile, RenamedFileReplacesTheEarlierOneWhole) {
    TempFolder folder;
    const std::string final_path = folder.write("out.txt", "earlier");
    {
        ReplacementFile file(folder.file("out.txt.tmp"), 0600);
        ASSERT_TRUE(file.created());
        write_all(file, "new contents");
        EXPECT_EQ(read_bytes(final_path), "earlier");  // nothing changes before the rename
        ASSERT_TRUE(file.close(/*sync=*/true));
        ASSERT_TRUE(file.rename_onto(final_path));
    }
    EXPECT_EQ(read_bytes(final_path), "new contents");
    EXPECT_EQ(folder.entry_count(), 1);
}

TEST(ReplacementFile, AbandonedFileIsRemovedAndTheEarlierOneKept) {
    TempFolder folder;
    const std::string final_path = folder.write("out.txt", "earlier");
    {
        ReplacementFile file(folder.file("out.txt.tmp"), 0600);
        ASSERT_TRUE(file.created());
        write_all(file, "half");
    }
    EXPECT_EQ(read_bytes(final_path), "earlier");
    EXPECT_EQ(folder.entry_count(), 1);
}

TEST(ReplacementFile, NeverWritesIntoAFileThatExistsUnderTheTemporaryName) {
    TempFolder folder;
    const std::string someone_elses = folder.write("busy.tmp", "theirs");
    {
        ReplacementFile file(someone_elses, 0600);
        EXPECT_FALSE(file.created());
        EXPECT_EQ(file.descriptor(), -1);
    }
    EXPECT_EQ(read_bytes(someone_elses), "theirs");  // neither written nor removed
}

TEST(ReplacementFile, FailedRenameStillRemovesTheTemporaryFile) {
    TempFolder folder;
    {
        ReplacementFile file(folder.file("x.tmp"), 0600);
        ASSERT_TRUE(file.created());
        ASSERT_TRUE(file.close(/*sync=*/false));
        EXPECT_FALSE(file.rename_onto(folder.file("no-such-folder/x")));
    }
    EXPECT_EQ(folder.entry_count(), 0);
}

TEST(ReplacementFile, AdoptedFileIsRemovedUnlessRenamed) {
    TempFolder folder;
    const std::string finished = folder.write("made-by-another-writer.tmp", "video");
    { ReplacementFile::adopt(finished); }
    EXPECT_EQ(folder.entry_count(), 0);
}

}  // namespace
}  // namespace clr
