// Encoders that misbehave, run through the clrender binary: fake encoders (shell scripts chosen
// through CLRENDER_FFMPEG) that fail, write garbage, stop reading or never exit, signals while
// clrender waits on one, and a real ffmpeg that runs out of disk space. In every case the
// earlier video under the final name stays byte for byte, no temporary or log file is left,
// no process of the encoder's group survives, and clrender ends in bounded time.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <unistd.h>

#include "support/command.h"
#include "support/process_table.h"
#include "support/small_disk.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using testing::read_bytes;
using testing::TempFolder;

// 11 frames of 128x96 (18 KiB each as the yuv420p an MP4's encoder is sent): together more than
// a pipe's 64 KiB buffer, so an encoder that reads nothing blocks clrender's writes.
const char* kAnimation = R"({
  "eyeLocations": [[-3, 1, 8], [3, 2, 7]], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 55,
  "width": 128, "height": 96, "DefaultColor": [0.1, 0.1, 0.2], "SunLocation": [10, 20, 10],
  "spheres": [{"center": [0, 0, 0], "radius": 1.5, "ambient": [1, 0.3, 0.2]}],
  "billboards": [{"UpperLeft": [-5, 4, -4], "LowerLeft": [-5, -3, -4], "UpperRight": [5, 4, -4], "ambient": [0.2, 0.6, 0.3]}]
})";

const std::string kEarlierVideo = "the earlier video, which no failed run may touch\n";

struct Outcome {
    int exit_code = -1;
    std::string errors;   // clrender's stderr
    double seconds = -1;  // from the start (or from the signal) to clrender's exit
};

int count_of(const std::string& text, const std::string& part) {
    int count = 0;
    for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + part.size())) ++count;
    return count;
}

// Processes of process group `group` that are still alive (zombies are dead: they only wait
// for their parent to collect their status).
std::set<int> living_members(int group) {
    std::set<int> members;
    for (const testing::ProcessEntry& process : testing::process_table())
        if (process.group == group && process.state != 'Z') members.insert(process.pid);
    return members;
}

class EncoderFaults : public ::testing::Test {
protected:
    void SetUp() override {
        folder.write("anim.json", kAnimation);
        folder.write("anim.mp4", kEarlierVideo);
    }

    void TearDown() override {
        // A run that failed this test may have left its encoder running: stop it here.
        if (const int group = encoder_group(); group > 0 && !living_members(group).empty()) ::kill(-group, SIGKILL);
    }

    // A fake encoder: a shell script that first records its process group (its own pid: the
    // encoder leads a group of its own) and then runs `body`.
    std::string fake_encoder(const std::string& body) const {
        const std::string path = scripts.write("fake-ffmpeg", "#!/bin/sh\necho $$ > '" + scripts.file("group") + "'\n" + body + "\n");
        ::chmod(path.c_str(), 0755);
        return path;
    }

    int encoder_group() const {
        const std::string text = read_bytes(scripts.file("group"));
        return text.empty() ? -1 : std::stoi(text);
    }

    // Runs clrender in `folder` under a 30 s watchdog. With `signal_name`, sends it that
    // signal once the file `marker` exists (and a moment more, so that clrender is waiting);
    // Outcome::seconds then counts from the signal.
    Outcome run(const std::string& environment, const std::string& arguments, const std::string& signal_name = "",
                const std::string& marker = "") const {
        std::string script = "cd '" + folder.path() + "'\nstart=$(date +%s%N)\n" + environment + " '" + CLRENDER_BINARY +
                             "' " + arguments + " 2> '" + work.file("stderr.txt") + "' &\npid=$!\n" +
                             "( sleep 30; kill -KILL $pid ) >/dev/null 2>&1 &\nwatchdog=$!\n";
        if (!signal_name.empty()) {
            script += "i=0\nwhile [ ! -e '" + marker + "' ] && [ $i -lt 2000 ]; do sleep 0.01; i=$((i+1)); done\n"
                      "sleep 0.3\nstart=$(date +%s%N)\nkill -" + signal_name + " $pid\n";
        }
        script += "wait $pid\ncode=$?\nend=$(date +%s%N)\nkill $watchdog 2>/dev/null\n"
                  "echo $code > '" + work.file("code.txt") + "'\necho $(( (end - start) / 1000000 )) > '" +
                  work.file("ms.txt") + "'\n";
        work.write("run.sh", script);
        Outcome outcome;
        if (std::system(("bash '" + work.file("run.sh") + "'").c_str()) != 0) return outcome;
        outcome.exit_code = std::stoi(read_bytes(work.file("code.txt")));
        outcome.errors = read_bytes(work.file("stderr.txt"));
        outcome.seconds = std::stod(read_bytes(work.file("ms.txt"))) / 1000;
        return outcome;
    }

    // What every failed or interrupted run must leave: one error line, the earlier video as it
    // was and nothing else new, no process of the encoder's group alive.
    void expect_clean_failure(const Outcome& outcome) const {
        EXPECT_EQ(count_of(outcome.errors, "clrender: error: "), 1) << outcome.errors;
        EXPECT_EQ(read_bytes(folder.file("anim.mp4")), kEarlierVideo) << "the earlier video was replaced";
        std::set<std::string> names;
        for (const auto& entry : fs::directory_iterator(folder.path())) names.insert(entry.path().filename().string());
        EXPECT_EQ(names, (std::set<std::string>{"anim.json", "anim.mp4"})) << "temporary or log files left behind";
        const int group = encoder_group();
        ASSERT_GT(group, 0) << "the fake encoder never ran";
        // SIGKILLed processes vanish within microseconds; allow a loaded machine 2 s.
        for (int i = 0; i < 200 && !living_members(group).empty(); ++i)
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        EXPECT_TRUE(living_members(group).empty()) << "processes of the encoder's group " << group << " still run";
    }

    void expect_exit_4(const Outcome& outcome, const std::string& fragment) const {
        EXPECT_EQ(outcome.exit_code, 4) << outcome.errors;
        EXPECT_NE(outcome.errors.find("anim.mp4: video encoding failed: " + fragment), std::string::npos) << outcome.errors;
        EXPECT_LT(outcome.seconds, 20) << "the 1 s stall timeout should end it within a few seconds";
        expect_clean_failure(outcome);
    }

    TempFolder folder;   // where clrender runs and the video goes
    TempFolder scripts;  // the fake encoder and its group id
    TempFolder work;     // the runner script and what it records
};

const std::string kQuickTimeout = "CLRENDER_ENCODER_TIMEOUT=1 ";

std::string encoder_env(const std::string& fake) { return "CLRENDER_FFMPEG='" + fake + "' "; }

// A wrapper script that exits but leaves a child running: the child must not outlive clrender.
TEST_F(EncoderFaults, EncoderExitingAtOnce) {
    const std::string fake = fake_encoder("sleep 1000 &\necho 'cannot open the output' >&2\nexit 1");
    const Outcome outcome = run(kQuickTimeout + encoder_env(fake), "anim.json -q --video anim.mp4");
    expect_exit_4(outcome, "");
    EXPECT_NE(outcome.errors.find("exited with status 1"), std::string::npos) << outcome.errors;
    EXPECT_NE(outcome.errors.find("cannot open the output"), std::string::npos) << "the log's tail" << outcome.errors;
}

// ffmpeg itself does this when the disk fills while it moves the MP4 index to the front.
TEST_F(EncoderFaults, EncoderWritingGarbageAndExitingZero) {
    const std::string fake = fake_encoder("cat > /dev/null\nfor last; do :; done\necho 'not a video' > \"$last\"\nexit 0");
    const Outcome outcome = run(kQuickTimeout + encoder_env(fake), "anim.json -q --video anim.mp4");
    expect_exit_4(outcome, "the finished video is not valid");
}

TEST_F(EncoderFaults, EncoderNeverReading) {
    const std::string fake = fake_encoder("exec sleep 1000");
    const Outcome outcome = run(kQuickTimeout + encoder_env(fake), "anim.json -q --video anim.mp4");
    expect_exit_4(outcome, "the encoder stopped reading frames for 1 s");
}

// It also leaves a child of its own running: the whole group must be stopped.
TEST_F(EncoderFaults, EncoderReadingEverythingAndNeverExiting) {
    const std::string fake = fake_encoder("sleep 1000 &\ncat > /dev/null\nwait");
    const Outcome outcome = run(kQuickTimeout + encoder_env(fake), "anim.json -q --video anim.mp4");
    expect_exit_4(outcome, "the encoder did not finish: its output stopped growing for 1 s after the last frame");
}

// Its background child survives it unless clrender stops the whole group.
TEST_F(EncoderFaults, EncoderKilledBySignalMidStream) {
    const std::string fake = fake_encoder("sleep 1000 &\nhead -c 20000 > /dev/null\nkill -KILL $$");
    const Outcome outcome = run(kQuickTimeout + encoder_env(fake), "anim.json -q --video anim.mp4");
    expect_exit_4(outcome, "the encoder stopped reading frames: ");
    EXPECT_NE(outcome.errors.find("was killed by signal 9"), std::string::npos) << outcome.errors;
}

// The default stall timeout (60 s) is far away: only the signal can end these runs quickly.
TEST_F(EncoderFaults, SigtermWhileTheEncoderStopsReading) {
    const std::string fake = fake_encoder("exec sleep 1000");
    const Outcome outcome = run(encoder_env(fake), "anim.json -q --video anim.mp4", "TERM", scripts.file("group"));
    EXPECT_EQ(outcome.exit_code, 143) << outcome.errors;
    EXPECT_NE(outcome.errors.find("interrupted by SIGTERM"), std::string::npos) << outcome.errors;
    EXPECT_LT(outcome.seconds, 5) << "clrender must stop within about a second of the signal";
    expect_clean_failure(outcome);
}

TEST_F(EncoderFaults, CtrlCWhileWaitingForTheEncoderToExit) {
    const std::string fake = fake_encoder("sleep 1000 &\ncat > /dev/null\ntouch '" + scripts.file("read-all") + "'\nwait");
    const Outcome outcome = run(encoder_env(fake), "anim.json -q --video anim.mp4", "INT", scripts.file("read-all"));
    EXPECT_EQ(outcome.exit_code, 130) << outcome.errors;
    EXPECT_NE(outcome.errors.find("interrupted by SIGINT"), std::string::npos) << outcome.errors;
    EXPECT_LT(outcome.seconds, 5) << "clrender must stop within about a second of the signal";
    expect_clean_failure(outcome);
}

// The log's tail is quoted in the error, which must stay one line and pass no escape
// sequence from the encoder to the terminal.
TEST_F(EncoderFaults, EncoderLogIsQuotedOnOneEscapedLine) {
    const std::string fake = fake_encoder("printf 'first line\\n\\033[2Jsecond line\\n' >&2\nexit 1");
    const Outcome outcome = run(kQuickTimeout + encoder_env(fake), "anim.json -q --video anim.mp4");
    expect_exit_4(outcome, "");
    EXPECT_NE(outcome.errors.find("its log ends: first line | \\x1B[2Jsecond line\n"), std::string::npos) << outcome.errors;
    EXPECT_EQ(count_of(outcome.errors, "\n"), 1) << "one line: " << outcome.errors;
}

// An encoder that floods its log and never exits: under the default 60 s stall timeout one
// writing a warning per pixel filled a gigabyte a second. This one writes 3 MB and then waits,
// so that the test itself never loads the disk: without the 1 MiB bound clrender would wait
// for the stall timeout, past the test's watchdog.
TEST_F(EncoderFaults, EncoderFloodingItsLog) {
    const std::string fake = fake_encoder("yes 'a warning, again' | head -c 3000000 >&2\ncat > /dev/null\nexec sleep 1000");
    const Outcome outcome = run(encoder_env(fake), "anim.json -q --video anim.mp4");
    expect_exit_4(outcome, "the encoder wrote more than 1 MiB of messages to its log");
}

// A closed terminal: the encoder (in its own process group) must be stopped, its files removed.
TEST_F(EncoderFaults, SighupWhileTheEncoderStopsReading) {
    const std::string fake = fake_encoder("exec sleep 1000");
    const Outcome outcome = run(encoder_env(fake), "anim.json -q --video anim.mp4", "HUP", scripts.file("group"));
    EXPECT_EQ(outcome.exit_code, 129) << outcome.errors;
    EXPECT_NE(outcome.errors.find("interrupted by SIGHUP"), std::string::npos) << outcome.errors;
    EXPECT_LT(outcome.seconds, 5) << "clrender must stop within about a second of the signal";
    expect_clean_failure(outcome);
}

// ---- A real ffmpeg on a full disk -------------------------------------------------------

using testing::have_program;

struct DiskRun {
    int exit_code = -1;
    std::string errors;
    std::string listing;  // the disk's files after the run
    std::string video;    // anim.mp4 after the run
};

// Runs clrender on a tmpfs of `pages` pages holding the scene and an earlier anim.mp4, all
// inside a private mount namespace: the disk vanishes with it, so what the checks need is
// copied out to `work` first.
DiskRun run_on_small_disk(const TempFolder& work, const std::string& scene, long pages) {
    const long kib = pages * ::sysconf(_SC_PAGESIZE) / 1024;
    work.write("scene.json", scene);
    work.write("earlier.mp4", kEarlierVideo);
    fs::create_directories(work.file("disk"));
    work.write("disk.sh", "set -e\ncd '" + work.path() + "'\nmount -t tmpfs -o size=" + std::to_string(kib) +
                              "k tmpfs disk\ncp scene.json disk/anim.json\ncp earlier.mp4 disk/anim.mp4\ncd disk\nset +e\n'" +
                              CLRENDER_BINARY + "' anim.json -q --video anim.mp4 2> ../stderr.txt\necho $? > ../code.txt\n"
                              "ls -A > ../listing.txt\ncp anim.mp4 ../after.mp4\n");
    DiskRun run;
    if (testing::run_in_mount_namespace(work.path(), "sh disk.sh") != 0) return run;
    run.exit_code = std::stoi(read_bytes(work.file("code.txt")));
    run.errors = read_bytes(work.file("stderr.txt"));
    run.listing = read_bytes(work.file("listing.txt"));
    run.video = read_bytes(work.file("after.mp4"));
    return run;
}

// ffmpeg exits 0 with a broken file when the disk fills while it moves the MP4 index to the
// front (+faststart), and 1 when it fills earlier: neither may replace the earlier video, and
// both messages say that the disk is full (ffmpeg's own log does not).
TEST(EncoderOnAFullDisk, FailsWith4AndKeepsTheEarlierVideo) {
    if (!have_program("ffmpeg") || !have_program("ffprobe")) GTEST_SKIP() << "ffmpeg is not installed";
    if (!testing::can_mount_small_disks()) GTEST_SKIP() << "cannot mount a tmpfs (needs root or unprivileged user namespaces)";
    std::string scene = kAnimation;
    const std::string small_size = R"("width": 128, "height": 96)";
    scene.replace(scene.find(small_size), small_size.size(), R"("width": 320, "height": 240)");

    // The video's size where space is plenty (the same frames give the same bytes).
    TempFolder reference;
    reference.write("anim.json", scene);
    ASSERT_EQ(testing::run_clrender("anim.json -q --video anim.mp4", reference.path()).exit_code, 0);
    const long page = ::sysconf(_SC_PAGESIZE);
    const long video_pages = (static_cast<long>(fs::file_size(reference.file("anim.mp4"))) + page - 1) / page;
    const long enough = video_pages + 2;  // the scene and the earlier video take a page each

    {
        TempFolder work;
        const DiskRun control = run_on_small_disk(work, scene, enough);
        ASSERT_EQ(control.exit_code, 0) << "with room for it, the video must be written:\n" << control.errors;
        EXPECT_TRUE(control.video == read_bytes(reference.file("anim.mp4"))) << "the video differs";
    }
    for (long pages : {enough - 1, 3L}) {
        TempFolder work;
        const DiskRun run = run_on_small_disk(work, scene, pages);
        EXPECT_EQ(run.exit_code, 4) << pages << " pages:\n" << run.errors;
        EXPECT_NE(run.errors.find("anim.mp4: video encoding failed: "), std::string::npos) << run.errors;
        // Also where ffmpeg exited 0 and only the check found the file cut off: the disk is named.
        EXPECT_NE(run.errors.find("it is likely full (No space left on device)"), std::string::npos)
            << pages << " pages:\n" << run.errors;
        EXPECT_EQ(count_of(run.errors, "clrender: error: "), 1) << run.errors;
        EXPECT_TRUE(run.video == kEarlierVideo)  // no EXPECT_EQ: it would print a video's bytes
            << pages << " pages: the earlier video was replaced by " << run.video.size() << " bytes";
        EXPECT_EQ(run.listing, "anim.json\nanim.mp4\n") << pages << " pages: files left behind";
    }
}

// The render loop does not wait on the encoder: an encoder that reads nothing until clrender
// reports frame 2 done (--progress json prints a line as each frame is handed over: frames 0 to
// 2 are then rendered and handed over) sees that report, and the video then comes out whole.
// 1280x960 frames (1.8 MB as yuv420p) are more than the pipe to the encoder holds (1 MiB), so
// a render loop that handed each frame to the encoder itself would still be sending frame 0.
// (frames_done counts files in place, which a video's frames are not until the video is.)
TEST_F(EncoderFaults, RenderLoopRunsAheadOfAnEncoderThatReadsNothing) {
    if (!testing::have_program("ffmpeg") || !testing::have_program("ffprobe")) GTEST_SKIP() << "ffmpeg is not installed";
    const std::string seen = scripts.file("seen");
    const std::string fake = fake_encoder(
        "i=0\n"
        "while ! grep -q '\"frame\":2,' '" + work.file("stderr.txt") + "' && [ $i -lt 2000 ]; do sleep 0.01; i=$((i+1)); done\n"
        "grep -o '\"frame\":[0-9]*,' '" + work.file("stderr.txt") + "' | tail -1 | tr -dc 0-9 > '" + seen + "'\n"
        "exec ffmpeg \"$@\"");
    const Outcome outcome = run(encoder_env(fake), "anim.json --progress json --size 1280x960 --video anim.mp4");
    const std::string started = read_bytes(seen);  // the last frame handed over
    EXPECT_TRUE(!started.empty() && std::stoi(started) >= 2)
        << "the last frame handed over before the encoder read its first byte: '" << started << "'";
    ASSERT_EQ(outcome.exit_code, 0) << outcome.errors;
    EXPECT_NE(read_bytes(folder.file("anim.mp4")), kEarlierVideo);
}

}  // namespace
}  // namespace clr
