#include "support/stage_runner.h"

#include "device/kernel_sources.h"
#include "support/opencl_test_device.h"

namespace clr::testing {
namespace {

template <typename T>
cl::Buffer input_buffer(const std::vector<T>& data) {
    return cl::Buffer(test_device().context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, data.size() * sizeof(T),
                      const_cast<T*>(data.data()));
}

template <typename T>
std::vector<T> read_back(const cl::Buffer& buffer, std::size_t count) {
    std::vector<T> out(count);
    test_device().queue().enqueueReadBuffer(buffer, CL_TRUE, 0, count * sizeof(T), out.data());
    return out;
}

void run_1d(cl::Kernel& kernel, std::size_t count) {
    test_device().queue().enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(count), cl::NullRange);
}

}  // namespace

StageRunner::StageRunner(const Scene& scene, const RendererOptions& options)
    : renderer_(test_device(), scene, options),
      program_(test_device().build_program(assemble_program_source(kTestStagesProgram.entry, options.kernel_dir),
                                           renderer_.features().build_options())) {}

std::vector<ClrRay> StageRunner::raygen(const ClrCamera& camera) {
    std::size_t count = static_cast<std::size_t>(camera.width) * camera.height;
    cl::Buffer rays(test_device().context(), CL_MEM_WRITE_ONLY, count * sizeof(ClrRay));
    cl::Kernel kernel(program_, "raygen");
    kernel.setArg(0, camera);
    kernel.setArg(1, rays);
    test_device().queue().enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(camera.width, camera.height),
                                               cl::NullRange);
    return read_back<ClrRay>(rays, count);
}

std::vector<ClrHit> StageRunner::intersect(const std::vector<ClrRay>& rays) {
    cl::Buffer ray_buffer = input_buffer(rays);
    cl::Buffer hits(test_device().context(), CL_MEM_WRITE_ONLY, rays.size() * sizeof(ClrHit));
    cl::Kernel kernel(program_, "intersect");
    kernel.setArg(0, ray_buffer);
    kernel.setArg(1, static_cast<cl_int>(rays.size()));
    renderer_.bind_scene(kernel, 2);
    kernel.setArg(2 + Renderer::kSceneArgs, hits);
    run_1d(kernel, rays.size());
    return read_back<ClrHit>(hits, rays.size());
}

ShadeOutput StageRunner::shade(const std::vector<ClrRay>& rays, const std::vector<ClrHit>& hits, int reflections) {
    cl::Buffer ray_buffer = input_buffer(rays);
    cl::Buffer hit_buffer = input_buffer(hits);
    cl::Buffer colors(test_device().context(), CL_MEM_WRITE_ONLY, rays.size() * sizeof(cl_float4));
    cl::Buffer next_rays(test_device().context(), CL_MEM_WRITE_ONLY, rays.size() * sizeof(ClrRay));
    cl::Kernel kernel(program_, "shade");
    kernel.setArg(0, ray_buffer);
    kernel.setArg(1, hit_buffer);
    kernel.setArg(2, static_cast<cl_int>(rays.size()));
    kernel.setArg(3, static_cast<cl_int>(reflections));
    renderer_.bind_scene(kernel, 4);
    kernel.setArg(4 + Renderer::kSceneArgs, colors);
    kernel.setArg(5 + Renderer::kSceneArgs, next_rays);
    run_1d(kernel, rays.size());
    return {read_back<cl_float4>(colors, rays.size()), read_back<ClrRay>(next_rays, rays.size())};
}

}  // namespace clr::testing
