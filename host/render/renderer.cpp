#include "render/renderer.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <future>
#include <stdexcept>
#include <system_error>

#include "core/display_bytes.h"
#include "core/errors.h"
#include "core/huge_pages.h"
#include "core/stopwatch.h"
#include "device/cl_errors.h"
#include "device/kernel_sources.h"
#include "render/primary_ray_path.h"
#include "render/screen_tiles.h"
#include "shared/clr_samples.h"

namespace clr {
namespace {

// Work-group shape for the pixel grid: wide rows suit SIMD on CPUs (PoCL vectorises along
// x) and warps on GPUs. An explicit size keeps every core busy on small images too.
constexpr int kGroupWidth = 16;
constexpr int kGroupHeight = 4;
// render_packets: one work-item per 16x16-pixel screen tile, whose rows of 16 pixels already
// fill the SIMD lanes (PoCL has nothing left to vectorise across work-items). A work-group is
// a short row of tiles: few enough work-groups that PoCL's cost per work-group stays small,
// enough of them (over 500 at 1080p) to keep every core busy.
constexpr int kTileGroupWidth = 4;

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

// `buffer` holding `data`: written in place when it has that size already (a moving camera's
// frames re-express the same geometry relative to each eye: for a 1M-triangle mesh a fresh
// 80 MB buffer a frame cost its page faults on top of the copy), else made anew. The write is
// queued after the kernels that read the old contents, and done when this returns.
template <typename T>
void refill(cl::CommandQueue& queue, const cl::Context& context, cl::Buffer& buffer, const std::vector<T>& data) {
    if (!data.empty() && buffer() != nullptr && buffer.getInfo<CL_MEM_SIZE>() == data.size() * sizeof(T)) {
        queue.enqueueWriteBuffer(buffer, CL_TRUE, 0, data.size() * sizeof(T), data.data());
        return;
    }
    buffer = upload(context, data);
}

// The texel buffer over `storage` itself where it has texels: a device that works in host
// memory (PoCL) then reads them where they are, instead of copying 20 MB into fresh pages on
// every start (docs/benchmarks.md, Against POV-Ray); another may still copy or cache them,
// which the spec allows. The caller keeps `storage` alive and unwritten while the buffer lives.
cl::Buffer use_in_place(const cl::Context& context, PageAlignedVector<std::uint8_t>& storage) {
    if (storage.empty()) return upload(context, std::vector<std::uint8_t>{});
    return cl::Buffer(context, CL_MEM_READ_ONLY | CL_MEM_USE_HOST_PTR | CL_MEM_HOST_NO_ACCESS, storage.size(),
                      storage.data());
}

// Whether the device works in host memory (CPU devices such as PoCL's): then the kernel
// writes into the image itself, through a buffer over its storage, instead of into a
// device buffer whose every byte is then copied once more (docs/benchmarks.md).
bool shares_host_memory(const cl::Device& device) {
    return device.getInfo<CL_DEVICE_TYPE>() == CL_DEVICE_TYPE_CPU && device.getInfo<CL_DEVICE_HOST_UNIFIED_MEMORY>();
}

// Whether primary rays go one work-item a pixel (RendererOptions::per_pixel): on a GPU, 16-ray
// packets in screen tiles kept its lanes idle (1M triangles: 23 Mrays/s in packets, 1,104 per
// pixel through the BVH; docs/benchmarks.md, A GPU).
bool per_pixel_on(const cl::Device& device, const std::optional<bool>& choice) {
    if (choice) return *choice;
    return traces_per_pixel(device.getInfo<CL_DEVICE_TYPE>());
}

}  // namespace

Renderer::Renderer(DeviceContext& device, const Scene& scene, const RendererOptions& options)
    : device_(device),
      scene_(scene),
      frame_(scene_),
      screen_tiles_(options.screen_tiles && !per_pixel_on(device.device(), options.per_pixel)),
      band_sizer_(options.band_seconds),
      fixed_band_rows_(options.band_rows),
      between_bands_(options.between_bands),
      band_done_(options.band_done),
      crop_(options.crop) {
    // Impostors start placed for the first key, so that the buffers have their frames' sizes,
    // and the geometry relative to its eye, the first frame's origin (frame_camera): a still's
    // frame then uploads nothing again (show()), which for a 1M-triangle mesh was 0.2 s.
    if (!scene_.camera_path.empty()) {
        frame_.place_impostors(scene_.camera_path.front());
        origin_ = scene_.camera_path.front().eye;
    }
    compiled_ = compile_scene(frame_, origin_);
    features_ = options.features.value_or(compiled_.features);
    features_.double_precision = options.double_precision;
    features_.float_output = options.float_output;
    // Per pixel, primary rays search the BVH too: among enough objects, build one. Packets
    // that walk it need one whatever the count.
    if (options.screen_tiles && !screen_tiles_ && FeatureSet::bvh_objects(scene_) > kBvhMinObjects) features_.bvh = true;
    bvh_packets_ = screen_tiles_ && !features_.clip &&
                   options.packets_walk_bvh.value_or(prefers_bvh_packets(scene_.triangles.size(), features_.clip));
    if (bvh_packets_) features_.bvh = true;
    if (options.double_precision && device_.device().getInfo<CL_DEVICE_DOUBLE_FP_CONFIG>() == 0)
        throw DeviceError("'" + device_.entry().device_name +
                          "' has no double precision (cl_khr_fp64); use --precision float or another device");

    const Stopwatch build_time;
    // Only the kernel this renderer runs is built: compiling the others too would slow every
    // cold start (docs/benchmarks.md, Start-up).
    const KernelProgram& program = screen_tiles_ ? kRenderTilesProgram : kRenderBruteForceProgram;
    const std::string source = assemble_program_source(program.entry, options.kernel_dir);
    std::optional<cl::Program> ready;
    if (options.general_stand_in && !options.features) {
        ready = device_.prebuilt_program(source, features_.build_options());
        const FeatureSet general = FeatureSet::general(features_);
        if (!ready && !(general == features_)) {
            ready = device_.prebuilt_program(source, general.build_options());
            if (ready) features_ = general;  // its buffers too: the BVH, the coverage bits
        }
    }
    program_ = ready ? *ready : device_.build_program(source, features_.build_options());
    build_ms_ = build_time.elapsed_ms();
    try {
        if (screen_tiles_)
            render_packets_ = TypedKernel<RenderPacketsSignature>(program_, kRenderPackets);
        else
            render_ = TypedKernel<RenderSignature>(program_, kRender);
        texel_storage_ = std::move(compiled_.texels);
        scene_args_.texels = use_in_place(device_.context(), texel_storage_);
        // Only kernels with alpha tests read the coverage bits (render_packets, with
        // CLR_FEATURE_ALPHA); others get the one-word stand-in.
        scene_args_.coverage = upload(device_.context(), features_.alpha ? compiled_.coverage : std::vector<std::uint32_t>{});
        compiled_.texels = {};  // the buffer's now; frames only move positions
        compiled_.coverage = {};
        if (features_.bvh) {  // otherwise empty: never read
            const MeshTreeCache tree_cache = MeshTreeCache::from_environment();
            mesh_trees_ = build_mesh_trees(scene_, &tree_cache);
            bvh_ = build_bvh(frame_, mesh_trees_);
        }
        // Corner normals and meshes' shading do not move with the eye: uploaded once, not with
        // each frame's geometry.
        scene_args_.triangle_normals = upload(device_.context(), compiled_.triangle_normals);
        compiled_.triangle_normals = {};  // the buffer's now, as the texels are
        scene_args_.mesh_surfaces = upload(device_.context(), compiled_.mesh_surfaces);
        scene_args_.triangle_ties = upload_triangle_ties();
        scene_args_.materials = upload(device_.context(), compiled_.materials);
        upload_geometry();
        uploaded_ = true;
        max_buffer_bytes_ = device_.device().getInfo<CL_DEVICE_MAX_MEM_ALLOC_SIZE>();
        render_in_place_ = shares_host_memory(device_.device());
    } catch (const cl::Error& error) {
        throw DeviceError(describe_cl_error(error, "uploading the scene to '" + device_.entry().device_name + "'"));
    }
    if (options.max_buffer_bytes) max_buffer_bytes_ = std::min(max_buffer_bytes_, options.max_buffer_bytes);
}

cl::Buffer Renderer::upload_triangle_ties() const {
    // Only programs that settle hits on shared edges read the neighbours (six ints a triangle,
    // as Scene::triangle_ties holds them, uploaded without a copy); others get the one-element
    // stand-in. A scene built without them ties each triangle to itself.
    using Ties = std::array<std::int32_t, 6>;
    static_assert(sizeof(Ties) == 6 * sizeof(cl_int));
    if (!features_.triangle_ties) return upload(device_.context(), std::vector<Ties>{});
    if (scene_.triangle_ties.size() == scene_.triangles.size()) return upload(device_.context(), scene_.triangle_ties);
    std::vector<Ties> alone(scene_.triangles.size());
    for (std::size_t t = 0; t < alone.size(); ++t) alone[t].fill(static_cast<std::int32_t>(t));
    return upload(device_.context(), alone);
}

void Renderer::upload_geometry() {
    const cl::Context& context = device_.context();
    cl::CommandQueue& queue = device_.queue();
    refill(queue, context, scene_args_.spheres, compiled_.spheres);
    refill(queue, context, scene_args_.billboards, compiled_.billboards);
    refill(queue, context, scene_args_.triangles, compiled_.triangles);
    refill(queue, context, scene_args_.planes, compiled_.planes);
    refill(queue, context, scene_args_.lights, compiled_.lights);
    compile_bvh(bvh_, origin_, device_bvh_nodes_);
    refill(queue, context, scene_args_.bvh_nodes, device_bvh_nodes_);
    refill(queue, context, scene_args_.bvh_items, bvh_.items);
    scene_args_.info = compiled_.info;
    scene_args_.info.primary_bvh = bvh_packets_ ? 1 : 0;
}

// Only positions change from frame to frame; impostors also turn, and then their billboards
// and the BVH over them are made anew.
void Renderer::show(const CameraKey& key, const Vec3& origin, const FrameCamera* binned_for) {
    tiles_binned_ = false;
    bool turns = !scene_.impostors.empty();
    if (uploaded_ && origin == origin_ && !turns) return;
    uploaded_ = false;
    origin_ = origin;
    if (turns) frame_.place_impostors(key);
    // Binning reads only the placed geometry and the camera, so it runs beside compiling and
    // uploading, while the device's threads wait for the frame: on 10k impostors the two take
    // about 0.9 and 0.6 ms (docs/benchmarks.md, Impostor frames). The future's destructor
    // waits for it, also when an upload throws. A process that cannot start the thread bins
    // in render_camera() instead, as a still frame does (run.cpp lists devices the same way).
    std::future<void> tiles;
    if (binned_for && screen_tiles_ && !bvh_packets_) {
        try {
            tiles = std::async(std::launch::async, [this, binned_for] { binner_.bin(frame_, *binned_for, tiles_); });
        } catch (const std::system_error&) {
        }
    }
    compile_frame(compiled_, frame_, origin_);
    if (turns && features_.bvh) bvh_ = build_bvh(frame_, mesh_trees_);
    try {
        upload_geometry();
    } catch (const cl::Error& error) {
        throw DeviceError(describe_cl_error(error, "uploading the scene to '" + device_.entry().device_name + "'"));
    }
    uploaded_ = true;
    if (tiles.valid()) {
        tiles.get();
        tiles_binned_ = true;
    }
}

Image Renderer::render(const CameraKey& key, int frame, FrameTiming* timing) {
    FrameCamera camera = frame_camera(scene_, key, frame);
    show(key, camera.origin, &camera);
    return render_camera(camera, timing, crop_);
}

void Renderer::change_view(const Vec3& up, double fov_degrees, int width, int height, const SamplingSettings& sampling) {
    // Impostors turn about the up vector: they are placed anew for the next frame (show()
    // places them on every frame of a scene that has them, reading scene_.up).
    scene_.up = up;
    scene_.fov_degrees = fov_degrees;
    scene_.width = width;
    scene_.height = height;
    scene_.sampling = sampling;
}

void Renderer::warm_up() {
    const CameraKey& key = scene_.camera_path.front();
    FrameCamera thumbnail = make_frame_camera(key.eye, key.lookat, scene_.up, scene_.fov_degrees, 64, 36, key.eye);
    show(key, thumbnail.origin);
    render_camera(thumbnail, nullptr, std::nullopt);  // the whole thumbnail: a crop is of the frame
}

void Renderer::move_geometry_to(const Vec3& origin) {
    // Without a camera key the geometry is relative to (0, 0, 0) and nothing has impostors.
    if (!scene_.camera_path.empty()) show(scene_.camera_path.front(), origin);
}

void Renderer::recycle(Image&& image) { spare_pixels_ = std::move(image.rgba); }

static bool is_out_of_memory(const cl::Error& error) {
    return error.err() == CL_MEM_OBJECT_ALLOCATION_FAILURE || error.err() == CL_OUT_OF_RESOURCES ||
           error.err() == CL_OUT_OF_HOST_MEMORY || error.err() == CL_INVALID_BUFFER_SIZE;
}

void Renderer::reserve_pixels(std::size_t bytes) {
    if (bytes <= pixels_capacity_) return;
    pixels_ = cl::Buffer();  // free the old buffer before asking for a larger one
    pixels_capacity_ = 0;
    pixels_ = cl::Buffer(device_.context(), CL_MEM_WRITE_ONLY, bytes);
    pixels_capacity_ = bytes;
}


std::uint8_t* Renderer::kernel_pixels(Image& image) const {
    return features_.float_output ? reinterpret_cast<std::uint8_t*>(image.linear.data()) : image.rgba.data();
}

double Renderer::render_band(const ClrCamera& camera, const PixelRect& region, int first_row, int rows,
                             Image& rows_image) {
    std::size_t row_bytes = static_cast<std::size_t>(camera.width) * pixel_bytes();
    std::size_t band_bytes = rows * row_bytes;
    std::uint8_t* target = kernel_pixels(rows_image) + (first_row - region.y0) * row_bytes;
    bool in_place = render_in_place_;
    if (in_place)
        pixels_ = cl::Buffer(device_.context(), CL_MEM_WRITE_ONLY | CL_MEM_USE_HOST_PTR | CL_MEM_HOST_READ_ONLY,
                             band_bytes, target);
    else
        reserve_pixels(band_bytes);
    cl::Kernel& kernel = screen_tiles_ ? render_packets_.bind(camera, first_row, rows, scene_args_, pixels_, tile_args_)
                                       : render_.bind(camera, first_row, rows, scene_args_, pixels_);
    // render_packets: one work-item per screen tile that the band's rows touch; render: one
    // per pixel. A crop's columns are a global offset: the kernels read their column from
    // get_global_id(0), so the full frame's tile grid stays as it is, and columns outside the
    // crop are not rendered (nor written: render_camera() keeps only the crop's columns).
    cl::NDRange offset, local, global;
    if (screen_tiles_) {
        std::size_t tile_rows = (first_row + rows - 1) / kClrTileSize - first_row / kClrTileSize + 1;
        const int first_tile = region.x0 / kClrTileSize;
        const int end_tile = (region.x1 + kClrTileSize - 1) / kClrTileSize;
        offset = cl::NDRange(first_tile, 0);
        local = cl::NDRange(kTileGroupWidth, 1);
        global = cl::NDRange(round_up(end_tile - first_tile, kTileGroupWidth), tile_rows);
    } else {
        offset = cl::NDRange(region.x0, 0);
        local = cl::NDRange(kGroupWidth, kGroupHeight);
        global = cl::NDRange(round_up(region.width(), kGroupWidth), round_up(rows, kGroupHeight));
    }
    // The whole frame keeps the null offset it always had.
    if (region.x0 == 0) offset = cl::NullRange;
    cl::Event done;
    device_.queue().enqueueNDRangeKernel(kernel, offset, global, local, nullptr, &done);
    if (in_place) {
        // Mapping makes the kernel's writes visible in the image; the pointer is the image's.
        // Where it is (as on PoCL), map and unmap are queued at once and the host waits once.
        cl::Event mapped_event;
        void* mapped = device_.queue().enqueueMapBuffer(pixels_, CL_FALSE, CL_MAP_READ, 0, band_bytes, nullptr,
                                                        &mapped_event);
        if (mapped != target) {
            mapped_event.wait();
            std::memcpy(target, mapped, band_bytes);
        }
        cl::Event unmapped;
        device_.queue().enqueueUnmapMemObject(pixels_, mapped, nullptr, &unmapped);
        unmapped.wait();  // the driver is done with the image before it leaves the renderer
        pixels_ = cl::Buffer();  // the image's storage: never used after this frame
        pixels_capacity_ = 0;
    } else {
        device_.queue().enqueueReadBuffer(pixels_, CL_TRUE, 0, band_bytes, target);
    }
    auto ns = done.getProfilingInfo<CL_PROFILING_COMMAND_END>() - done.getProfilingInfo<CL_PROFILING_COMMAND_START>();
    return static_cast<double>(ns) * 1e-6;
}

const ScreenTiles& Renderer::upload_screen_tiles(const FrameCamera& camera) {
    if (bvh_packets_)
        leave_tiles_unlisted(camera, tiles_);
    else if (!tiles_binned_)
        binner_.bin(frame_, camera, tiles_);
    tiles_binned_ = false;
    const ScreenTiles& tiles = tiles_;
    tile_args_.offsets = upload(device_.context(), tiles.offsets);
    tile_args_.items = upload(device_.context(), tiles.items);
    tile_args_.nearest = upload(device_.context(), tiles.nearest);
    tile_args_.rows = upload(device_.context(), tiles.rows);
    tile_args_.tiles_x = tiles.tiles_x;
    return tiles;
}

// Copies columns [x0, x0 + crop.width) of every row of `rows` (as wide as the frame) into `crop`:
// its display bytes, or in the float output mode its linear values (the bytes follow from those).
static void keep_columns(const Image& rows, int x0, Image& crop) {
    const std::size_t crop_values = static_cast<std::size_t>(crop.width) * 4;
    const std::size_t row_values = static_cast<std::size_t>(rows.width) * 4;
    for (int row = 0; row < crop.height; ++row) {
        const std::size_t from = row * row_values + static_cast<std::size_t>(x0) * 4;
        if (!rows.linear.empty())
            std::memcpy(crop.linear.data() + row * crop_values, rows.linear.data() + from, crop_values * sizeof(float));
        else
            std::memcpy(crop.rgba.data() + row * crop_values, rows.rgba.data() + from, crop_values);
    }
}

// Every frame renders in bands of rows (BandSizer) so that between_bands_ runs several times a
// second, and also when one band's pixel buffer exceeds the device's allocation limit, or its
// allocation fails: then the limit halves until a band fits. Bands give the same bytes: every
// pixel's samples depend on the pixel and the frame (clr_samples.h), not on its band.
Image Renderer::render_camera(const FrameCamera& view, FrameTiming* timing, const std::optional<PixelRect>& crop) {
    const Stopwatch frame_time;
    const ClrCamera camera = view.device();
    const PixelRect region = crop.value_or(PixelRect{0, camera.width, 0, camera.height});
    if (!region.inside(camera.width, camera.height))
        throw std::invalid_argument("crop " + format_pixel_rect(region) + " outside the " +
                                    std::to_string(camera.width) + "x" + std::to_string(camera.height) + " frame");
    const bool whole_rows = region.x0 == 0 && region.x1 == camera.width;
    // The kernels write whole rows of the frame's width: a crop of fewer columns renders its
    // rows into a frame-wide image first, and keeps its columns from there.
    Image image;
    image.width = region.width();
    image.height = region.height();
    std::size_t row_bytes = static_cast<std::size_t>(camera.width) * 4;
    std::size_t image_bytes = static_cast<std::size_t>(image.width) * image.height * 4;
    // Every pixel is written below, so recycled storage of the right size needs no clearing;
    // new storage costs a page fault and a zero fill per page (docs/benchmarks.md), or per
    // 2 MiB where huge pages serve (8.3 MB at 1080p).
    if (spare_pixels_.size() == image_bytes) image.rgba.swap(spare_pixels_);
    spare_pixels_.clear();
    resize_with_huge_pages(image.rgba, image_bytes);
    if (features_.float_output) {
        image.linear.resize(static_cast<std::size_t>(image.width) * image.height * 4);
        row_bytes = static_cast<std::size_t>(camera.width) * pixel_bytes();  // the kernel's rows
    }
    Image rows_image;
    if (!whole_rows) {
        rows_image.width = camera.width;
        rows_image.height = region.height();
        if (features_.float_output)
            rows_image.linear.resize(static_cast<std::size_t>(camera.width) * region.height() * 4);
        else
            rows_image.rgba.resize(row_bytes * region.height());
    }
    if (row_bytes > max_buffer_bytes_)
        throw DeviceError("a row of " + std::to_string(camera.width) + " pixels needs " + std::to_string(row_bytes) +
                          " bytes of device memory, more than '" + device_.entry().device_name + "' allows (" +
                          std::to_string(max_buffer_bytes_) + ")");
    std::vector<double> work;
    if (screen_tiles_) {
        try {
            const ScreenTiles& tiles = upload_screen_tiles(view);
            work = bvh_packets_ ? row_work_through_bvh(frame_.object_count(), camera.width, camera.height)
                                : row_work(tiles, camera.width, camera.height);
        } catch (const cl::Error& error) {
            throw DeviceError(describe_cl_error(error, "uploading screen tiles to '" + device_.entry().device_name + "'"));
        }
    } else {
        int objects = static_cast<int>(frame_.object_count());
        work = row_work(objects, camera.width, camera.height);
    }
    band_sizer_.start_frame(std::move(work), camera.samples, camera.width);
    double kernel_ms = render_bands(camera, region, whole_rows ? image : rows_image);
    if (!whole_rows) keep_columns(rows_image, region.x0, image);
    if (features_.float_output) fill_display_bytes(image);  // the kernel wrote floats only
    if (timing) {
        timing->kernel_ms = kernel_ms;
        timing->total_ms = frame_time.elapsed_ms();
    }
    return image;
}

double Renderer::render_bands(const ClrCamera& camera, const PixelRect& region, Image& rows_image) {
    std::size_t row_bytes = static_cast<std::size_t>(camera.width) * pixel_bytes();
    int limit = static_cast<int>(std::min<std::size_t>(region.height(), max_buffer_bytes_ / row_bytes));
    double kernel_ms = 0;
    bands_ = 0;
    for (int first_row = region.y0; first_row < region.y1;) {
        if (between_bands_) between_bands_();
        const int rows_left = region.y1 - first_row;
        int rows = fixed_band_rows_ > 0 ? std::min({fixed_band_rows_, limit, rows_left})
                                        : band_sizer_.next_rows(first_row, std::min(limit, rows_left));
        const Stopwatch band_time;
        try {
            kernel_ms += render_band(camera, region, first_row, rows, rows_image);
        } catch (const cl::Error& error) {
            if (!is_out_of_memory(error) || rows == 1)
                throw DeviceError(describe_cl_error(error, "rendering a frame on '" + device_.entry().device_name + "'"));
            limit = std::max(1, rows / 2);
            continue;  // the same rows again, in a smaller band
        }
        band_sizer_.band_done(first_row, rows, band_time.elapsed_seconds());
        first_row += rows;
        ++bands_;
        if (band_done_) band_done_(static_cast<double>(first_row - region.y0) / region.height());
    }
    return kernel_ms;
}

}  // namespace clr
