// clrender view from start to stop: the one printed line, a scene error before listening
// (exit 2, nothing printed to standard output), options that do not apply refused, and a
// signal ending it with 128 + signal and nothing left behind.
#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <regex>
#include <set>
#include <thread>

#include "support/command.h"
#include "support/loopback_client.h"
#include "support/temp_folder.h"
#include "view/viewer_process.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using testing::read_bytes;
using testing::run_clrender;
using testing::TempFolder;
using testing::ViewerProcess;

const std::string kDemoScene = std::string(CLRENDER_SOURCE_DIR) + "/scenes/demo/demo.json";

std::set<std::string> entries(const TempFolder& folder) {
    std::set<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder.path())) names.insert(entry.path().filename().string());
    return names;
}

TEST(ViewLifetime, PrintsOneLineAndStopsCleanlyOnEachSignal) {
    for (const auto& [signal, code] : {std::pair{SIGTERM, 143}, std::pair{SIGINT, 130}}) {
        TempFolder folder;
        folder.write("before.txt", "x");
        ViewerProcess viewer("'" + kDemoScene + "' --size 32x18", folder.path());
        ASSERT_TRUE(viewer.started()) << viewer.output();
        EXPECT_TRUE(std::regex_match(viewer.address_line(),
                                     std::regex(R"(clrender: view at http://127\.0\.0\.1:\d+/\?token=[0-9a-f]{32})")));
        // A frame in flight and an open connection do not keep it from stopping.
        auto client = viewer.client();
        EXPECT_EQ(client->Get(viewer.with_token("/frame.png").c_str())->status, 200);
        EXPECT_EQ(viewer.stop(signal), code) << viewer.output();
        EXPECT_EQ(entries(folder), (std::set<std::string>{"before.txt", "view-stderr.txt"})) << "left behind";
        // The port is free again: nothing of the server lives on.
        EXPECT_FALSE(client->Get(viewer.with_token("/scene.json").c_str()));
    }
}

TEST(ViewLifetime, ASignalRightAfterTheLineStopsIt) {
    // The server's thread may not have started listening when the line is printed; a signal at
    // that moment must still end the viewer.
    TempFolder folder;
    for (int i = 0; i < 5; ++i) {
        ViewerProcess viewer("'" + kDemoScene + "' --size 16x9", folder.path());
        ASSERT_TRUE(viewer.started()) << viewer.output();
        EXPECT_EQ(viewer.stop(SIGTERM, 20), 143) << viewer.output();
    }
}

TEST(ViewLifetime, EachStartHasItsOwnToken) {
    TempFolder folder;
    ViewerProcess first("'" + kDemoScene + "' --size 32x18", folder.path());
    ViewerProcess second("'" + kDemoScene + "' --size 32x18", folder.path());
    ASSERT_TRUE(first.started() && second.started()) << first.output() << second.output();
    EXPECT_NE(first.token(), second.token());
    EXPECT_NE(first.port(), second.port());
    // One's token does not open the other.
    EXPECT_EQ(second.client()->Get(("/scene.json?token=" + first.token()).c_str())->status, 403);
}

TEST(ViewLifetime, SceneErrorsAreReportedAsForARenderBeforeListening) {
    TempFolder folder;
    folder.write("bad.json", R"({"eye": [0, 0, 5], "lookat": [0, 0, 5], "up": [0, 1, 0], "fov_angle": 60, "width": 8, "height": 8})");
    const auto result = run_clrender("view bad.json --no-browser", folder.path());
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_EQ(result.output,
              "clrender: error: bad.json: /eye: eye and lookat are the same point [0, 0, 5], so the camera has no view "
              "direction\n")
        << "the render's one line, and no address";
    EXPECT_EQ(run_clrender("view missing.json --no-browser", folder.path()).exit_code, 2);
    // -D values are checked as a render checks them.
    EXPECT_EQ(run_clrender("view '" + kDemoScene + "' --no-browser -D fov_angle=200", folder.path()).exit_code, 2);
}

TEST(ViewLifetime, OptionsThatDoNotApplyAreUsageErrors) {
    TempFolder folder;
    for (const char* option : {"-o x.png", "--video x.mp4", "--frames 1", "--explain-pixel 1,1", "--port 70000",
                               "--bind ''", "--output-dir ''", "--spp 0", "--size 0x5", "--nonsense"}) {
        const auto result = run_clrender("view '" + kDemoScene + "' --no-browser " + option, folder.path());
        EXPECT_EQ(result.exit_code, 1) << option << ": " << result.output;
        EXPECT_EQ(result.output.find("view at"), std::string::npos) << option;
    }
    EXPECT_EQ(folder.entry_count(), 0);
    EXPECT_EQ(run_clrender("view --help").exit_code, 0);
    EXPECT_NE(run_clrender("view --help").output.find("--no-browser"), std::string::npos);
}

// The render options the viewer takes (view_options.cpp's footer), and every other one of
// `clrender --help` with a value to give it: each of those names an output or another mode,
// which the viewer would ignore in silence.
const std::set<std::string> kOptionsThatApply = {"--help",    "--size",         "--spp",   "--device",
                                                 "--threads", "--define",       "--seed",  "--precision",
                                                 "--strict",  "--placeholders", "--quiet", "--kernel-dir"};
const std::map<std::string, std::string> kOptionsThatDoNotApply = {
    {"--output", "-o x.png"},
    {"--video", "--video x.mp4"},
    {"--frames", "--frames 1"},
    {"--assemble", "--assemble"},
    {"--resume", "--resume"},
    {"--quality", "--quality 20"},
    {"--list-devices", "--list-devices"},
    {"--frame-count", "--frame-count"},
    {"--reference", "--reference"},
    {"--stats", "--stats s.json"},
    {"--explain-pixel", "--explain-pixel 1,1"},
    {"--progress", "--progress json"},
    {"--crop", "--crop 0,4,0,4"},
    {"--check", "--check"},
    {"--plan", "--plan"},
    {"--alpha", "--alpha"},
    {"--join", "--join t.png"},
    {"--display-server", "--display-server localhost:1"},
    {"--version", ""},  // prints the version and exits, as for a render
};

TEST(ViewLifetime, EveryRenderOptionAppliesOrIsRefused) {
    // --plan and --display-server were taken and ignored: the viewer served, no plan printed,
    // nothing sent to tev.
    const std::string help = run_clrender("--help").output;
    const std::regex option(R"(\n  (?:-[a-zA-Z],)?(--[a-z-]+))");
    TempFolder folder;
    std::set<std::string> listed;
    for (auto it = std::sregex_iterator(help.begin(), help.end(), option); it != std::sregex_iterator(); ++it) {
        const std::string name = (*it)[1];
        listed.insert(name);
        if (kOptionsThatApply.count(name)) continue;
        const auto refused = kOptionsThatDoNotApply.find(name);
        ASSERT_NE(refused, kOptionsThatDoNotApply.end()) << name << ": the viewer neither takes nor refuses it";
        if (refused->second.empty()) continue;
        const auto result = run_clrender("view '" + kDemoScene + "' --no-browser " + refused->second, folder.path(),
                                         "timeout 20");
        EXPECT_EQ(result.exit_code, 1) << refused->second << ": " << result.output;
        const std::string shown = refused->second.substr(0, refused->second.find(' '));  // -o for --output
        EXPECT_NE(result.output.find(shown + " does not apply to clrender view"), std::string::npos) << result.output;
        EXPECT_EQ(result.output.find("view at"), std::string::npos) << refused->second;
    }
    EXPECT_EQ(listed.size(), kOptionsThatApply.size() + kOptionsThatDoNotApply.size()) << "an option left --help";
    EXPECT_EQ(folder.entry_count(), 0);
}

TEST(ViewLifetime, AMissingOutputFolderIsAnOutputError) {
    TempFolder folder;
    const auto result = run_clrender("view '" + kDemoScene + "' --no-browser --output-dir nowhere", folder.path());
    EXPECT_EQ(result.exit_code, 4) << result.output;
    EXPECT_NE(result.output.find("--output-dir nowhere: no such folder"), std::string::npos) << result.output;
}

TEST(ViewLifetime, AnOutputDirThatIsAFileOrCannotBeWrittenIsRefusedAtStart) {
    TempFolder folder;
    folder.write("file.txt", "a file");
    const auto file = run_clrender("view '" + kDemoScene + "' --no-browser --output-dir file.txt", folder.path());
    EXPECT_EQ(file.exit_code, 4) << file.output;
    EXPECT_NE(file.output.find("--output-dir file.txt: not a folder"), std::string::npos) << file.output;
    EXPECT_EQ(read_bytes(folder.file("file.txt")), "a file");
    if (::geteuid() == 0) GTEST_SKIP() << "root may write into read-only folders";
    fs::create_directories(folder.file("locked"));
    fs::permissions(folder.file("locked"), fs::perms::owner_read | fs::perms::owner_exec);
    const auto locked = run_clrender("view '" + kDemoScene + "' --no-browser --output-dir locked", folder.path());
    fs::permissions(folder.file("locked"), fs::perms::owner_all);
    EXPECT_EQ(locked.exit_code, 4) << locked.output;
    EXPECT_NE(locked.output.find("--output-dir locked: cannot write there (Permission denied)"), std::string::npos)
        << locked.output;
    EXPECT_EQ(locked.output.find("view at"), std::string::npos);
}

// A name would be looked up (and could name another machine later), and an address with a
// space is no address: both are refused before anything loads, with the reason.
TEST(ViewLifetime, BindMustBeAnAddress) {
    TempFolder folder;
    for (const std::string bind : {"evil.example", "'127.0.0.1 '", "127.0.0.1:80", "'[::1'"}) {
        const auto result = run_clrender("view '" + kDemoScene + "' --no-browser --bind " + bind, folder.path());
        EXPECT_EQ(result.exit_code, 1) << bind << ": " << result.output;
        EXPECT_NE(result.output.find("is not an IP address (127.0.0.1, ::1, 0.0.0.0, ...) or localhost"), std::string::npos)
            << bind << ": " << result.output;
        EXPECT_EQ(result.output.find("No such file"), std::string::npos) << result.output;
    }
}

// Installs a stand-in for xdg-open in `folder` that records what it was asked to open; returns
// the environment that makes the viewer use it (and write its page under `folder`).
std::string stand_in_browser_opener(const TempFolder& folder) {
    fs::create_directories(folder.file("bin"));
    folder.write("bin/xdg-open", "#!/bin/sh\necho \"$1\" > '" + folder.file("opened.txt") + "'\n");
    fs::permissions(folder.file("bin/xdg-open"), fs::perms::owner_all);
    fs::create_directories(folder.file("run"));
    fs::permissions(folder.file("run"), fs::perms::owner_all);
    return "PATH='" + folder.file("bin") + "' XDG_RUNTIME_DIR='" + folder.file("run") + "'";
}

// What the stand-in was asked to open (waiting up to 5 s for it), "" when nothing.
std::string opened_by_stand_in(const TempFolder& folder) {
    for (int i = 0; i < 500 && read_bytes(folder.file("opened.txt")).empty(); ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    std::string opened = read_bytes(folder.file("opened.txt"));
    if (!opened.empty()) opened.pop_back();  // the newline
    return opened;
}

TEST(ViewLifetime, OpensTheBrowserWithTheAddressAndGoesOnWithoutOne) {
    TempFolder folder;
    fs::create_directories(folder.file("bin"));
    // A stand-in for xdg-open that records what it was asked to open.
    folder.write("bin/xdg-open", "#!/bin/sh\necho \"$1\" > '" + folder.file("opened.txt") + "'\n");
    fs::permissions(folder.file("bin/xdg-open"), fs::perms::owner_all);
    fs::create_directories(folder.file("run"));
    fs::permissions(folder.file("run"), fs::perms::owner_all);
    ViewerProcess viewer("'" + kDemoScene + "' --size 16x9", folder.path(),
                         "PATH='" + folder.file("bin") + "' XDG_RUNTIME_DIR='" + folder.file("run") + "'", true);
    ASSERT_TRUE(viewer.started()) << viewer.output();
    for (int i = 0; i < 500 && read_bytes(folder.file("opened.txt")).empty(); ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    // xdg-open (and the browser it starts) get a page's path, not the token, which any user
    // could read in their arguments; the page, its owner's alone, forwards to the address.
    std::string opened = read_bytes(folder.file("opened.txt"));
    ASSERT_FALSE(opened.empty());
    opened.pop_back();  // the newline
    EXPECT_EQ(opened.find(viewer.token()), std::string::npos) << opened;
    EXPECT_EQ(fs::path(opened).parent_path().parent_path(), fs::path(folder.file("run"))) << opened;
    EXPECT_EQ(fs::status(opened).permissions() & fs::perms::all, fs::perms::owner_read | fs::perms::owner_write);
    EXPECT_EQ(fs::status(fs::path(opened).parent_path()).permissions() & fs::perms::all, fs::perms::owner_all);
    const std::string address = "http://127.0.0.1:" + std::to_string(viewer.port()) + "/?token=" + viewer.token();
    EXPECT_NE(read_bytes(opened).find("<meta http-equiv=\"refresh\" content=\"0;url=" + address + "\">"),
              std::string::npos)
        << read_bytes(opened);
    EXPECT_EQ(viewer.stop(SIGTERM), 143);
    EXPECT_FALSE(fs::exists(fs::path(opened).parent_path())) << "the page and its folder are removed";
    // Without xdg-open: a warning, and the viewer serves all the same.
    ViewerProcess without("'" + kDemoScene + "' --size 16x9", folder.path(), "PATH=/nonexistent", true);
    ASSERT_TRUE(without.started()) << without.output();
    EXPECT_EQ(without.client()->Get(without.with_token("/scene.json").c_str())->status, 200);
    EXPECT_EQ(without.stop(SIGTERM), 143);
    EXPECT_NE(without.output().find("warning: cannot open the browser"), std::string::npos) << without.output();
}

// Where the page that opens the browser cannot be made (a folder no one can create in), the
// browser is not opened, with a warning, and the viewer serves all the same.
TEST(ViewLifetime, APageThatCannotBeWrittenOpensNoBrowser) {
    TempFolder folder;
    fs::create_directories(folder.file("bin"));
    folder.write("bin/xdg-open", "#!/bin/sh\necho \"$1\" > '" + folder.file("opened.txt") + "'\n");
    fs::permissions(folder.file("bin/xdg-open"), fs::perms::owner_all);
    ViewerProcess viewer("'" + kDemoScene + "' --size 16x9", folder.path(),
                         "PATH='" + folder.file("bin") + "' XDG_RUNTIME_DIR=/proc", true);
    ASSERT_TRUE(viewer.started()) << viewer.output();
    EXPECT_EQ(viewer.client()->Get(viewer.with_token("/scene.json").c_str())->status, 200);
    EXPECT_EQ(viewer.stop(SIGTERM), 143);
    EXPECT_FALSE(fs::exists(folder.file("opened.txt"))) << read_bytes(folder.file("opened.txt"));
    EXPECT_NE(viewer.output().find("warning: cannot open the browser (cannot make a folder in /proc: "),
              std::string::npos)
        << viewer.output();
}

// A request still arriving when the viewer is told to stop is dropped at once: its client
// sees the connection end well before the 5 s read timeout that would otherwise run out.
TEST(ViewLifetime, AHalfSentRequestIsDroppedAtTheStop) {
    TempFolder folder;
    ViewerProcess viewer("'" + kDemoScene + "' --size 16x9", folder.path());
    ASSERT_TRUE(viewer.started()) << viewer.output();
    const int socket = testing::connect_to_loopback(viewer.port());
    ASSERT_GE(socket, 0);
    ASSERT_EQ(::write(socket, "GET /scene", 10), 10);
    std::this_thread::sleep_for(std::chrono::milliseconds(300));  // the server is reading it
    int code = 0;
    const auto signalled = std::chrono::steady_clock::now();
    std::thread stopper([&] { code = viewer.stop(SIGTERM); });
    pollfd ready{socket, POLLIN, 0};
    char byte = 0;
    const bool ended = ::poll(&ready, 1, 10000) > 0 && ::read(socket, &byte, 1) == 0;
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - signalled).count();
    stopper.join();
    ::close(socket);
    EXPECT_TRUE(ended);
    EXPECT_LT(seconds, 3.0);
    EXPECT_EQ(code, 143);
}

TEST(ViewLifetime, AnotherBindAddressWarns) {
    TempFolder folder;
    ViewerProcess viewer("'" + kDemoScene + "' --size 16x9 --bind 0.0.0.0", folder.path());
    ASSERT_TRUE(viewer.started()) << viewer.output();
    EXPECT_EQ(viewer.stop(SIGTERM), 143);
    EXPECT_NE(viewer.output().find("warning: --bind 0.0.0.0: the viewer listens beyond this machine"), std::string::npos)
        << viewer.output();
}

// 127.0.0.0/8 is this machine: the note says which address, not that other machines reach it.
TEST(ViewLifetime, AnotherLoopbackAddressIsNotBeyondThisMachine) {
    TempFolder folder;
    ViewerProcess viewer("'" + kDemoScene + "' --size 16x9 --bind 127.0.0.2", folder.path());
    // (started() expects 127.0.0.1 in the line)
    EXPECT_NE(viewer.address_line().find("clrender: view at http://127.0.0.2:"), std::string::npos) << viewer.output();
    EXPECT_EQ(viewer.stop(SIGTERM), 143);
    EXPECT_NE(viewer.output().find("warning: --bind 127.0.0.2: listening on 127.0.0.2 rather than 127.0.0.1"),
              std::string::npos)
        << viewer.output();
    EXPECT_EQ(viewer.output().find("beyond this machine"), std::string::npos) << viewer.output();
}

// localhost is a name: the viewer listens on its first address only, and a browser looks the
// name up itself (Chromium tries ::1 first), where another user's program could hold the same
// port and receive the token. The line, and the page that opens the browser, name the address
// the viewer listens on.
TEST(ViewLifetime, BindLocalhostNamesTheAddressItListensOn) {
    TempFolder folder;
    ViewerProcess viewer("'" + kDemoScene + "' --size 16x9 --bind localhost", folder.path(),
                         stand_in_browser_opener(folder), true);
    std::smatch line;
    const std::string address_line = viewer.address_line();
    ASSERT_TRUE(std::regex_match(address_line, line,
                                 std::regex(R"(clrender: view at (http://(127\.0\.0\.1|\[::1\]):\d+/\?token=[0-9a-f]{32}))")))
        << viewer.output();
    const std::string opened = opened_by_stand_in(folder);
    ASSERT_FALSE(opened.empty());
    EXPECT_NE(read_bytes(opened).find("url=" + line[1].str() + "\""), std::string::npos) << read_bytes(opened);
    EXPECT_EQ(viewer.stop(SIGTERM), 143);
    EXPECT_NE(viewer.output().find("warning: --bind localhost: listening on " + line[2].str() + " only"), std::string::npos)
        << viewer.output();
}

// The printed line is the one way to the viewer with --no-browser: standard output full or
// closed is an output error (exit 4, one line), never a viewer that serves on unreachable.
TEST(ViewLifetime, AnAddressThatCannotBePrintedIsAnOutputError) {
    TempFolder folder;
    for (const std::string redirection : {">/dev/full", ">&-"}) {
        // (timeout: a viewer that served on would otherwise keep the test waiting)
        const std::string command = "cd '" + folder.path() + "' && timeout 60 '" + CLRENDER_BINARY + "' view '" +
                                    kDemoScene + "' --size 16x9 -q --no-browser --port 0 " + redirection +
                                    " 2>stderr.txt";
        const int status = std::system(command.c_str());
        ASSERT_TRUE(WIFEXITED(status)) << redirection;
        EXPECT_EQ(WEXITSTATUS(status), 4) << redirection << ": " << read_bytes(folder.file("stderr.txt"));
        const std::string message = read_bytes(folder.file("stderr.txt"));
        EXPECT_EQ(message.rfind("clrender: error: standard output: cannot write the viewer's address (", 0), 0u)
            << redirection << ": " << message;
        EXPECT_NE(message.find("; with --no-browser nothing else would show it\n"), std::string::npos) << message;
        EXPECT_EQ(std::count(message.begin(), message.end(), '\n'), 1) << message;
    }
}

}  // namespace
}  // namespace clr
