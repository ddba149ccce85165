// The shared structs must have the same size and field offsets on the device as on the
// host, or every buffer would be read shifted.
#include <gtest/gtest.h>

#include <cstddef>

#include "device/kernel_sources.h"
#include "render/feature_set.h"
#include "shared/clr_types.h"
#include "support/opencl_test_device.h"

namespace clr {
namespace {

TEST(StructLayout, DeviceAgreesWithHost) {
    auto& device = testing::test_device();
    cl::Program program = device.build_program(assemble_program_source(kTestStagesProgram.entry), FeatureSet::all().build_options());
    cl::Kernel kernel(program, "struct_layout");
    const int kCount = 14;
    cl::Buffer out(device.context(), CL_MEM_WRITE_ONLY, kCount * sizeof(cl_int));
    kernel.setArg(0, out);
    device.queue().enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(1), cl::NullRange);
    std::vector<cl_int> device_values(kCount);
    device.queue().enqueueReadBuffer(out, CL_TRUE, 0, kCount * sizeof(cl_int), device_values.data());

    const std::vector<int> host_values = {
        sizeof(ClrCamera), sizeof(ClrSphere), sizeof(ClrBillboard), sizeof(ClrRay), sizeof(ClrHit),
        sizeof(ClrSceneInfo),
        offsetof(ClrCamera, width), offsetof(ClrSphere, flags), offsetof(ClrBillboard, color),
        offsetof(ClrBillboard, texel_offset), offsetof(ClrBillboard, flags), offsetof(ClrHit, index),
        offsetof(ClrSceneInfo, sphere_count), offsetof(ClrSceneInfo, max_depth),
    };
    for (int i = 0; i < kCount; ++i) EXPECT_EQ(device_values[i], host_values[i]) << "layout value " << i;
}

}  // namespace
}  // namespace clr
