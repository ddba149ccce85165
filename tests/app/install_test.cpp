// `cmake --install` of this build tree into a fresh prefix, and the installed clrender used as a
// user would: from another folder, its --version, man page and bash completion
// (README.md, Install; docs/command-line.md, Version).
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <iterator>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "device/device_selection.h"
#include "device/opencl.h"
#include "scene/image_loader.h"
#include "support/shell.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using testing::read_bytes;
using testing::run_shell;
using testing::shell_quoted;
using testing::TempFolder;

const char* kSmallScene = R"({
  "eye": [0, 0, 6], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60,
  "width": 40, "height": 30, "DefaultColor": [0.1, 0.1, 0.1],
  "spheres": [{"type": "sphere", "center": [0, 0, 0], "radius": 1.5, "ambient": [1, 0, 0]}],
  "billboards": [{"type": "billboard", "UpperLeft": [-8, 6, -2], "LowerLeft": [-8, -6, -2],
                  "UpperRight": [8, 6, -2], "ambient": [0, 0, 1]}]
})";

bool is_executable(const fs::path& path) {
    struct stat info {};
    return ::stat(path.c_str(), &info) == 0 && S_ISREG(info.st_mode) && (info.st_mode & S_IXUSR);
}

bool have_program(const std::string& name) { return run_shell("command -v " + name + " >/dev/null").exit_code == 0; }

// Each test installs the build tree into a prefix of its own, and works in a folder that is
// neither the source nor the build tree.
class Install : public ::testing::Test {
protected:
    void SetUp() override {
        const testing::CommandResult install =
            run_shell(shell_quoted(CLRENDER_CMAKE) + " --install " + shell_quoted(CLRENDER_BUILD_DIR) + " --prefix " +
                      shell_quoted(prefix_.path()));
        ASSERT_EQ(install.exit_code, 0) << install.output;
    }

    std::string installed(const std::string& relative) const { return prefix_.file(relative); }

    // The installed clrender run in the work folder, with the tests' program cache.
    testing::CommandResult run_installed(const std::string& arguments, const std::string& environment = "") const {
        return run_shell("cd " + shell_quoted(work_.path()) + " && CLRENDER_CACHE_DIR=" +
                         shell_quoted(CLRENDER_TEST_CACHE_DIR) + " " + environment + " " +
                         shell_quoted(installed("bin/clrender")) + " " + arguments);
    }

    TempFolder prefix_;
    TempFolder work_;
};

TEST_F(Install, PutsTheProgramsDocsSchemaAndLicenceUnderThePrefix) {
    EXPECT_TRUE(is_executable(installed("bin/clrender")));
    EXPECT_TRUE(is_executable(installed("bin/clrender_make_forest")));
    EXPECT_TRUE(fs::is_regular_file(installed("share/bash-completion/completions/clrender")));
    const fs::path source = CLRENDER_SOURCE_DIR;
    EXPECT_EQ(read_bytes(installed("share/clrender/scene.schema.json")), read_bytes(source / "docs/scene.schema.json"));
    EXPECT_EQ(read_bytes(installed("share/doc/clrender/LICENSE")), read_bytes(source / "LICENSE"));
    EXPECT_EQ(read_bytes(installed("share/doc/clrender/README.md")), read_bytes(source / "README.md"));
    int documents = 0;
    for (const auto& entry : fs::directory_iterator(source / "docs")) {
        if (entry.path().extension() != ".md") continue;
        ++documents;
        const std::string name = entry.path().filename().string();
        EXPECT_EQ(read_bytes(installed("share/doc/clrender/docs/" + name)), read_bytes(entry.path())) << name;
    }
    EXPECT_GE(documents, 5);
    // The forest generator runs from the prefix too (it draws everything in code).
    const auto forest = run_shell(shell_quoted(installed("bin/clrender_make_forest")) + " --help");
    EXPECT_EQ(forest.exit_code, 0) << forest.output;
}

TEST_F(Install, InstalledBinaryRendersInAnotherFolder) {
    work_.write("small.json", kSmallScene);
    const auto result = run_installed("small.json -q");
    ASSERT_EQ(result.exit_code, 0) << result.output;
    auto image = load_image(work_.file("small.png"));
    ASSERT_TRUE(image);
    EXPECT_EQ(image->width, 40);
    EXPECT_EQ(image->height, 30);
    // Centre: the red sphere; corner: the blue billboard behind it.
    EXPECT_EQ(image->at(20, 15, 0), 255);
    EXPECT_EQ(image->at(20, 15, 2), 0);
    EXPECT_EQ(image->at(0, 0, 2), 255);
}

// The commit that `git describe` output names, resolved by git itself; empty when it names none.
std::string resolve_commit(const std::string& described) {
    const auto result = run_shell("git -C " + shell_quoted(CLRENDER_SOURCE_DIR) + " rev-parse --verify -q " +
                                  shell_quoted(described + "^{commit}"));
    return result.exit_code == 0 ? result.output : "";
}

bool source_is_a_git_checkout() {
    const auto result = run_shell("cd " + shell_quoted(CLRENDER_SOURCE_DIR) + " && git rev-parse --show-toplevel");
    return result.exit_code == 0 &&
           fs::equivalent(fs::path(result.output.substr(0, result.output.find('\n'))), CLRENDER_SOURCE_DIR);
}

// The program store built with the build tree is installed beside the binary, which finds it
// there: a first run with an empty cache builds nothing from source.
TEST_F(Install, InstalledBinaryFindsItsProgramStore) {
    const fs::path built = fs::path(CLRENDER_BUILD_DIR) / "share/clrender/programs";
    if (!fs::is_directory(built)) GTEST_SKIP() << "built with CLRENDER_PROGRAM_STORE_VARIANTS=none: no store";
    int entries = 0;
    for (const auto& entry : fs::directory_iterator(built)) {
        if (entry.path().extension() != ".clbin") continue;
        ++entries;
        EXPECT_EQ(read_bytes(installed("share/clrender/programs/" + entry.path().filename().string())),
                  read_bytes(entry.path()));
    }
    ASSERT_GT(entries, 0) << "the build's program store is empty (no OpenCL device when it was built?)";
    work_.write("small.json", kSmallScene);
    const auto result = run_installed("small.json -q --stats stats.json",
                                      "CLRENDER_CACHE_DIR=" + shell_quoted(work_.file("cache")) +
                                          " env -u CLRENDER_PROGRAM_STORE");
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_NE(read_bytes(work_.file("stats.json")).find("\"store_hits\": 1"), std::string::npos)
        << read_bytes(work_.file("stats.json"));
}

TEST_F(Install, VersionNamesTheBuildsCommitAndTheOpenCLPlatforms) {
    const auto result = run_installed("--version");
    ASSERT_EQ(result.exit_code, 0) << result.output;
    std::istringstream lines(result.output);
    std::string line;
    std::getline(lines, line);
    EXPECT_EQ(line, std::string("clrender ") + CLRENDER_VERSION);

    std::getline(lines, line);
    std::smatch match;
    ASSERT_TRUE(std::regex_match(line, match, std::regex("commit: (\\S+)"))) << line;
    std::string commit = match[1];
    if (source_is_a_git_checkout()) {
        const std::string dirty = "-dirty";
        if (commit.size() > dirty.size() && commit.compare(commit.size() - dirty.size(), dirty.size(), dirty) == 0)
            commit.resize(commit.size() - dirty.size());
        const auto head = run_shell("git -C " + shell_quoted(CLRENDER_SOURCE_DIR) + " rev-parse HEAD");
        EXPECT_EQ(resolve_commit(commit), head.output)
            << "--version's commit " << commit << " is not HEAD (a commit made since the last build?)";
    } else {
        EXPECT_EQ(commit, "unknown");
    }

    // The platforms the OpenCL loader gives this test, one line each, by name.
    std::vector<cl::Platform> platforms;
    try {
        cl::Platform::get(&platforms);
    } catch (const cl::Error&) {
    }
    std::string rest((std::istreambuf_iterator<char>(lines)), std::istreambuf_iterator<char>());
    if (platforms.empty()) {
        EXPECT_EQ(rest, "OpenCL platforms: none\n");
    } else {
        EXPECT_EQ(rest.rfind("OpenCL platforms:\n", 0), 0u) << rest;
        for (const cl::Platform& platform : platforms) {
            std::string name = platform.getInfo<CL_PLATFORM_NAME>();
            while (!name.empty() && name.back() == '\0') name.pop_back();
            EXPECT_NE(rest.find("\n  " + name + " (OpenCL "), std::string::npos) << name << " missing from:\n" << rest;
        }
    }
}

TEST_F(Install, VersionSaysNoneWithoutAnOpenCLDriver) {
    // OCL_ICD_VENDORS names the folder the ICD loader reads drivers from: an empty one.
    const auto result = run_installed("--version", "OCL_ICD_VENDORS=" + shell_quoted(work_.path()));
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find("\nOpenCL platforms: none\n"), std::string::npos) << result.output;
}

TEST(VersionCommit, IsUnknownOutsideAGitCheckoutEvenInsideAnotherRepository) {
    if (!have_program("git")) GTEST_SKIP() << "git is not installed";
    TempFolder folder;
    const std::string script = std::string(CLRENDER_SOURCE_DIR) + "/cmake/write_version.cmake";
    // The commit cmake/write_version.cmake writes for the tree `source`.
    auto commit_for = [&](const std::string& source) {
        const std::string output = folder.file("build_commit.cpp");
        const auto result = run_shell(shell_quoted(CLRENDER_CMAKE) + " -DSOURCE_DIR=" + shell_quoted(source) +
                                      " -DOUTPUT=" + shell_quoted(output) + " -P " + shell_quoted(script));
        EXPECT_EQ(result.exit_code, 0) << result.output;
        std::smatch match;
        const std::string text = read_bytes(output);
        return std::regex_search(text, match, std::regex("return \"([^\"]*)\";")) ? std::string(match[1]) : "?";
    };
    fs::create_directories(folder.file("tarball"));
    EXPECT_EQ(commit_for(folder.file("tarball")), "unknown");

    // An unpacked tarball inside someone's repository: not that repository's commit.
    const std::string repository = folder.file("repository");
    fs::create_directories(repository + "/clrender-0.1.0");
    const auto made = run_shell("cd " + shell_quoted(repository) +
                                " && git init -q && git -c user.name=t -c user.email=t@t commit -q --allow-empty -m x"
                                " && git rev-parse HEAD");
    ASSERT_EQ(made.exit_code, 0) << made.output;
    EXPECT_EQ(commit_for(repository + "/clrender-0.1.0"), "unknown");
    // The repository itself is a checkout: its commit, abbreviated.
    const std::string commit = commit_for(repository);
    EXPECT_FALSE(commit.empty());
    EXPECT_EQ(made.output.rfind(commit, 0), 0u) << commit << " is not a prefix of " << made.output;
}

TEST_F(Install, ManPageRendersWithEveryOptionAndSection) {
    if (!CLRENDER_HAVE_MAN_PAGE) GTEST_SKIP() << "built without help2man: no man page to install";
    const std::string page = installed("share/man/man1/clrender.1");
    ASSERT_TRUE(fs::is_regular_file(page));
    std::string render;
    if (have_program("man"))
        render = "MANWIDTH=500 MANPAGER=cat man --warnings -l " + shell_quoted(page);
    else if (have_program("groff"))
        render = "groff -man -Tutf8 -ww -rLL=500n " + shell_quoted(page) + " | col -b";
    else
        GTEST_SKIP() << "neither man nor groff is installed: the man page was not rendered";
    const auto warnings = run_shell(render + " 2>&1 >/dev/null");
    EXPECT_EQ(warnings.output, "") << "the formatter warned";
    const auto result = run_shell(render + " 2>/dev/null");
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find(std::string("\nclrender ") + CLRENDER_VERSION + " "), std::string::npos)
        << "the page's footer names no version";
    for (const char* section : {"NAME", "SYNOPSIS", "OPTIONS", "ENVIRONMENT", "EXIT STATUS", "EXAMPLES", "SEE ALSO"})
        EXPECT_NE(result.output.find(std::string("\n") + section + "\n"), std::string::npos) << section;
    // Every long option the program knows, as an entry of its own: its name (after its short
    // one, "-o,--output") and its value's type alone on a line, the description below.
    const auto words = run_installed("--completion-words");
    ASSERT_EQ(words.exit_code, 0);
    std::istringstream lines(words.output);
    std::string short_name;
    int entries = 0;
    for (std::string line; std::getline(lines, line);) {
        if (line.rfind("--", 0) != 0) {
            short_name = line.substr(0, line.find(' ')) + ",";
            continue;
        }
        const std::string& entry = line;
        const bool found = result.output.find("\n       " + entry + "\n") != std::string::npos ||
                           result.output.find("\n       " + short_name + entry + "\n") != std::string::npos;
        EXPECT_TRUE(found) << "'" << entry << "' has no entry of its own";
        entries += found;
        short_name.clear();
    }
    EXPECT_GE(entries, 15);
}

// The README's build commands name targets this build has, and one of them builds only the
// program: a user who follows it gets build/clrender without the tests.
TEST(ReadmeBuild, NamesTheProgramsTargetAndOnlyTargetsThatExist) {
    const std::string readme = read_bytes(fs::path(CLRENDER_SOURCE_DIR) / "README.md");
    EXPECT_NE(readme.find("cmake --build build -j2 --target clrender "), std::string::npos)
        << "the README does not say how to build only the program";
    const auto help = run_shell(shell_quoted(CLRENDER_CMAKE) + " --build " + shell_quoted(CLRENDER_BUILD_DIR) + " --target help");
    ASSERT_EQ(help.exit_code, 0) << help.output;
    const std::regex target(R"(--target ([A-Za-z0-9_]+))");
    int named = 0;
    for (auto match = std::sregex_iterator(readme.begin(), readme.end(), target); match != std::sregex_iterator(); ++match) {
        ++named;
        EXPECT_NE(help.output.find("... " + (*match)[1].str() + "\n"), std::string::npos)
            << "README.md names target " << (*match)[1] << ", which the build does not have";
    }
    EXPECT_GE(named, 1);
}

// Runs the installed completion in bash for the words of a command line (the last is the one
// being completed) in the work folder; returns the candidates, one per line, sorted.
std::string complete(const std::string& prefix, const std::string& folder, const std::vector<std::string>& words) {
    std::string array;
    for (const std::string& word : words) array += " " + shell_quoted(word);
    const std::string script = "source " + shell_quoted(prefix + "/share/bash-completion/completions/clrender") +
                               "\nCOMP_WORDS=(" + array + ")\nCOMP_CWORD=$((${#COMP_WORDS[@]} - 1))\n_clrender\n" +
                               "printf '%s\\n' \"${COMPREPLY[@]}\" | sort | sed '/^$/d'\n";
    const auto result = run_shell("cd " + shell_quoted(folder) + " && PATH=" + shell_quoted(prefix + "/bin") +
                                  ":\"$PATH\" bash -c " + shell_quoted(script));
    return result.exit_code == 0 ? result.output : "bash failed: " + result.output;
}

TEST_F(Install, CompletionIsValidBashAndCompletesOptionsValuesAndScenes) {
    const std::string file = installed("share/bash-completion/completions/clrender");
    const auto syntax = run_shell("bash -n " + shell_quoted(file));
    EXPECT_EQ(syntax.exit_code, 0) << syntax.output;

    const std::string prefix = prefix_.path();
    const std::string binary = installed("bin/clrender");
    EXPECT_EQ(complete(prefix, work_.path(), {"clrender", "--prec"}), "--precision\n");  // from PATH
    EXPECT_EQ(complete(prefix, work_.path(), {binary, "--prec"}), "--precision\n");      // as typed
    EXPECT_EQ(complete(prefix, work_.path(), {"clrender", "--precision", ""}), "double\nfloat\n");
    EXPECT_EQ(complete(prefix, work_.path(), {"clrender", "--precision", "d"}), "double\n");
    EXPECT_EQ(complete(prefix, work_.path(), {"clrender", "--precision", "=", "f"}), "float\n");
    EXPECT_EQ(complete(prefix, work_.path(), {"clrender", "--spp", ""}), "");

    // Every option the program lists completes from a bare '-'.
    const auto words = run_installed("--completion-words");
    std::istringstream lines(words.output);
    std::vector<std::string> names;
    for (std::string line; std::getline(lines, line);) names.push_back(line.substr(0, line.find(' ')));
    std::string expected;
    for (const std::string& name : names) expected += name + "\n";
    EXPECT_NE(std::count(expected.begin(), expected.end(), '\n'), 0);
    const auto sorted = run_shell("printf '%s' " + shell_quoted(expected) + " | sort");
    EXPECT_EQ(complete(prefix, work_.path(), {"clrender", "-"}), sorted.output);

    // Scenes and folders where no option wants a value; any file after -o.
    work_.write("a.json", "{}");
    work_.write("b.js", "");
    work_.write("notes.txt", "");
    fs::create_directory(work_.file("sub"));
    EXPECT_EQ(complete(prefix, work_.path(), {"clrender", ""}), "a.json\nb.js\nsub\n");
    EXPECT_EQ(complete(prefix, work_.path(), {"clrender", "a.json", "-o", "n"}), "notes.txt\n");
}

// -d completes what it takes: the kinds, and each device's index and platform:device as the
// program lists them.
TEST_F(Install, CompletionOffersDeviceSelectorsAfterDashD) {
    const std::string prefix = prefix_.path();
    const std::string all = "\n" + complete(prefix, work_.path(), {"clrender", "-d", ""});
    EXPECT_NE(all.find("\ncpu\n"), std::string::npos) << all;
    EXPECT_NE(all.find("\ngpu\n"), std::string::npos) << all;
    const std::vector<DeviceEntry> devices = list_devices();
    ASSERT_FALSE(devices.empty()) << "the tests need a device (PoCL)";
    for (const DeviceEntry& entry : devices) {
        EXPECT_NE(all.find("\n" + std::to_string(entry.index) + "\n"), std::string::npos) << all;
        EXPECT_NE(all.find("\n" + std::to_string(entry.platform_index) + ":" + std::to_string(entry.device_index) + "\n"),
                  std::string::npos)
            << all;
    }
    EXPECT_EQ(complete(prefix, work_.path(), {"clrender", "--device", "cp"}), "cpu\n");
    EXPECT_EQ(complete(prefix, work_.path(), {"clrender", "--device", "=", "0:"}), "0:0\n");
    // A device's name completes too, quoted for the shell.
    const std::string& name = devices.front().device_name;
    const std::string named = complete(prefix, work_.path(), {"clrender", "-d", name.substr(0, 3)});
    const auto quoted = run_shell("bash -c " + shell_quoted("printf '%q' " + shell_quoted(name)));
    EXPECT_NE(named.find(quoted.output + "\n"), std::string::npos) << named;
}

}  // namespace
}  // namespace clr
