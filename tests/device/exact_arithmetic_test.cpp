// Float division and square root in clrender's programs are correctly rounded wherever the device
// offers it (device/exact_arithmetic.h): every program asks, and a kernel's quotients and roots
// are the host's to the bit.
#include "device/exact_arithmetic.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "support/opencl_test_device.h"
#include "support/scoped_env.h"

namespace clr {
namespace {

using testing::ScopedEnv;

const char* const kDivideAndRoot = R"(
kernel void divide_and_root(global const float* a, global const float* b, global float* quotient, global float* root)
{
    size_t i = get_global_id(0);
    quotient[i] = a[i] / b[i];
    root[i] = sqrt(a[i]);
}
)";

bool device_offers_exact_division(const cl::Device& device) {
    return (device.getInfo<CL_DEVICE_SINGLE_FP_CONFIG>() & CL_FP_CORRECTLY_ROUNDED_DIVIDE_SQRT) != 0;
}

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(ExactArithmetic, ProgramsAskForItWhereTheDeviceOffersIt) {
    ScopedEnv cache("CLRENDER_CACHE_DIR", "off");  // built here, not taken from an earlier run
    DeviceContext& device = testing::test_device();
    const cl::Program program = device.build_program(kDivideAndRoot, "-DCLR_TEST=1");
    const std::string options = program.getBuildInfo<CL_PROGRAM_BUILD_OPTIONS>(device.device());
    const bool asked = options.find("-cl-fp32-correctly-rounded-divide-sqrt") != std::string::npos;
    EXPECT_EQ(asked, device_offers_exact_division(device.device())) << options;
    EXPECT_NE(options.find("-DCLR_TEST=1"), std::string::npos) << "the program's own options are kept: " << options;
    EXPECT_EQ(with_exact_arithmetic(device.device(), "").empty(), !device_offers_exact_division(device.device()));
}

TEST(ExactArithmetic, QuotientsAndRootsAreTheHostsToTheBit) {
    DeviceContext& device = testing::test_device();
    if (!device_offers_exact_division(device.device())) GTEST_SKIP() << "the device rounds within its ulp bounds";
    ScopedEnv cache("CLRENDER_CACHE_DIR", "off");
    std::mt19937 random(11);
    std::uniform_real_distribution<float> mantissa(1.0f, 2.0f);
    std::uniform_int_distribution<int> exponent(-60, 60);
    const std::size_t count = 1 << 16;
    std::vector<float> a(count), b(count);
    for (std::size_t i = 0; i < count; ++i) {
        a[i] = std::ldexp(mantissa(random), exponent(random));
        b[i] = std::ldexp(mantissa(random), exponent(random));
    }
    const cl::Program program = device.build_program(kDivideAndRoot, "");
    cl::Kernel kernel(program, "divide_and_root");
    const cl::Context& context = device.context();
    cl::Buffer in_a(context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, count * sizeof(float), a.data());
    cl::Buffer in_b(context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, count * sizeof(float), b.data());
    cl::Buffer quotients(context, CL_MEM_WRITE_ONLY, count * sizeof(float));
    cl::Buffer roots(context, CL_MEM_WRITE_ONLY, count * sizeof(float));
    kernel.setArg(0, in_a);
    kernel.setArg(1, in_b);
    kernel.setArg(2, quotients);
    kernel.setArg(3, roots);
    device.queue().enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(count), cl::NullRange);
    std::vector<float> q(count), r(count);
    device.queue().enqueueReadBuffer(quotients, CL_FALSE, 0, count * sizeof(float), q.data());
    device.queue().enqueueReadBuffer(roots, CL_TRUE, 0, count * sizeof(float), r.data());
    int wrong_quotients = 0, wrong_roots = 0;
    for (std::size_t i = 0; i < count; ++i) {
        wrong_quotients += !same_bits(q[i], a[i] / b[i]);
        wrong_roots += !same_bits(r[i], std::sqrt(a[i]));
    }
    EXPECT_EQ(wrong_quotients, 0);
    EXPECT_EQ(wrong_roots, 0);
}

}  // namespace
}  // namespace clr
