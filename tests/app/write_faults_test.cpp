// Writes that fail in ways a user's environment causes, run through the clrender binary: a
// --stats report that cannot be written after the video is finished, a file size limit
// (`ulimit -f`, whose SIGXFSZ would kill clrender mid-write), and a standard error whose
// reader has gone (`clrender ... 2>&1 | head -1`, whose SIGPIPE would kill clrender). Each
// must end with the documented exit code and leave every earlier file as it was and no
// temporary file.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "support/command.h"
#include "support/small_disk.h"
#include "support/temp_folder.h"

extern char** environ;

namespace clr {
namespace {

namespace fs = std::filesystem;
using testing::read_bytes;
using testing::TempFolder;

const char* kAnimation = R"({
  "eyeLocations": [[-3, 1, 8], [3, 2, 7]], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 55,
  "width": 32, "height": 24, "clrender": {"frames_per_segment": 4},
  "spheres": [{"center": [0, 0, 0], "radius": 1.5, "ambient": [1, 0.3, 0.2]}]
})";
const char* kStill = R"({
  "eye": [0, 0, 6], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60, "width": 400, "height": 300,
  "spheres": [{"center": [0, 0, 0], "radius": 1, "ambient": [1, 0, 0]}]
})";
const std::string kEarlier = "an earlier output that no failed run may touch\n";

std::set<std::string> names_in(const std::string& folder) {
    std::set<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder)) names.insert(entry.path().filename().string());
    return names;
}

using testing::have_program;

// The video is finished and checked before the report is written; the report's folder is a
// full tmpfs. The video must not be renamed into place before the report is written.
TEST(WriteFaults, StatsFailingAfterTheVideoKeepsTheEarlierVideo) {
    if (!have_program("ffmpeg") || !have_program("ffprobe")) GTEST_SKIP() << "ffmpeg is not installed";
    if (!testing::can_mount_small_disks()) GTEST_SKIP() << "cannot mount a tmpfs (needs root or unprivileged user namespaces)";
    TempFolder folder;
    folder.write("anim.json", kAnimation);
    folder.write("anim.mp4", kEarlier);
    fs::create_directory(folder.file("full"));
    folder.write("run.sh", "set -e\ncd '" + folder.path() + "'\nmount -t tmpfs -o size=16k tmpfs full\n"
                           "echo earlier > full/stats.json\n(dd if=/dev/zero of=full/filler bs=4096 2>/dev/null || true)\n"
                           "set +e\n'" + CLRENDER_BINARY + "' anim.json -q --reference --video anim.mp4 --stats full/stats.json"
                           " 2> stderr.txt\necho $? > code.txt\nls -A full > full-listing.txt\n");
    ASSERT_EQ(testing::run_in_mount_namespace(folder.path(), "sh run.sh"), 0);
    const std::string errors = read_bytes(folder.file("stderr.txt"));
    EXPECT_EQ(read_bytes(folder.file("code.txt")), "4\n") << errors;
    EXPECT_NE(errors.find("full/stats.json: write failed: No space left on device"), std::string::npos) << errors;
    EXPECT_TRUE(read_bytes(folder.file("anim.mp4")) == kEarlier) << "the new video replaced the earlier one";
    EXPECT_EQ(read_bytes(folder.file("full-listing.txt")), "filler\nstats.json\n");
    EXPECT_EQ(names_in(folder.path()), (std::set<std::string>{"anim.json", "anim.mp4", "full", "run.sh", "stderr.txt",
                                                              "code.txt", "full-listing.txt"}));
}

// A 400x300 PNG needs more than 2 KiB: the write fails with EFBIG (exit 4), it does not kill
// clrender with SIGXFSZ and leave its temporary file.
TEST(WriteFaults, FileSizeLimitIsAnOutputError) {
    TempFolder folder;
    folder.write("still.json", kStill);
    folder.write("still.png", kEarlier);
    const testing::CommandResult result =
        testing::run_clrender("still.json -q --reference -o still.png", folder.path(), "ulimit -f 2;");
    EXPECT_EQ(result.exit_code, 4) << result.output;
    EXPECT_NE(result.output.find("still.png: write failed: File too large"), std::string::npos) << result.output;
    EXPECT_EQ(read_bytes(folder.file("still.png")), kEarlier);
    EXPECT_EQ(names_in(folder.path()), (std::set<std::string>{"still.json", "still.png"})) << "temporary file left";
}

// The same for OpenEXR (linear floats, about 1.4 MB here): it is encoded in memory and written
// through the same atomic file, so the earlier image survives and no temporary file stays.
TEST(WriteFaults, FileSizeLimitOnAnExrIsAnOutputError) {
    TempFolder folder;
    folder.write("still.json", kStill);
    folder.write("still.exr", kEarlier);
    const testing::CommandResult result =
        testing::run_clrender("still.json -q --reference -o still.exr", folder.path(), "ulimit -f 2;");
    EXPECT_EQ(result.exit_code, 4) << result.output;
    EXPECT_NE(result.output.find("still.exr: write failed: File too large"), std::string::npos) << result.output;
    EXPECT_EQ(read_bytes(folder.file("still.exr")), kEarlier);
    EXPECT_EQ(names_in(folder.path()), (std::set<std::string>{"still.json", "still.exr"})) << "temporary file left";
}

// Standard error is a pipe whose reader has already closed it: every message fails with
// EPIPE. The render must still finish and write its frames; losing messages is no failure.
TEST(WriteFaults, ClosedStandardErrorDoesNotStopTheRender) {
    TempFolder folder;
    folder.write("anim.json", kAnimation);
    int pipe_fds[2];
    ASSERT_EQ(::pipe(pipe_fds), 0);
    ::close(pipe_fds[0]);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], STDERR_FILENO);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    const std::string binary = CLRENDER_BINARY;
    const std::string scene = folder.file("anim.json"), pattern = folder.file("f_%04d.png");
    std::vector<const char*> argv = {binary.c_str(), scene.c_str(), "--reference", "-o", pattern.c_str(), nullptr};
    // The test runner itself may ignore or block SIGPIPE: clrender must start with the default action.
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    sigset_t defaults;
    sigemptyset(&defaults);
    sigaddset(&defaults, SIGPIPE);
    posix_spawnattr_setsigdefault(&attributes, &defaults);
    sigset_t none_blocked;
    sigemptyset(&none_blocked);
    posix_spawnattr_setsigmask(&attributes, &none_blocked);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
    pid_t pid = -1;
    ASSERT_EQ(::posix_spawn(&pid, binary.c_str(), &actions, &attributes, const_cast<char**>(argv.data()), environ), 0);
    posix_spawnattr_destroy(&attributes);
    posix_spawn_file_actions_destroy(&actions);
    ::close(pipe_fds[1]);
    int status = 0;
    ASSERT_EQ(::waitpid(pid, &status, 0), pid);
    ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
    EXPECT_EQ(WEXITSTATUS(status), 0);
    std::set<std::string> expected = {"anim.json"};
    for (int frame = 0; frame < 5; ++frame) expected.insert(testing::frame_name(frame));
    EXPECT_EQ(names_in(folder.path()), expected);
}

}  // namespace
}  // namespace clr
