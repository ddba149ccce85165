// The program sources: kernel files name what they use with #include, which clrender resolves
// itself (each file once, compiler messages naming the real file and line), and each program
// holds only its own kernels.
#include "device/kernel_sources.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "core/errors.h"
#include "render/feature_set.h"
#include "support/opencl_test_device.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using testing::TempFolder;

int count_of(const std::string& text, const std::string& part) {
    int count = 0;
    for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++count;
    return count;
}

// A kernel folder: programs/entry.cl includes common/a.cl twice and common/b.cl, which
// includes common/a.cl again.
void write_kernel_folder(const TempFolder& folder, const std::string& entry_body) {
    fs::create_directories(folder.file("programs"));
    fs::create_directories(folder.file("common"));
    folder.write("common/a.cl", "/* a */\nint from_a(void) { return 1; }\n");
    folder.write("common/b.cl", "#include \"common/a.cl\"\nint from_b(void) { return from_a() + 1; }\n");
    folder.write("programs/entry.cl", entry_body);
}

TEST(KernelSources, EachFileGoesInOnceAtItsFirstInclude) {
    TempFolder folder;
    write_kernel_folder(folder, "#include \"common/a.cl\"\n  #  include \"common/b.cl\"\n#include \"common/a.cl\"\n"
                                "__kernel void k(__global int* out) { *out = from_b(); }\n");
    const std::string source = assemble_program_source("programs/entry.cl", folder.path());
    EXPECT_EQ(count_of(source, "int from_a(void)"), 1) << source;
    EXPECT_EQ(count_of(source, "int from_b(void)"), 1) << source;
    EXPECT_EQ(count_of(source, "#include"), 0) << source;
    EXPECT_LT(source.find("int from_a(void)"), source.find("int from_b(void)")) << "a comes first: " << source;
    EXPECT_NE(source.find("#line 1 \"kernels/common/b.cl\""), std::string::npos) << source;
    // Back in the entry after b.cl (included on its line 2): line 3 onwards.
    EXPECT_NE(source.find("#line 3 \"kernels/programs/entry.cl\""), std::string::npos) << source;
}

TEST(KernelSources, AnIncludeOfNoFileIsADeviceErrorNamingIt) {
    TempFolder folder;
    write_kernel_folder(folder, "#include \"common/a.cl\"\n#include \"common/missing.cl\"\n");
    try {
        assemble_program_source("programs/entry.cl", folder.path());
        FAIL() << "no error";
    } catch (const DeviceError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("kernels/programs/entry.cl:2"), std::string::npos) << message;
        EXPECT_NE(message.find("\"common/missing.cl\""), std::string::npos) << message;
    }
    // The embedded files follow the same rule.
    EXPECT_THROW(assemble_program_source("programs/no_such_program.cl"), DeviceError);
}

TEST(KernelSources, CompilerMessagesNameTheRealFileAndLine) {
    TempFolder folder;
    write_kernel_folder(folder, "#include \"common/b.cl\"\n"
                                "__kernel void k(__global int* out) { *out = from_b(); }\n"
                                "__kernel void broken(__global int* out) { *out = not_declared_in_entry; }\n");
    folder.write("common/a.cl", "/* a */\n\nint from_a(void) { return not_declared_in_a; }\n");
    const std::string source = assemble_program_source("programs/entry.cl", folder.path());
    try {
        testing::test_device().build_program(source, "");
        FAIL() << "the program built";
    } catch (const DeviceError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("kernels/common/a.cl:3"), std::string::npos) << message;
        EXPECT_NE(message.find("kernels/programs/entry.cl:3"), std::string::npos) << message;
    }
}

// The command line's program holds render_packets alone, so that building it (and asking
// the driver for its binary) compiles nothing else; the others hold what their users run.
TEST(KernelSources, EachProgramHoldsOnlyItsKernels) {
    struct Expected {
        KernelProgram program;
        std::string kernels;  // CL_PROGRAM_KERNEL_NAMES, sorted
    };
    for (const Expected& expected : {Expected{kRenderTilesProgram, "render_packets"},
                                     Expected{kRenderBruteForceProgram, "render"},
                                     Expected{kTestStagesProgram, "intersect;raygen;shade;struct_layout"}}) {
        cl::Program program = testing::test_device().build_program(assemble_program_source(expected.program.entry),
                                                                   FeatureSet::all().build_options());
        std::vector<cl::Kernel> kernels;
        program.createKernels(&kernels);
        std::vector<std::string> names;
        for (const cl::Kernel& kernel : kernels) names.push_back(kernel.getInfo<CL_KERNEL_FUNCTION_NAME>());
        std::sort(names.begin(), names.end());
        std::string joined;
        for (const std::string& name : names) joined += (joined.empty() ? "" : ";") + name;
        EXPECT_EQ(joined, expected.kernels) << expected.program.entry;
    }
}

}  // namespace
}  // namespace clr
