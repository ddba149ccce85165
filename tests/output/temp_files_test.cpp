// Temporary file names fit wherever the final name fits, and the sweep removes exactly the
// files of dead clrender processes on this machine.
#include "output/temp_files.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "core/errors.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using testing::TempFolder;

std::string dead_pid() {
    const pid_t child = ::fork();
    if (child == 0) ::_exit(0);
    ::waitpid(child, nullptr, 0);
    return std::to_string(child);
}

TEST(TempFiles, NamesAreShortAndIndependentOfTheFinalName) {
    const std::string long_name = std::string(250, 'x') + ".png";
    const fs::path temp = temp_path_in_folder_of("/some/folder/" + long_name);
    EXPECT_EQ(temp.parent_path(), fs::path("/some/folder"));
    const std::string name = temp.filename().string();
    EXPECT_TRUE(std::regex_match(name, std::regex(R"(\.clrender-[0-9a-f]{8}-[0-9]+-[0-9]+\.tmp)"))) << name;
    EXPECT_LE(name.size() + 4, 255u) << "with the encoder log's \".log\" it still fits NAME_MAX";
    EXPECT_NE(temp_path_in_folder_of("a.png"), temp_path_in_folder_of("a.png"));
    EXPECT_EQ(fs::path(temp_path_in_folder_of("a.png")).parent_path(), fs::path(""));
}

// While names are taken, unpredictable ones of the same form are tried (so that the sweep
// still knows them), a bounded number of times; the failure then says what was taken.
TEST(TempFiles, TakenNamesAreFollowedByUnpredictableOnesAndThenRefused) {
    std::vector<std::string> tried;
    const std::string made = create_under_temp_name("/some/folder/out.png", [&tried](const std::string& temp_path) {
        tried.push_back(temp_path);
        errno = EEXIST;
        return false;
    });
    EXPECT_EQ(made, "");
    EXPECT_EQ(errno, EEXIST);
    ASSERT_EQ(tried.size(), static_cast<std::size_t>(kMostTempNameTries));
    EXPECT_EQ(std::set<std::string>(tried.begin(), tried.end()).size(), tried.size());
    const std::regex usual_form(R"(/some/folder/\.clrender-[0-9a-f]{8}-[0-9]{1,10}-[0-9]{1,10}\.tmp)");
    for (const std::string& path : tried) EXPECT_TRUE(std::regex_match(path, usual_form)) << path;
    const std::string failure = temp_creation_failure(EEXIST);
    EXPECT_EQ(failure.find("File exists"), std::string::npos) << "the final name does not exist: " << failure;
    EXPECT_NE(failure.find("temporary"), std::string::npos) << failure;

    tried.clear();
    EXPECT_EQ(create_under_temp_name("out.png", [&tried](const std::string& temp_path) {
                  tried.push_back(temp_path);
                  errno = EACCES;
                  return false;
              }),
              "");
    EXPECT_EQ(tried.size(), 1u) << "only a taken name is worth another try";
    EXPECT_EQ(temp_creation_failure(EACCES), "cannot create a file in its folder: Permission denied");
}

TEST(TempFiles, OnlyThisHostsNamesOfDeadProcessesAreStale) {
    const std::string id = temp_host_id();
    const std::string dead = dead_pid();
    const std::string live = std::to_string(::getpid());
    const std::string parent = std::to_string(::getppid());
    EXPECT_TRUE(is_stale_temp_name(".clrender-" + id + "-" + dead + "-0.tmp"));
    EXPECT_TRUE(is_stale_temp_name(".clrender-" + id + "-" + dead + "-12.tmp.log"));
    EXPECT_FALSE(is_stale_temp_name(".clrender-" + id + "-" + live + "-0.tmp"));
    EXPECT_FALSE(is_stale_temp_name(".clrender-" + id + "-" + parent + "-0.tmp"));
    EXPECT_FALSE(is_stale_temp_name(".clrender-" + std::string(id == "00000000" ? "00000001" : "00000000") + "-" +
                                    dead + "-0.tmp"));
    EXPECT_FALSE(is_stale_temp_name(".clrender-" + id + "-" + dead + "-0.tmp~"));
    EXPECT_FALSE(is_stale_temp_name("clrender-" + id + "-" + dead + "-0.tmp"));
    EXPECT_FALSE(is_stale_temp_name(".clrender-" + id + "-0-0.tmp")) << "pid 0 is a process group";
}

TEST(TempFiles, SweepRemovesStaleFilesButNotFoldersOrLinks) {
    TempFolder folder;
    const std::string stale = ".clrender-" + temp_host_id() + "-" + dead_pid() + "-3.tmp";
    folder.write(stale, "left by a killed run");
    folder.write("keep.png", "an image");
    fs::create_directory(folder.file(stale + ".log"));  // a folder of that name is not a temporary file
    fs::create_symlink("keep.png", folder.file(".clrender-" + temp_host_id() + "-" + dead_pid() + "-4.tmp"));
    EXPECT_EQ(sweep_stale_temp_files(folder.path()), 1);
    EXPECT_FALSE(fs::exists(folder.file(stale)));
    EXPECT_EQ(folder.entry_count(), 3);
    EXPECT_EQ(sweep_stale_temp_files(folder.file("missing")), 0);
}

TEST(TempFiles, PreparingAFolderLeavesNothingAndReportsAMissingOne) {
    TempFolder folder;
    prepare_output_folder(folder.file("out.png"));
    EXPECT_EQ(folder.entry_count(), 0);
    EXPECT_THROW(prepare_output_folder(folder.file("missing/out.png")), OutputError);
}

}  // namespace
}  // namespace clr
