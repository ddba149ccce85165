// Every host-side kernel signature (render/kernel_signatures.h) must match the parameters the
// kernel declares, or arguments would bind to the wrong parameters and show only as wrong
// pixels. The program is built with -cl-kernel-arg-info so the device reports each kernel's
// parameter names, address qualifiers and type names.
#include <gtest/gtest.h>

#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "device/kernel_sources.h"
#include "render/feature_set.h"
#include "render/kernel_signatures.h"
#include "support/opencl_test_device.h"

namespace clr {
namespace {

// Every program clrender builds: the production one, the brute-force one, the tests' stages.
const std::vector<KernelProgram> kPrograms = {kRenderTilesProgram, kRenderBruteForceProgram, kTestStagesProgram};

// Built from source (never from the program cache: a binary need not carry argument info).
cl::Program program_with_arg_info(const KernelProgram& entry) {
    auto& device = testing::test_device();
    cl::Program program(device.context(), assemble_program_source(entry.entry));
    program.build({device.device()}, (FeatureSet::all().build_options() + " -cl-kernel-arg-info").c_str());
    return program;
}

const std::vector<cl::Program>& programs() {
    static const std::vector<cl::Program> built = [] {
        std::vector<cl::Program> list;
        for (const KernelProgram& entry : kPrograms) list.push_back(program_with_arg_info(entry));
        return list;
    }();
    return built;
}

// The kernel names of `program`.
std::set<std::string> kernel_names(const cl::Program& program) {
    std::istringstream names(program.getInfo<CL_PROGRAM_KERNEL_NAMES>());
    std::set<std::string> in_program;
    for (std::string name; std::getline(names, name, ';');)
        if (!name.empty()) in_program.insert(name.c_str());  // c_str(): drop a trailing terminator
    return in_program;
}

// The kernel `name` from whichever program holds it.
cl::Kernel kernel_named(const std::string& name) {
    for (const cl::Program& program : programs())
        if (kernel_names(program).count(name)) return cl::Kernel(program, name.c_str());
    ADD_FAILURE() << "no program holds kernel " << name;
    return cl::Kernel();
}

// "name: global pointer" or "name: private int", as the host declares a parameter.
std::string describe(const KernelParam& param) {
    return param.name + ": " + (param.global_buffer ? "global pointer" : "private " + param.type_name);
}

// The same description of the kernel's parameter `index`, from the device.
std::string describe(const cl::Kernel& kernel, cl_uint index) {
    std::string name = kernel.getArgInfo<CL_KERNEL_ARG_NAME>(index);
    std::string type = kernel.getArgInfo<CL_KERNEL_ARG_TYPE_NAME>(index);
    cl_kernel_arg_address_qualifier address = kernel.getArgInfo<CL_KERNEL_ARG_ADDRESS_QUALIFIER>(index);
    // Drivers may end the strings with their terminator.
    for (std::string* text : {&name, &type})
        while (!text->empty() && text->back() == '\0') text->pop_back();
    bool pointer = !type.empty() && type.back() == '*';
    if (address == CL_KERNEL_ARG_ADDRESS_GLOBAL && pointer) return name + ": global pointer";
    if (address == CL_KERNEL_ARG_ADDRESS_PRIVATE && !pointer) return name + ": private " + type;
    return name + ": address qualifier " + std::to_string(address) + ", type " + type;
}

TEST(KernelSignatures, EveryHostSignatureMatchesItsKernel) {
    for (const KernelDeclaration& declared : kernel_declarations()) {
        SCOPED_TRACE(declared.kernel_name);
        cl::Kernel kernel = kernel_named(declared.kernel_name);
        if (!kernel()) continue;
        cl_uint count = kernel.getInfo<CL_KERNEL_NUM_ARGS>();
        std::vector<std::string> host, device;
        for (const KernelParam& param : declared.params) host.push_back(describe(param));
        for (cl_uint i = 0; i < count; ++i) device.push_back(describe(kernel, i));
        EXPECT_EQ(host, device);
    }
}

TEST(KernelSignatures, EveryKernelOfTheProgramHasAHostSignature) {
    std::set<std::string> declared;
    for (const KernelDeclaration& declaration : kernel_declarations()) declared.insert(declaration.kernel_name);
    std::set<std::string> in_programs;
    for (const cl::Program& program : programs())
        for (const std::string& name : kernel_names(program)) in_programs.insert(name);
    EXPECT_EQ(in_programs, declared);
}

}  // namespace
}  // namespace clr
