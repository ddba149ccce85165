// The OpenCL driver under the process's limits, through the real binary with cold caches: an
// address-space limit (ulimit -v) ends every run in success or out of memory (exit 6), never a
// signal death or a hang; a signal during a cold build ends the run within a second; too few file
// descriptors and a PoCL cache folder that cannot be written are named, not passed off as a
// missing driver.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "support/command.h"
#include "support/small_disk.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using testing::read_bytes;
using testing::run_clrender;
using testing::TempFolder;

const char* kScene = R"({
  "eye": [0, 0, 6], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60,
  "width": 40, "height": 30, "DefaultColor": [0.1, 0.1, 0.1],
  "spheres": [{"type": "sphere", "center": [0, 0, 0], "radius": 1.5, "ambient": [1, 0, 0]}]
})";

// Empty caches of clrender's and PoCL's own in the test's folder: every run builds cold.
std::string cold_caches(const TempFolder& folder, const std::string& name) {
    fs::create_directories(folder.file(name + "/clrender"));
    fs::create_directories(folder.file(name + "/pocl"));
    return "CLRENDER_CACHE_DIR='" + folder.file(name + "/clrender") + "' POCL_CACHE_DIR='" + folder.file(name + "/pocl") +
           "' ";
}

// AddressSanitizer reserves terabytes of address space for its shadow memory (a sanitized
// clrender cannot start under `ulimit -v`), reports the driver's faults itself instead of
// clrender's diagnosis, and slows the run: the limits are checked in the plain build.
#ifdef __SANITIZE_ADDRESS__
#define SKIP_UNDER_ADDRESS_SANITIZER() GTEST_SKIP() << "process limits are checked without AddressSanitizer"
#else
#define SKIP_UNDER_ADDRESS_SANITIZER() (void)0
#endif

int count_lines_with(const std::string& text, const std::string& fragment) {
    int count = 0;
    for (std::size_t at = text.find(fragment); at != std::string::npos; at = text.find(fragment, at + 1)) ++count;
    return count;
}

// From too little address space for the driver to start to enough for a build, in steps: PoCL
// 3.1 found no device, hung on a lock of its own, aborted or faulted across this range.
TEST(DriverLimits, AnAddressSpaceLimitEndsInSuccessOrOutOfMemory) {
    SKIP_UNDER_ADDRESS_SANITIZER();
    TempFolder folder;
    folder.write("scene.json", kScene);
    int successes = 0, refusals = 0;
    for (int kib = 300000; kib <= 1500000; kib += 200000) {
        const std::string name = "limit" + std::to_string(kib);
        // timeout: a hang is exit 137, a signal death 128 + the signal; either fails below.
        const std::string wrapper = cold_caches(folder, name) + "timeout -s KILL 120 bash -c 'ulimit -v " +
                                    std::to_string(kib) + " && exec \"$0\" \"$@\"'";
        const testing::CommandResult result = run_clrender("scene.json -q -o " + name + ".png", folder.path(), wrapper);
        if (result.exit_code == 0) {
            ++successes;
            EXPECT_TRUE(fs::exists(folder.file(name + ".png"))) << kib;
            continue;
        }
        ++refusals;
        ASSERT_EQ(result.exit_code, 6) << "ulimit -v " << kib << ": " << result.output;
        EXPECT_EQ(count_lines_with(result.output, "clrender: error: out of memory"), 1) << kib << ": " << result.output;
        EXPECT_NE(result.output.find("ulimit -v " + std::to_string(kib)), std::string::npos) << result.output;
        EXPECT_FALSE(fs::exists(folder.file(name + ".png"))) << kib;
    }
    EXPECT_GT(refusals, 0) << "300000 KiB is too little for the driver to start";
    EXPECT_GT(successes, 0) << "1500000 KiB is enough for a cold build";
}

// Kernel sources whose build takes the compiler many seconds: the embedded kernels with a kernel
// of 1024 inlined sines added to each program.
std::string slow_kernels(const TempFolder& folder) {
    const std::string kernels = folder.file("slow-kernels");
    fs::copy(std::string(CLRENDER_SOURCE_DIR) + "/kernels", kernels, fs::copy_options::recursive);
    std::string slow = "\n#define CLR_SLOW0(x) x = sin(x * 1.0001f + 0.5f);\n";
    for (int level = 1; level <= 10; ++level)
        slow += "#define CLR_SLOW" + std::to_string(level) + "(x) CLR_SLOW" + std::to_string(level - 1) + "(x) CLR_SLOW" +
                std::to_string(level - 1) + "(x)\n";
    slow += "__kernel void clr_slow_to_build(__global float* v) { float x = v[0]; CLR_SLOW10(x) v[0] = x; }\n";
    for (const auto& program : fs::directory_iterator(kernels + "/programs")) {
        const std::string text = read_bytes(program.path());
        folder.write(fs::relative(program.path(), folder.path()).string(), text + slow);
    }
    return kernels;
}

// SIGTERM or SIGINT a second into a cold build that takes many seconds: before the watchdog,
// clrender waited for the build (and, short of memory, forever).
void expect_signal_ends_a_cold_build_within_a_second(const std::string& signal_name, int expected_code) {
    TempFolder folder;
    folder.write("scene.json", kScene);
    const std::string kernels = slow_kernels(folder);
    folder.write("interrupt.sh", cold_caches(folder, "caches") + "'" + CLRENDER_BINARY +
                                     "' scene.json -q -o out.png --kernel-dir '" + kernels +
                                     "' 2> stderr.txt &\n"
                                     "pid=$!\n"
                                     // The guard's sleep must not hold the test's output
                                     // open: CTest would wait the full minute for it.
                                     "( sleep 60; kill -KILL $pid 2>/dev/null ) </dev/null >/dev/null 2>&1 &\n"
                                     "guard=$!\n"
                                     "sleep 1\n"
                                     "start=$(date +%s%N)\n"
                                     "kill -" + signal_name + " $pid\n"
                                     "wait $pid\n"
                                     "code=$?\n"
                                     "end=$(date +%s%N)\n"
                                     "kill $guard 2>/dev/null\n"
                                     "echo $code $(( (end - start) / 1000000 )) > result.txt\n");
    ASSERT_EQ(std::system(("cd '" + folder.path() + "' && bash interrupt.sh").c_str()), 0);
    int code = -1, milliseconds = -1;
    std::sscanf(read_bytes(folder.file("result.txt")).c_str(), "%d %d", &code, &milliseconds);
    const std::string stderr_text = read_bytes(folder.file("stderr.txt"));
    EXPECT_EQ(code, expected_code) << stderr_text;
    EXPECT_LT(milliseconds, 1000) << "the signal must end a cold build within a second";
    EXPECT_EQ(count_lines_with(stderr_text, "clrender: error: interrupted by " + std::string(signal_name == "INT" ? "SIGINT" : "SIGTERM")), 1)
        << stderr_text;
    EXPECT_FALSE(fs::exists(folder.file("out.png")));
}

TEST(DriverLimits, SigtermEndsAColdBuildWithinASecond) {
    SKIP_UNDER_ADDRESS_SANITIZER();
    expect_signal_ends_a_cold_build_within_a_second("TERM", 143);
}

TEST(DriverLimits, SigintEndsAColdBuildWithinASecond) {
    SKIP_UNDER_ADDRESS_SANITIZER();
    expect_signal_ends_a_cold_build_within_a_second("INT", 130);
}

// PoCL 3.1's linker aborted (SIGABRT) with `ulimit -n` 7 to 14 on a cold build.
TEST(DriverLimits, TooFewFileDescriptorsAreNamed) {
    SKIP_UNDER_ADDRESS_SANITIZER();
    TempFolder folder;
    folder.write("scene.json", kScene);
    const std::string wrapper = cold_caches(folder, "caches") + "timeout -s KILL 120 bash -c 'ulimit -n 10 && exec \"$0\" \"$@\"'";
    const testing::CommandResult result = run_clrender("scene.json -q -o out.png", folder.path(), wrapper);
    ASSERT_EQ(result.exit_code, 3) << result.output;
    EXPECT_EQ(count_lines_with(result.output, "clrender: error:"), 1) << result.output;
    EXPECT_NE(result.output.find("too few file descriptors: the limit is 10 (ulimit -n)"), std::string::npos) << result.output;
    EXPECT_EQ(result.output.find("install an OpenCL driver"), std::string::npos) << result.output;
    EXPECT_FALSE(fs::exists(folder.file("out.png")));
}

// A soft limit below the hard one is raised for the driver: the run succeeds.
TEST(DriverLimits, ASoftDescriptorLimitIsRaisedForTheDriver) {
    SKIP_UNDER_ADDRESS_SANITIZER();
    TempFolder folder;
    folder.write("scene.json", kScene);
    const std::string wrapper = cold_caches(folder, "caches") + "timeout -s KILL 120 bash -c 'ulimit -Sn 10 && exec \"$0\" \"$@\"'";
    const testing::CommandResult result = run_clrender("scene.json -q -o out.png", folder.path(), wrapper);
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_TRUE(fs::exists(folder.file("out.png")));
}

void expect_pocl_cache_named(const testing::CommandResult& result, const std::string& cache, const TempFolder& folder) {
    ASSERT_EQ(result.exit_code, 3) << result.output;
    EXPECT_EQ(count_lines_with(result.output, "clrender: error:"), 1) << result.output;
    EXPECT_NE(result.output.find("PoCL's kernel cache folder '" + cache + "' cannot be written"), std::string::npos)
        << result.output;
    EXPECT_EQ(result.output.find("install an OpenCL driver"), std::string::npos) << result.output;
    EXPECT_FALSE(fs::exists(folder.file("out.png")));
}

// POCL_CACHE_DIR naming a file: PoCL failed the build ("failed to build the program").
TEST(DriverLimits, APoclCacheFolderThatIsAFileIsNamed) {
    TempFolder folder;
    folder.write("scene.json", kScene);
    const std::string cache = folder.write("not-a-folder", "x");
    const testing::CommandResult result =
        run_clrender("scene.json -q -o out.png", folder.path(), "CLRENDER_CACHE_DIR=off POCL_KERNEL_CACHE=1 POCL_CACHE_DIR='" + cache + "'");
    expect_pocl_cache_named(result, cache, folder);
}

// The whole cache folder ($XDG_CACHE_HOME, PoCL's and clrender's) on a read-only file system:
// PoCL found no device, and clrender said to install a driver.
TEST(DriverLimits, AReadOnlyCacheFolderIsNamed) {
    if (!testing::can_mount_small_disks()) GTEST_SKIP() << "cannot mount a read-only tmpfs here (needs root or unshare -rm)";
    TempFolder folder;
    folder.write("scene.json", kScene);
    const std::string cache = folder.file("cache");
    fs::create_directories(cache);
    const std::string wrapper = "env -u POCL_CACHE_DIR -u CLRENDER_CACHE_DIR XDG_CACHE_HOME='" + cache +
                                "' unshare -rm sh -c 'mount -t tmpfs -o ro tmpfs \"$XDG_CACHE_HOME\" && exec \"$0\" \"$@\"'";
    const testing::CommandResult result = run_clrender("scene.json -q -o out.png", folder.path(), wrapper);
    expect_pocl_cache_named(result, cache + "/pocl", folder);
}

}  // namespace
}  // namespace clr
