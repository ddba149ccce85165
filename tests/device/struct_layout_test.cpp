// The shared structs must have the same size and field offsets on the device as on the
// host, or every buffer would be read shifted. Both sides write them from one list,
// kernels/shared/clr_layout.h, which must name every struct and field of clr_types.h.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <regex>
#include <string>
#include <vector>

#include "device/kernel_sources.h"
#include "render/feature_set.h"
#include "render/kernel_signatures.h"
#include "shared/clr_layout.h"
#include "shared/clr_types.h"
#include "support/opencl_test_device.h"

namespace clr {
namespace {

struct LayoutValue {
    std::string what;
    int value;
};

// The host's view, in the order kernels/layout.cl writes the device's.
std::vector<LayoutValue> host_layout() {
    std::vector<LayoutValue> values;
#define CLR_LAYOUT_STRUCT(type) values.push_back({"sizeof(" #type ")", sizeof(type)});
#define CLR_LAYOUT_FIELD(type, field)                                             \
    values.push_back({"offsetof(" #type ", " #field ")", offsetof(type, field)}); \
    values.push_back({"sizeof(" #type "." #field ")", sizeof(type::field)});
    CLR_LAYOUT_LIST
#undef CLR_LAYOUT_STRUCT
#undef CLR_LAYOUT_FIELD
    return values;
}

std::vector<int> device_layout(std::size_t count) {
    auto& device = testing::test_device();
    cl::Program program = device.build_program(assemble_program_source(kTestStagesProgram.entry), FeatureSet::all().build_options());
    cl::Buffer out(device.context(), CL_MEM_WRITE_ONLY, count * sizeof(cl_int));
    TypedKernel<StructLayoutSignature> kernel(program, kStructLayout);
    device.queue().enqueueNDRangeKernel(kernel.bind(out), cl::NullRange, cl::NDRange(1), cl::NullRange);
    std::vector<cl_int> values(count);
    device.queue().enqueueReadBuffer(out, CL_TRUE, 0, count * sizeof(cl_int), values.data());
    return values;
}

TEST(StructLayout, DeviceAgreesWithHost) {
    const std::vector<LayoutValue> host = host_layout();
    const std::vector<int> device = device_layout(host.size());
    for (std::size_t i = 0; i < host.size(); ++i) EXPECT_EQ(device[i], host[i].value) << host[i].what;
}

// "Struct.field" for every field of every `typedef struct { ... } Name;` in `header`, in
// declaration order ("clr_uint pad0, pad1;" declares two).
std::vector<std::string> declared_fields(std::string header) {
    header = std::regex_replace(header, std::regex(R"(/\*[\s\S]*?\*/)"), " ");
    std::vector<std::string> fields;
    const std::regex typedef_struct(R"(typedef\s+struct\s*\{([^}]*)\}\s*(\w+)\s*;)");
    const std::regex declaration(R"(\s*\w+\s+([^;]+);)");
    const std::regex name(R"(\w+)");
    for (std::sregex_iterator s(header.begin(), header.end(), typedef_struct), end; s != end; ++s) {
        const std::string body = (*s)[1], type = (*s)[2];
        for (std::sregex_iterator d(body.begin(), body.end(), declaration); d != end; ++d) {
            const std::string names = (*d)[1];
            for (std::sregex_iterator n(names.begin(), names.end(), name); n != end; ++n)
                fields.push_back(type + "." + n->str());
        }
    }
    return fields;
}

std::string embedded_types_header() {
    for (const EmbeddedKernelFile& file : embedded_kernel_files())
        if (std::string(file.path) == "shared/clr_types.h") return file.text;
    ADD_FAILURE() << "shared/clr_types.h is not among the embedded kernel files";
    return "";
}

std::vector<std::string> listed_fields() {
    std::vector<std::string> fields;
#define CLR_LAYOUT_STRUCT(type)
#define CLR_LAYOUT_FIELD(type, field) fields.push_back(#type "." #field);
    CLR_LAYOUT_LIST
#undef CLR_LAYOUT_STRUCT
#undef CLR_LAYOUT_FIELD
    return fields;
}

TEST(StructLayout, ListNamesEveryFieldOfTheSharedStructs) {
    const std::vector<std::string> declared = declared_fields(embedded_types_header());
    ASSERT_GE(declared.size(), 40u) << "the parser found too few fields to be reading clr_types.h";
    const std::vector<std::string> listed = listed_fields();
    std::string missing;
    for (const std::string& field : declared)
        if (std::find(listed.begin(), listed.end(), field) == listed.end()) missing += " " + field;
    EXPECT_EQ(missing, "") << "fields of clr_types.h that kernels/shared/clr_layout.h does not list";
    EXPECT_EQ(listed, declared) << "kernels/shared/clr_layout.h must list the fields in declaration order";
}

TEST(StructLayout, FieldParserReadsSeveralNamesPerDeclaration) {
    const std::string header =
        "typedef struct {\n  clr_float4 a; /* x; y */\n  clr_uint b, c;\n} First;\n"
        "#define NOT_A_STRUCT 1\ntypedef struct { clr_int d; } Second;\n";
    EXPECT_EQ(declared_fields(header), (std::vector<std::string>{"First.a", "First.b", "First.c", "Second.d"}));
}

}  // namespace
}  // namespace clr
