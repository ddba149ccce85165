// AtomicFile: the final name shows either the old file or the complete new one, never a
// partial write, and an abandoned writer leaves no trace.
#include "output/atomic_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/errors.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

namespace fs = std::filesystem;

using testing::read_bytes;
using testing::TempFolder;

void write(AtomicFile& file, const std::string& text) { file.write(text.data(), text.size()); }

TEST(AtomicFile, NothingUnderTheFinalNameBeforeCommit) {
    TempFolder folder;
    const std::string final_path = folder.file("out.png");
    AtomicFile file(final_path);
    write(file, "complete contents");
    std::fflush(file.stream());
    EXPECT_FALSE(fs::exists(final_path));
    EXPECT_TRUE(fs::exists(file.temp_path()));
    // Same folder, so that the rename is atomic; a hidden name, unlike the final one.
    EXPECT_EQ(fs::path(file.temp_path()).parent_path(), fs::path(folder.path()));
    EXPECT_EQ(fs::path(file.temp_path()).filename().string().rfind(".out.png.tmp-", 0), 0u) << file.temp_path();

    file.commit();
    EXPECT_EQ(read_bytes(final_path), "complete contents");
    EXPECT_FALSE(fs::exists(file.temp_path()));
    EXPECT_EQ(folder.entry_count(), 1);
}

TEST(AtomicFile, AbandonedWriterLeavesNothing) {
    TempFolder folder;
    {
        AtomicFile file(folder.file("out.png"));
        write(file, "half of an image");
    }
    EXPECT_EQ(folder.entry_count(), 0);
}

TEST(AtomicFile, WriterAbandonedByAnExceptionLeavesNothing) {
    TempFolder folder;
    try {
        AtomicFile file(folder.file("out.png"));
        write(file, "half of an image");
        throw std::runtime_error("render failed");
    } catch (const std::runtime_error&) {
    }
    EXPECT_EQ(folder.entry_count(), 0);
}

TEST(AtomicFile, CommitReplacesAnExistingFileWhole) {
    TempFolder folder;
    const std::string final_path = folder.file("out.ppm");
    std::ofstream(final_path) << "old";
    AtomicFile file(final_path);
    write(file, "new and longer");
    std::fflush(file.stream());
    EXPECT_EQ(read_bytes(final_path), "old");  // untouched until commit
    file.commit();
    EXPECT_EQ(read_bytes(final_path), "new and longer");
    EXPECT_EQ(folder.entry_count(), 1);
}

TEST(AtomicFile, WritersOfTheSameFileUseDistinctTemporaryFiles) {
    TempFolder folder;
    AtomicFile first(folder.file("out.png"));
    AtomicFile second(folder.file("out.png"));
    EXPECT_NE(first.temp_path(), second.temp_path());
    write(first, "first");
    write(second, "second");
    first.commit();
    second.commit();
    EXPECT_EQ(read_bytes(folder.file("out.png")), "second");
    EXPECT_EQ(folder.entry_count(), 1);
}

TEST(AtomicFile, MissingFolderIsAnOutputErrorNamingPathAndCause) {
    TempFolder folder;
    const std::string final_path = folder.file("missing/out.png");
    try {
        AtomicFile file(final_path);
        ADD_FAILURE() << "no OutputError";
    } catch (const OutputError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find(final_path), std::string::npos) << message;
        EXPECT_NE(message.find("No such file or directory"), std::string::npos) << message;
    }
    EXPECT_EQ(folder.entry_count(), 0);
}

TEST(AtomicFile, ReadOnlyFolderIsAnOutputError) {
    if (::geteuid() == 0) GTEST_SKIP() << "root may write into read-only folders";
    TempFolder folder;
    fs::permissions(folder.path(), fs::perms::owner_read | fs::perms::owner_exec, fs::perm_options::replace);
    EXPECT_THROW(AtomicFile file(folder.file("out.png")), OutputError);
}

TEST(AtomicFile, FailedRenameIsAnOutputErrorThatLeavesNoTemporaryFile) {
    TempFolder folder;
    fs::create_directory(folder.file("out.png"));  // a folder where the file should go
    {
        AtomicFile file(folder.file("out.png"));
        write(file, "data");
        EXPECT_THROW(file.commit(), OutputError);
    }
    EXPECT_TRUE(fs::is_directory(folder.file("out.png")));
    EXPECT_EQ(folder.entry_count(), 1);
}

TEST(AtomicFile, WriteAfterCommitIsAnError) {
    TempFolder folder;
    AtomicFile file(folder.file("out.png"));
    file.commit();
    EXPECT_THROW(write(file, "late"), OutputError);
    EXPECT_THROW(file.commit(), OutputError);
    EXPECT_EQ(read_bytes(folder.file("out.png")), "");
}

}  // namespace
}  // namespace clr
