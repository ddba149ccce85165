#include "render/renderer.h"

#include <chrono>

#include "core/errors.h"
#include "device/cl_errors.h"
#include "device/kernel_sources.h"

namespace clr {
namespace {

// Work-group shape for the pixel grid: wide rows suit SIMD on CPUs (PoCL vectorises along
// x) and warps on GPUs. An explicit size keeps every core busy on small images too.
constexpr int kGroupWidth = 16;
constexpr int kGroupHeight = 4;

std::size_t round_up(std::size_t value, std::size_t multiple) { return (value + multiple - 1) / multiple * multiple; }

// OpenCL buffers cannot be empty, so a scene without spheres gets a one-element buffer
// that the kernels never read (the counts say so).
template <typename T>
cl::Buffer upload(const cl::Context& context, const std::vector<T>& data) {
    static const T kUnused{};
    const void* bytes = data.empty() ? &kUnused : data.data();
    std::size_t size = data.empty() ? sizeof(T) : data.size() * sizeof(T);
    return cl::Buffer(context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, size, const_cast<void*>(bytes));
}

double elapsed_ms(std::chrono::steady_clock::time_point since) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - since).count();
}

}  // namespace

Renderer::Renderer(DeviceContext& device, const Scene& scene, const RendererOptions& options) : device_(device) {
    CompiledScene compiled = compile_scene(scene);
    features_ = options.features.value_or(compiled.features);
    info_ = compiled.info;

    auto start = std::chrono::steady_clock::now();
    program_ = device_.build_program(assemble_program_source(options.kernel_dir), features_.build_options());
    build_ms_ = elapsed_ms(start);
    try {
        render_kernel_ = cl::Kernel(program_, "render");
        spheres_ = upload(device_.context(), compiled.spheres);
        billboards_ = upload(device_.context(), compiled.billboards);
        texels_ = upload(device_.context(), compiled.texels);
        bind_scene(render_kernel_, 1);
    } catch (const cl::Error& error) {
        throw DeviceError(describe_cl_error(error, "uploading the scene to '" + device_.entry().device_name + "'"));
    }
}

void Renderer::bind_scene(cl::Kernel& kernel, int first) const {
    kernel.setArg(first, spheres_);
    kernel.setArg(first + 1, billboards_);
    kernel.setArg(first + 2, texels_);
    kernel.setArg(first + 3, info_);
}

Image Renderer::render_frame(const ClrCamera& camera, FrameTiming* timing) {
    auto start = std::chrono::steady_clock::now();
    Image image;
    image.width = camera.width;
    image.height = camera.height;
    image.rgba.resize(static_cast<std::size_t>(camera.width) * camera.height * 4);
    try {
        if (image.rgba.size() > pixels_capacity_) {
            pixels_ = cl::Buffer(device_.context(), CL_MEM_WRITE_ONLY, image.rgba.size());
            pixels_capacity_ = image.rgba.size();
        }
        render_kernel_.setArg(0, camera);
        render_kernel_.setArg(5, pixels_);
        cl::NDRange global(round_up(camera.width, kGroupWidth), round_up(camera.height, kGroupHeight));
        cl::Event done;
        device_.queue().enqueueNDRangeKernel(render_kernel_, cl::NullRange, global,
                                             cl::NDRange(kGroupWidth, kGroupHeight), nullptr, &done);
        device_.queue().enqueueReadBuffer(pixels_, CL_TRUE, 0, image.rgba.size(), image.rgba.data());
        if (timing) {
            auto ns = done.getProfilingInfo<CL_PROFILING_COMMAND_END>() - done.getProfilingInfo<CL_PROFILING_COMMAND_START>();
            timing->kernel_ms = static_cast<double>(ns) * 1e-6;
        }
    } catch (const cl::Error& error) {
        throw DeviceError(describe_cl_error(error, "rendering a frame on '" + device_.entry().device_name + "'"));
    }
    if (timing) timing->total_ms = elapsed_ms(start);
    return image;
}

}  // namespace clr
