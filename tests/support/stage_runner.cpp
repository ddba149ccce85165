#include "support/stage_runner.h"

#include "device/kernel_sources.h"
#include "render/kernel_signatures.h"
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
                                           renderer_.features().build_options())) {
    renderer_.move_geometry_to({0, 0, 0});  // the stages' rays are in scene coordinates
}

std::vector<ClrRay> StageRunner::raygen(const ClrCamera& camera) {
    std::size_t count = static_cast<std::size_t>(camera.width) * camera.height;
    cl::Buffer rays(test_device().context(), CL_MEM_WRITE_ONLY, count * sizeof(ClrRay));
    TypedKernel<RaygenSignature> kernel(program_, kRaygen);
    test_device().queue().enqueueNDRangeKernel(kernel.bind(camera, rays), cl::NullRange,
                                               cl::NDRange(camera.width, camera.height), cl::NullRange);
    return read_back<ClrRay>(rays, count);
}

std::vector<ClrHit> StageRunner::intersect(const std::vector<ClrRay>& rays) {
    cl::Buffer ray_buffer = input_buffer(rays);
    cl::Buffer hits(test_device().context(), CL_MEM_WRITE_ONLY, rays.size() * sizeof(ClrHit));
    TypedKernel<IntersectSignature> kernel(program_, kIntersect);
    run_1d(kernel.bind(ray_buffer, static_cast<cl_int>(rays.size()), renderer_.scene_args(), hits), rays.size());
    return read_back<ClrHit>(hits, rays.size());
}

ShadeOutput StageRunner::shade(const std::vector<ClrRay>& rays, const std::vector<ClrHit>& hits, int reflections) {
    cl::Buffer ray_buffer = input_buffer(rays);
    cl::Buffer hit_buffer = input_buffer(hits);
    cl::Buffer colors(test_device().context(), CL_MEM_WRITE_ONLY, rays.size() * sizeof(cl_float4));
    cl::Buffer next_rays(test_device().context(), CL_MEM_WRITE_ONLY, rays.size() * sizeof(ClrRay));
    TypedKernel<ShadeSignature> kernel(program_, kShade);
    run_1d(kernel.bind(ray_buffer, hit_buffer, static_cast<cl_int>(rays.size()), static_cast<cl_int>(reflections),
                       renderer_.scene_args(), colors, next_rays),
           rays.size());
    return {read_back<cl_float4>(colors, rays.size()), read_back<ClrRay>(next_rays, rays.size())};
}

}  // namespace clr::testing
