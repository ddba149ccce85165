// Progress through the real binary (docs/command-line.md, Progress): the bar on a terminal for a
// still as for an animation, nothing when standard error is not a terminal or with -q, an error
// line that starts on a line of its own after the bar, and --progress json's lines.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "support/command.h"
#include "support/small_disk.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using testing::read_bytes;
using testing::run_clrender;
using testing::TempFolder;

// A still of a fraction of a second.
const char* kStill = R"({
  "eye": [0, 3, 14], "lookat": [0, 1, 0], "up": [0, 1, 0], "fov_angle": 60,
  "width": 400, "height": 300, "SunLocation": [30, 50, 20], "MaxDepth": 6, "clrender": {"spp": 16},
  "spheres": [
    {"center": [-3, 1, 0], "radius": 2, "ambient": [0.9, 0.3, 0.2], "IsMirror": 1},
    {"center": [3, 1, 0], "radius": 2, "ambient": [0.2, 0.4, 0.9], "IsMirror": 1},
    {"center": [0, 4, 2], "radius": 1, "ambient": [0.9, 0.9, 0.2]}],
  "billboards": [{"UpperLeft": [-20, -1, -20], "LowerLeft": [-20, -1, 20], "UpperRight": [20, -1, -20], "ambient": [0.5, 0.5, 0.5]}]
})";

// The same still, a second or two on two loaded cores: several bands of rows.
const char* kBandedStill = R"({
  "eye": [0, 3, 14], "lookat": [0, 1, 0], "up": [0, 1, 0], "fov_angle": 60,
  "width": 512, "height": 384, "SunLocation": [30, 50, 20], "MaxDepth": 6, "clrender": {"spp": 256},
  "spheres": [
    {"center": [-3, 1, 0], "radius": 2, "ambient": [0.9, 0.3, 0.2], "IsMirror": 1},
    {"center": [3, 1, 0], "radius": 2, "ambient": [0.2, 0.4, 0.9], "IsMirror": 1},
    {"center": [0, 4, 2], "radius": 1, "ambient": [0.9, 0.9, 0.2]}],
  "billboards": [{"UpperLeft": [-20, -1, -20], "LowerLeft": [-20, -1, 20], "UpperRight": [20, -1, -20], "ambient": [0.5, 0.5, 0.5]}]
})";

// The same still, slow enough (minutes) to be interrupted while it renders.
const char* kSlowStill = R"({
  "eye": [0, 3, 14], "lookat": [0, 1, 0], "up": [0, 1, 0], "fov_angle": 60,
  "width": 1024, "height": 1024, "SunLocation": [30, 50, 20], "MaxDepth": 8, "clrender": {"spp": 1024},
  "spheres": [
    {"center": [-3, 1, 0], "radius": 2, "ambient": [0.9, 0.3, 0.2], "IsMirror": 1},
    {"center": [3, 1, 0], "radius": 2, "ambient": [0.2, 0.4, 0.9], "IsMirror": 1},
    {"center": [0, 4, 2], "radius": 1, "ambient": [0.9, 0.9, 0.2]}],
  "billboards": [{"UpperLeft": [-20, -1, -20], "LowerLeft": [-20, -1, 20], "UpperRight": [20, -1, -20], "ambient": [0.5, 0.5, 0.5]}]
})";

const char* kAnimation = R"({
  "eyeLocations": [[-3, 1, 8], [3, 2, 7]], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 55,
  "width": 48, "height": 32, "clrender": {"frames": 10},
  "spheres": [{"center": [0, 0, 0], "radius": 1.5, "ambient": [1, 0.3, 0.2]}]
})";

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

// Runs `script_text` (bash) with its standard streams on a new terminal (script(1)); returns
// what the terminal showed.
std::string run_on_a_terminal(const TempFolder& folder, const std::string& script_text) {
    folder.write("on_terminal.sh", "cd '" + folder.path() + "'\n" + script_text);
    const std::string command = "script -qefc 'bash \"" + folder.file("on_terminal.sh") + "\"' /dev/null > '" +
                                folder.file("terminal.txt") + "' 2>&1 < /dev/null";
    EXPECT_EQ(std::system(command.c_str()), 0) << command;
    return read_bytes(folder.file("terminal.txt"));
}

const std::string kBinary = std::string("'") + CLRENDER_BINARY + "'";

TEST(ProgressCli, HelpNamesTheProgressAndControlOptions) {
    auto result = run_clrender("--help");
    EXPECT_EQ(result.exit_code, 0);
    for (const char* option : {"--progress", "-t,--threads", "--crop", "bar", "json"})
        EXPECT_NE(result.output.find(option), std::string::npos) << option;
}

TEST(ProgressCli, AStillShowsABarOnATerminal) {
    TempFolder folder;
    folder.write("still.json", kStill);
    const std::string shown = run_on_a_terminal(folder, kBinary + " still.json -o still.png\n");
    EXPECT_NE(shown.find("clrender: ["), std::string::npos) << shown;
    EXPECT_NE(shown.find("100%"), std::string::npos) << shown;
    EXPECT_NE(shown.find("elapsed "), std::string::npos) << shown;
    EXPECT_NE(shown.find("left "), std::string::npos) << shown;
    EXPECT_EQ(shown.find("frame 1/1"), std::string::npos) << "a still has no frame count: " << shown;
    EXPECT_NE(shown.find("clrender: wrote still.png"), std::string::npos) << shown;
}

TEST(ProgressCli, AnAnimationsBarCountsFrames) {
    TempFolder folder;
    folder.write("anim.json", kAnimation);
    const std::string shown = run_on_a_terminal(folder, kBinary + " anim.json -o 'f_%04d.png'\n");
    EXPECT_NE(shown.find("frame 10/10"), std::string::npos) << shown;
    EXPECT_NE(shown.find("100%"), std::string::npos) << shown;
    EXPECT_NE(shown.find(" frames/s  elapsed "), std::string::npos) << "frames per second (docs/animation.md): " << shown;
}

TEST(ProgressCli, NoBarWithQuietOrNoneOrOffATerminal) {
    TempFolder folder;
    folder.write("still.json", kStill);
    for (const char* options : {"-q", "--progress none"}) {
        const std::string shown = run_on_a_terminal(folder, kBinary + " still.json -o still.png " + options + "\n");
        EXPECT_EQ(shown.find("clrender: ["), std::string::npos) << options << ": " << shown;
    }
    auto piped = run_clrender("still.json -o still.png", folder.path());
    ASSERT_EQ(piped.exit_code, 0) << piped.output;
    EXPECT_EQ(piped.output.find("clrender: ["), std::string::npos) << piped.output;
    EXPECT_EQ(piped.output.find('\r'), std::string::npos) << piped.output;
}

TEST(ProgressCli, AnInterruptionMessageStartsOnItsOwnLine) {
    TempFolder folder;
    folder.write("still.json", kSlowStill);
    const std::string shown = run_on_a_terminal(folder, kBinary +
                                                            " still.json -o still.png &\n"
                                                            "pid=$!\n"
                                                            "i=0\n"  // until the bar shows (at most 30 s)
                                                            "while ! grep -q 'clrender: \\[' terminal.txt && "
                                                            "[ $i -lt 3000 ]; do sleep 0.01; i=$((i+1)); done\n"
                                                            "sleep 0.5\n"
                                                            "kill -INT $pid\n"
                                                            "wait $pid\n"
                                                            "echo \"exit $?\"\n");
    EXPECT_NE(shown.find("exit 130"), std::string::npos) << shown;
    const std::size_t bar = shown.find("clrender: [");
    ASSERT_NE(bar, std::string::npos) << "the bar was drawn before the signal: " << shown;
    const std::size_t error = shown.find("clrender: error: interrupted by SIGINT");
    ASSERT_NE(error, std::string::npos) << shown;
    EXPECT_GT(error, bar);
    EXPECT_EQ(shown[error - 1], '\n') << "the error line shares the bar's line:\n" << shown;
}

// Every line on standard error (-q: nothing else) is one JSON object with the documented keys.
std::vector<nlohmann::json> json_lines(const std::string& output) {
    std::vector<nlohmann::json> parsed;
    for (const std::string& line : lines_of(output)) {
        nlohmann::json object;
        try {
            object = nlohmann::json::parse(line);
        } catch (const nlohmann::json::parse_error& error) {
            ADD_FAILURE() << "not JSON: '" << line << "': " << error.what();
            continue;
        }
        for (const char* key : {"frame", "frames", "frames_done", "percent", "elapsed_s", "eta_s"})
            EXPECT_TRUE(object.contains(key)) << key << " in " << line;
        parsed.push_back(object);
    }
    return parsed;
}

TEST(ProgressCli, JsonLinesForAStillComePerBand) {
    TempFolder folder;
    folder.write("still.json", kBandedStill);
    auto result = run_clrender("still.json -o still.png -q --progress json", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const std::vector<nlohmann::json> lines = json_lines(result.output);
    // Bands take about 0.15 s each and lines come at most ten a second: a still of a second or
    // more (spp 256 here) shows at least one band before the finished still, however fast.
    ASSERT_GE(lines.size(), 2u) << "bands, then the finished still:\n" << result.output;
    double percent = 0;
    for (const nlohmann::json& line : lines) {
        EXPECT_EQ(line["frames"], 1);
        EXPECT_EQ(line["frame"], 0);
        EXPECT_GE(line["percent"].get<double>(), percent) << line;
        percent = line["percent"].get<double>();
    }
    EXPECT_LT(lines.front()["percent"].get<double>(), 100);
    EXPECT_EQ(lines.front()["frames_done"], 0);
    EXPECT_EQ(lines.back()["percent"].get<double>(), 100);
    EXPECT_EQ(lines.back()["frames_done"], 1);
    EXPECT_EQ(lines.back()["eta_s"].get<double>(), 0);
}

TEST(ProgressCli, JsonLinesForAnAnimationComePerFrame) {
    TempFolder folder;
    folder.write("anim.json", kAnimation);
    auto result = run_clrender("anim.json -o 'f_%04d.png' --frames 2,5-7 -q --progress json", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const std::vector<nlohmann::json> lines = json_lines(result.output);
    // One line per frame rendered, and the last once every file is under its name.
    ASSERT_EQ(lines.size(), 5u) << result.output;
    const int frames[] = {2, 5, 6, 7, 7};
    int done = 0;
    for (int i = 0; i < 5; ++i) {
        EXPECT_EQ(lines[i]["frame"], frames[i]);
        EXPECT_EQ(lines[i]["frames"], 4);
        // A frame counts once its file is in place: the writer may lag behind the renderer.
        EXPECT_LE(lines[i]["frames_done"].get<int>(), std::min(i + 1, 4)) << lines[i];
        EXPECT_GE(lines[i]["frames_done"].get<int>(), done) << lines[i];
        done = lines[i]["frames_done"].get<int>();
        EXPECT_DOUBLE_EQ(lines[i]["percent"].get<double>(), 25.0 * std::min(i + 1, 4));
    }
    EXPECT_EQ(lines.back()["frames_done"], 4);
}

// On a disk that fills up, a frame whose file could not be written is never reported done:
// every line's frames_done is at most the frames on disk after the run.
TEST(ProgressCli, JsonFramesDoneCountsOnlyFramesOnDisk) {
    if (!testing::can_mount_small_disks()) GTEST_SKIP() << "cannot mount a small tmpfs here (needs root or unshare -rm)";
    TempFolder folder;
    folder.write("anim.json", R"({
      "eyeLocations": [[-3, 1, 8], [3, 2, 7]], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 55,
      "width": 96, "height": 64, "clrender": {"frames": 400, "seed": 3, "spp": 4},
      "spheres": [{"center": [0, 0, 0], "radius": 1.5, "ambient": [1, 0.3, 0.2]}],
      "billboards": [{"UpperLeft": [-5, 4, -4], "LowerLeft": [-5, -3, -4], "UpperRight": [5, 4, -4], "ambient": [0.2, 0.6, 0.3]}]
    })");
    fs::create_directory(folder.file("disk"));
    const int status = testing::run_in_mount_namespace(
        folder.path(), "mount -t tmpfs -o size=64k tmpfs disk; code=0; "
                       "\"$CLRENDER\" anim.json -o disk/f_%04d.png -q --progress json 2>stderr.txt || code=$?; "
                       "echo $code >exit_code; ls disk | grep -c \"^f_\" >frames_on_disk || true");
    ASSERT_EQ(status, 0) << "the namespace script failed";
    const std::string stderr_text = read_bytes(folder.file("stderr.txt"));
    ASSERT_EQ(read_bytes(folder.file("exit_code")), "4\n") << stderr_text;
    const int on_disk = std::stoi(read_bytes(folder.file("frames_on_disk")));
    ASSERT_GT(on_disk, 0) << stderr_text;
    ASSERT_LT(on_disk, 400) << stderr_text;
    int most_done = 0, progress_lines = 0;
    for (const std::string& line : lines_of(stderr_text)) {
        const nlohmann::json object = nlohmann::json::parse(line);  // every line is JSON, the error's too
        if (!object.contains("frames_done")) continue;
        ++progress_lines;
        most_done = std::max(most_done, object["frames_done"].get<int>());
    }
    EXPECT_GT(progress_lines, 0) << stderr_text;
    EXPECT_LE(most_done, on_disk) << "frames reported done that are not on disk:\n" << stderr_text;
}

// With --progress json every line on standard error is one JSON object: warnings and the error
// as much as progress, with -q and without.
TEST(ProgressCli, JsonMakesEveryLineOnStandardErrorJson) {
    TempFolder folder;
    folder.write("anim.json", std::string(kAnimation).insert(1, R"("unknown_key": 1, )"));  // a warning
    for (const char* quiet : {" -q", ""}) {
        auto good = run_clrender(std::string("anim.json -o 'f_%04d.png' --frames 0-2 --progress json") + quiet, folder.path());
        ASSERT_EQ(good.exit_code, 0) << good.output;
        auto bad = run_clrender(std::string("anim.json -o 'f_%04d.png' --frames 0-20 --progress json") + quiet, folder.path());
        ASSERT_EQ(bad.exit_code, 1) << bad.output;  // frame 20 is outside the animation
        int warnings = 0, errors = 0;
        for (const std::string& line : lines_of(good.output + bad.output)) {
            nlohmann::json object;
            ASSERT_NO_THROW(object = nlohmann::json::parse(line)) << "not JSON: " << line;
            ASSERT_TRUE(object.is_object()) << line;
            if (object.value("level", "") == "warning") {
                ++warnings;
                EXPECT_NE(object["message"].get<std::string>().find("unknown_key"), std::string::npos) << line;
            }
            if (object.value("level", "") == "error") {
                ++errors;
                EXPECT_EQ(object["exit_code"], 1) << line;
                EXPECT_NE(object["message"].get<std::string>().find("20"), std::string::npos) << line;
            }
        }
        EXPECT_EQ(warnings, 2) << quiet << good.output << bad.output;
        EXPECT_EQ(errors, 1) << quiet << bad.output;
    }
    // A command-line error, before the options are known, too.
    auto usage = run_clrender("anim.json --progress json --no-such-option", folder.path());
    EXPECT_EQ(usage.exit_code, 1);
    EXPECT_NO_THROW(nlohmann::json::parse(usage.output)) << usage.output;
}

// What the OpenCL compiler prints during a build that succeeds ("1 warning generated.") comes
// as JSON warnings too.
TEST(ProgressCli, JsonWrapsTheCompilersOwnOutput) {
    TempFolder folder;
    folder.write("still.json", kAnimation);
    const std::string kernels = folder.file("kernels");
    fs::copy(std::string(CLRENDER_SOURCE_DIR) + "/kernels", kernels, fs::copy_options::recursive);
    for (const auto& program : fs::directory_iterator(kernels + "/programs"))
        folder.write(fs::relative(program.path(), folder.path()).string(),
                     read_bytes(program.path()) + "\n#warning \"a warning of the test's\"\n");
    const std::string arguments = "still.json --frames 0 -o still.png -q --kernel-dir kernels";
    auto plain = run_clrender(arguments, folder.path(), "CLRENDER_CACHE_DIR=off");
    ASSERT_EQ(plain.exit_code, 0) << plain.output;
    EXPECT_NE(plain.output.find("warning generated."), std::string::npos) << "the compiler spoke: " << plain.output;
    auto json = run_clrender(arguments + " --progress json", folder.path(), "CLRENDER_CACHE_DIR=off");
    ASSERT_EQ(json.exit_code, 0) << json.output;
    int compiler_lines = 0;
    for (const std::string& line : lines_of(json.output)) {
        nlohmann::json object;
        ASSERT_NO_THROW(object = nlohmann::json::parse(line)) << "not JSON: " << line;
        if (object.value("message", "").rfind("OpenCL compiler: ", 0) == 0) {
            EXPECT_EQ(object["level"], "warning") << line;
            ++compiler_lines;
        }
    }
    EXPECT_GT(compiler_lines, 0) << json.output;
}

TEST(ProgressCli, JsonLinesWithoutQuietAndOffATerminal) {
    TempFolder folder;
    folder.write("anim.json", kAnimation);
    auto result = run_clrender("anim.json -o 'f_%04d.png' --frames 0-2 --progress json", folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    int progress = 0, messages = 0;
    for (const std::string& line : lines_of(result.output)) {
        nlohmann::json object;
        ASSERT_NO_THROW(object = nlohmann::json::parse(line)) << line;
        if (object.contains("frames_done")) ++progress;
        if (object.value("level", "") == "info") ++messages;  // the device line, the summary
    }
    EXPECT_EQ(progress, 4) << result.output;
    EXPECT_GE(messages, 2) << result.output;
}

}  // namespace
}  // namespace clr
