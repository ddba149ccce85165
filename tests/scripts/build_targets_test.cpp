// What the README's two commands install and build: scripts/demo.sh only the packages and the
// targets it runs (clrender and the forest generator, no GoogleTest, no Embree), scripts/test.sh
// everything the tests need. The scripts run copied into a folder of their own, with apt-get,
// dpkg-query, sudo, cmake and ctest replaced by fakes that record how they were called (and a
// fake cmake that "builds" programs which record how they were run).
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "support/shell.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using testing::CommandResult;
using testing::read_bytes;
using testing::run_shell;
using testing::shell_quoted;
using testing::TempFolder;

// The fake cmake: `--build DIR` "builds" each --target as a program in DIR that appends its
// name and arguments to the log; configuring makes the build folder.
const char* kFakeCmake = R"(#!/bin/bash
echo "cmake $*" >> "$FAKE_LOG"
if [ "$1" = "--build" ]; then
  dir=$2; shift 2
  while [ $# -gt 0 ]; do
    if [ "$1" = "--target" ]; then
      printf '#!/bin/sh\necho "run %s $*" >> "$FAKE_LOG"\n' "$2" > "$dir/$2"; chmod +x "$dir/$2"; shift
    fi
    shift
  done
else
  while [ $# -gt 0 ]; do [ "$1" = "-B" ] && mkdir -p "$2"; shift; done
fi
)";

class BuildTargets : public ::testing::Test {
protected:
    void SetUp() override {
        fs::create_directories(folder.file("repo/scripts"));
        for (const char* script : {"demo.sh", "build.sh", "install-deps.sh", "test.sh", "name-retried-tests.sh"})
            fs::copy_file(std::string(CLRENDER_SOURCE_DIR) + "/scripts/" + script,
                          folder.file(std::string("repo/scripts/") + script));
        fs::create_directories(folder.file("bin"));
        fake("cmake", kFakeCmake);
        fake("ctest", "#!/bin/sh\necho \"ctest $*\" >> \"$FAKE_LOG\"\n");
        fake("dpkg-query", "#!/bin/sh\nexit 1\n");  // nothing is installed
        fake("apt-get", "#!/bin/sh\necho \"apt-get $*\" >> \"$FAKE_LOG\"\n");
        fake("sudo", "#!/bin/sh\nexec \"$@\"\n");
    }

    void fake(const std::string& name, const std::string& body) const {
        ::chmod(folder.write("bin/" + name, body).c_str(), 0755);
    }

    // Runs repo/scripts/`script` with the fakes first on PATH; returns the log's lines.
    std::vector<std::string> run(const std::string& script) const {
        const CommandResult result =
            run_shell("FAKE_LOG=" + shell_quoted(folder.file("log")) + " PATH=" + shell_quoted(folder.file("bin")) +
                      ":$PATH CLRENDER_BUILD_DIR=" + shell_quoted(build()) + " bash " +
                      shell_quoted(folder.file("repo/scripts/" + script)));
        EXPECT_EQ(result.exit_code, 0) << result.output;
        std::vector<std::string> lines;
        std::istringstream log(read_bytes(folder.file("log")));
        for (std::string line; std::getline(log, line);) lines.push_back(line);
        return lines;
    }

    std::string build() const { return folder.file("build"); }

    TempFolder folder;
};

// The one log line that starts with `start`.
std::string line_starting(const std::vector<std::string>& lines, const std::string& start) {
    std::string found;
    for (const std::string& line : lines) {
        if (line.rfind(start, 0) != 0) continue;
        EXPECT_TRUE(found.empty()) << "two lines start with " << start;
        found = line;
    }
    return found;
}

bool has_word(const std::string& line, const std::string& word) {
    return (" " + line + " ").find(" " + word + " ") != std::string::npos;
}

TEST_F(BuildTargets, DemoInstallsAndBuildsOnlyWhatItRuns) {
    const std::vector<std::string> log = run("demo.sh");
    const std::string install = line_starting(log, "apt-get install");
    for (const char* package : {"cmake", "pocl-opencl-icd", "ocl-icd-opencl-dev", "libopenexr-dev", "ffmpeg"})
        EXPECT_TRUE(has_word(install, package)) << package << " not in: " << install;
    // What the top-level CMakeLists.txt requires for clrender itself, as the Debian packages
    // that hold it (the view server and the OBJ reader are part of clrender): a fresh Debian 12
    // root once stopped at configure without the HTTP library.
    for (const char* package : {"nlohmann-json3-dev", "libcli11-dev", "libpng-dev", "libssl-dev", "libjpeg62-turbo-dev",
                                "libstb-dev", "libisal-dev", "libxxhash-dev", "libtinyobjloader-dev", "libcpp-httplib-dev",
                                "pkg-config"})
        EXPECT_TRUE(has_word(install, package)) << package << " not in: " << install;
    for (const char* package : {"googletest", "libgtest-dev", "libembree-dev", "povray", "clang", "oclgrind", "slurmd"})
        EXPECT_FALSE(has_word(install, package)) << package << " in: " << install;
    const std::string configure = line_starting(log, "cmake -S");
    EXPECT_TRUE(has_word(configure, "-DCLRENDER_BUILD_TESTS=OFF")) << configure;
    EXPECT_TRUE(has_word(configure, "-DCLRENDER_BUILD_BENCH=OFF")) << configure;
    const std::string built = line_starting(log, "cmake --build");
    EXPECT_NE(built.find(" --target clrender --target clrender_make_forest"), std::string::npos) << built;
    EXPECT_EQ(built.find("clrender_tests"), std::string::npos) << built;
    EXPECT_EQ(built.find("clrender_bench"), std::string::npos) << built;
    // Then it renders with what it built: the still, the forest, the forest's video.
    EXPECT_NE(line_starting(log, "run clrender_make_forest").find("out/forest"), std::string::npos);
    int renders = 0;
    for (const std::string& line : log) renders += line.rfind("run clrender ", 0) == 0;
    EXPECT_EQ(renders, 2);
}

// A build folder configured before (by the test command, say) keeps its test targets.
TEST_F(BuildTargets, DemoKeepsTheOptionsOfAnExistingBuildFolder) {
    fs::create_directories(build());
    std::ofstream(build() + "/CMakeCache.txt") << "CLRENDER_BUILD_TESTS:BOOL=ON\n";
    const std::string configure = line_starting(run("demo.sh"), "cmake -S");
    EXPECT_EQ(configure.find("CLRENDER_BUILD_TESTS"), std::string::npos) << configure;
    EXPECT_EQ(configure.find("CLRENDER_BUILD_BENCH"), std::string::npos) << configure;
}

TEST_F(BuildTargets, TestCommandInstallsEverythingAndBuildsTheTests) {
    const std::vector<std::string> log = run("test.sh");
    const std::string install = line_starting(log, "apt-get install");
    for (const char* package : {"cmake", "pocl-opencl-icd", "ffmpeg", "googletest", "libgtest-dev", "libembree-dev",
                                "povray", "help2man", "parallel"})
        EXPECT_TRUE(has_word(install, package)) << package << " not in: " << install;
    const std::string configure = line_starting(log, "cmake -S");
    EXPECT_TRUE(has_word(configure, "-DCLRENDER_BUILD_TESTS=ON")) << configure;
    EXPECT_TRUE(has_word(configure, "-DCLRENDER_BUILD_BENCH=ON")) << configure;
    const std::string built = line_starting(log, "cmake --build");
    EXPECT_TRUE(built.size() > 11 && built.substr(built.size() - 24) == " --target clrender_tests") << built;
    EXPECT_FALSE(line_starting(log, "ctest").empty());
}

TEST_F(BuildTargets, UnknownPackageSetIsRefused) {
    const CommandResult result = run_shell("bash " + shell_quoted(folder.file("repo/scripts/install-deps.sh")) + " tests");
    EXPECT_EQ(result.exit_code, 1) << result.output;
    EXPECT_NE(result.output.find("usage: install-deps.sh"), std::string::npos) << result.output;
}

}  // namespace
}  // namespace clr
