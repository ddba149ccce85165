// code_file_identity() names the build that holds a function, for the caches' keys.
#include "core/code_file.h"

#include <dlfcn.h>
#include <errno.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstring>
#include <filesystem>
#include <string>

namespace clr {
namespace {

void a_function_of_the_main_program() {}

// The main program as the system names it after a start through PATH: its bare name
// (`clrender` run from a shell), whose bytes stand in argv[0] in place of the name it had.
class StartedByBareName {
public:
    StartedByBareName() : saved_(program_invocation_name) {
        const std::string bare = std::filesystem::path(saved_).filename().string();
        std::memcpy(program_invocation_name, bare.c_str(), bare.size() + 1);
    }
    ~StartedByBareName() { std::memcpy(program_invocation_name, saved_.c_str(), saved_.size() + 1); }
    StartedByBareName(const StartedByBareName&) = delete;
    StartedByBareName& operator=(const StartedByBareName&) = delete;

private:
    std::string saved_;
};

TEST(CodeFile, TheMainProgramIsTheFileThatRunsWhateverNameStartedIt) {
    const void* function = reinterpret_cast<const void*>(&a_function_of_the_main_program);
    const std::string identity = code_file_identity(function);
    struct stat running;
    ASSERT_EQ(::stat("/proc/self/exe", &running), 0);
    const std::string path = std::filesystem::read_symlink("/proc/self/exe").string();
    EXPECT_EQ(identity, path + " " + std::to_string(running.st_size) + " " + std::to_string(running.st_mtim.tv_sec) +
                            "." + std::to_string(running.st_mtim.tv_nsec));

    // Every build started as `clrender` through PATH had the same key ("clrender", looked up in
    // the working folder), so that a new build read the mesh and image cache entries of the old.
    std::string by_bare_name;
    {
        const StartedByBareName bare;
        by_bare_name = code_file_identity(function);
    }
    EXPECT_EQ(by_bare_name, identity);
}

TEST(CodeFile, ALibraryIsItsOwnFile) {
    const void* function = ::dlsym(RTLD_DEFAULT, "getpid");
    ASSERT_NE(function, nullptr);
    const std::string identity = code_file_identity(function);
    EXPECT_NE(identity.find("libc"), std::string::npos) << identity;
    EXPECT_NE(identity, code_file_identity(reinterpret_cast<const void*>(&a_function_of_the_main_program)));
}

}  // namespace
}  // namespace clr
