// AtomicFile: the final name shows either the old file or the complete new one, never a
// partial write, and an abandoned writer leaves no trace.
#include "output/atomic_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/errors.h"
#include "support/taken_temp_names.h"
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
    // Same folder, so that the rename is atomic; a short hidden name of clrender's own form,
    // not derived from the final name (temp_files.h).
    EXPECT_EQ(fs::path(file.temp_path()).parent_path(), fs::path(folder.path()));
    EXPECT_EQ(fs::path(file.temp_path()).filename().string().rfind(".clrender-", 0), 0u) << file.temp_path();
    EXPECT_EQ(fs::path(file.temp_path()).filename().string().find("out.png"), std::string::npos) << file.temp_path();

    file.commit();
    EXPECT_EQ(read_bytes(final_path), "complete contents");
    EXPECT_FALSE(fs::exists(file.temp_path()));
    EXPECT_EQ(folder.entry_count(), 1);
}

// The usual temporary names can be guessed and made first by another user who may write into
// the folder: the output is written under an unpredictable one instead.
TEST(AtomicFile, IsWrittenWhenTheUsualTemporaryNamesAreTaken) {
    TempFolder folder;
    const int taken = testing::take_the_next_usual_temp_names(folder, 64);
    AtomicFile file(folder.file("out.png"));
    write(file, "an image");
    file.commit();
    EXPECT_EQ(read_bytes(folder.file("out.png")), "an image");
    EXPECT_EQ(folder.entry_count(), taken + 1);
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
    {
        AtomicFile file(folder.file("out.png"));
        write(file, "data");
        fs::create_directories(folder.file("out.png/inside"));  // a folder appears where the file should go
        EXPECT_THROW(file.commit(), OutputError);
    }
    EXPECT_TRUE(fs::is_directory(folder.file("out.png")));
    EXPECT_EQ(folder.entry_count(), 1);
}

TEST(AtomicFile, FolderFifoAndDeviceAreRefusedBeforeWriting) {
    TempFolder folder;
    fs::create_directory(folder.file("folder.png"));
    ASSERT_EQ(::mkfifo(folder.file("fifo.png").c_str(), 0644), 0);
    EXPECT_THROW(AtomicFile file(folder.file("folder.png")), OutputError);
    EXPECT_THROW(AtomicFile file(folder.file("fifo.png")), OutputError);
    fs::create_symlink("/dev/null", folder.file("null.png"));  // never /dev/null itself: see output_safety_test.cpp
    EXPECT_THROW(AtomicFile file(folder.file("null.png")), OutputError);
    EXPECT_TRUE(fs::is_fifo(folder.file("fifo.png")));
    EXPECT_TRUE(fs::is_symlink(folder.file("null.png")));
    EXPECT_EQ(folder.entry_count(), 3);
}

TEST(AtomicFile, SymbolicLinkIsWrittenThroughAndSurvives) {
    TempFolder folder;
    fs::create_directory(folder.file("real"));
    std::ofstream(folder.file("real/out.png")) << "old";
    fs::create_symlink("real/out.png", folder.file("link.png"));
    AtomicFile file(folder.file("link.png"));
    EXPECT_EQ(fs::path(file.temp_path()).parent_path(), fs::canonical(folder.file("real")))
        << "beside the link's target, so that the rename stays in one file system";
    write(file, "new");
    file.commit();
    EXPECT_TRUE(fs::is_symlink(folder.file("link.png")));
    EXPECT_EQ(read_bytes(folder.file("real/out.png")), "new");
    EXPECT_EQ(folder.entry_count(), 2);
}

TEST(AtomicFile, CompletedFileIsOnDiskButNotInPlaceUntilCommit) {
    TempFolder folder;
    std::ofstream(folder.file("out.png")) << "old";
    {
        AtomicFile file(folder.file("out.png"));
        write(file, "new");
        file.complete();
        EXPECT_EQ(read_bytes(file.temp_path()), "new");
        EXPECT_EQ(read_bytes(folder.file("out.png")), "old");
    }  // never committed: a later step failed
    EXPECT_EQ(read_bytes(folder.file("out.png")), "old");
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
