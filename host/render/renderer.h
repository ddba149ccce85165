// Renders frames of one scene on one OpenCL device. Construction builds the program for the
// scene's feature set and uploads the scene buffers once; each frame then moves the geometry
// to its eye and places the impostors (FrameGeometry -> CompiledScene, BVH, screen tiles).
#pragma once

#include <functional>
#include <optional>
#include <vector>
#include <string>

#include "core/pixel_rect.h"
#include "device/device_context.h"
#include "render/band_sizer.h"
#include "render/bvh.h"
#include "render/scene_bvh.h"
#include "render/compiled_scene.h"
#include "render/frame_camera.h"
#include "render/frame_geometry.h"
#include "render/frame_timing.h"
#include "render/kernel_signatures.h"
#include "render/primary_ray_path.h"
#include "render/screen_tiles.h"
#include "scene/scene.h"

namespace clr {

struct RendererOptions {
    std::string kernel_dir;                // read kernels from here instead of the embedded copies
    std::optional<FeatureSet> features;    // compile these instead of the scene's own (tests)
    // For a still and for the viewer: where neither the program cache nor the program store
    // holds the scene's own program but one of them holds the general one
    // (FeatureSet::general), render with that instead of compiling: the same pixels, a little
    // slower per frame, and no compile (seconds on PoCL). Frames of an animation leave it off:
    // one compile pays for them all, and the program cache keeps it for the next run. Not with
    // `features`.
    bool general_stand_in = false;
    // Largest pixel buffer to allocate on the device, in bytes; 0: the device's own limit.
    // No band is larger (see render_bands()).
    std::size_t max_buffer_bytes = 0;
    // Every frame renders in bands of rows, each sized to take about band_seconds, so that
    // between_bands runs several times a second however long the frame takes.
    double band_seconds = 0.15;
    // Rows per band instead (tests): 0 sizes bands by time.
    int band_rows = 0;
    // Runs before each band; throws to abandon the frame (clrender passes
    // throw_if_interrupted, so that Ctrl-C stops a long still within a band's time).
    std::function<void()> between_bands;
    // Cull primary rays by screen tiles, 16 rays at a time (render_packets); off: every pixel tests every object
    // (the brute-force kernel, which the tests use as the general reference).
    bool screen_tiles = true;
    // Where screen_tiles is on: whether primary rays go one work-item a pixel through the BVH
    // (the brute-force kernel with a BVH compiled in) instead of in screen tiles of 16-ray
    // packets. Unset, the device decides: per pixel on a GPU, whose lanes each follow one ray,
    // tiles elsewhere (docs/benchmarks.md, A GPU). Either way the same bytes.
    std::optional<bool> per_pixel;
    // Where primary rays go in packets: whether the packets walk the BVH (built for them)
    // instead of screen-tile lists binned every frame. Unset: where the scene has many
    // triangles (prefers_bvh_packets(), render/primary_ray_path.h). Never where the camera clips
    // to near and far depths. Either way the same bytes.
    std::optional<bool> packets_walk_bvh;
    // Intersect and shade in double (the device needs cl_khr_fp64; DeviceError otherwise).
    bool double_precision = false;
    // Frames also carry their linear colours and coverage (Image::linear), from kernels
    // compiled with the float output mode (FeatureSet::float_output); rgba then holds the
    // same bytes as without.
    bool float_output = false;
    // Runs after each band with the fraction (0..1] of the frame's rows rendered (progress).
    std::function<void(double)> band_done;
    // Renders only these pixels of every frame, into an image of the rectangle's size; each
    // pixel is byte for byte the full frame's (docs/command-line.md, Crop). Must lie inside
    // the frame (std::invalid_argument otherwise).
    std::optional<PixelRect> crop;
};

class Renderer {
public:
    // Throws DeviceError on a build or upload failure.
    Renderer(DeviceContext& device, const Scene& scene, const RendererOptions& options = {});
    // The frame geometry refers to the renderer's own copy of the scene.
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // Renders the frame seen from camera key `key` with the scene's up vector, field of view,
    // size and sampling; `frame` (the animation frame index) seeds the sample pattern with the
    // scene's seed. Each call places everything for its own key: the result depends on no
    // earlier call. Throws DeviceError.
    Image render(const CameraKey& key, int frame = 0, FrameTiming* timing = nullptr);

    // Renders the next frames with another up vector, field of view, size and sampling, as a
    // scene that differs from this one only in those values would render them (`clrender view`
    // moves the camera without building the program or uploading the scene again). The caller
    // has checked the values as the scene loader checks a scene's.
    void change_view(const Vec3& up, double fov_degrees, int width, int height, const SamplingSettings& sampling);

    // Renders a small frame of the scene's first camera key and throws it away, so that work a
    // driver does on a kernel's first launch (PoCL compiles it for the work-group size) is not
    // timed with the first real frame (the benchmark).
    void warm_up();

    // Hands back a frame's image once the caller is done with it: the next frame of the same
    // size renders into its storage instead of new memory.
    void recycle(Image&& image);

    const FeatureSet& features() const { return features_; }
    // Whether primary packets walk the BVH rather than screen-tile lists (RendererOptions::packets_walk_bvh).
    bool packets_walk_bvh() const { return bvh_packets_; }
    // How this renderer traces primary rays (render/primary_ray_path.h).
    PrimaryRays primary_rays() const {
        return !screen_tiles_ ? PrimaryRays::per_pixel : bvh_packets_ ? PrimaryRays::bvh_packets : PrimaryRays::screen_tiles;
    }
    int bands_of_last_frame() const { return bands_; }
    double build_ms() const { return build_ms_; }

    // For the stage tests: the scene's kernel arguments, and the geometry in them made relative
    // to `origin` (after construction it is relative to the first camera key's eye, the first
    // frame's origin; the stage tests give rays in scene coordinates, origin (0, 0, 0)).
    const SceneArgs& scene_args() const { return scene_args_; }
    void move_geometry_to(const Vec3& origin);

private:
    // Moves the device geometry to `origin` (the frame camera's) and places the impostors for
    // `key`, uploading what changed. Given `binned_for` (the frame's camera, with screen tiles),
    // also bins the frame's screen tiles for it into tiles_, meanwhile on another thread.
    void show(const CameraKey& key, const Vec3& origin, const FrameCamera* binned_for = nullptr);
    // Renders the frame seen by `camera`, or its `crop`, the geometry already shown for it.
    Image render_camera(const FrameCamera& camera, FrameTiming* timing, const std::optional<PixelRect>& crop);
    // Renders the columns `region` names of rows [first_row, first_row + rows) of the frame into
    // `rows_image`, whose row 0 is the frame's row region.y0 and which is as wide as the frame;
    // returns the kernel time in ms.
    double render_band(const ClrCamera& camera, const PixelRect& region, int first_row, int rows, Image& rows_image);
    // Renders `region` of the frame in bands (band_sizer_ started for this frame) into
    // `rows_image` (see render_band); returns the summed kernel time in ms.
    double render_bands(const ClrCamera& camera, const PixelRect& region, Image& rows_image);
    void reserve_pixels(std::size_t bytes);
    // Bytes the kernel writes per pixel, and where it writes them in `image`.
    std::size_t pixel_bytes() const { return features_.float_output ? 4 * sizeof(float) : 4; }
    std::uint8_t* kernel_pixels(Image& image) const;
    // Bins the frame for `camera` into tiles_, unless show() did, and uploads the lists; where
    // the packets walk the BVH, uploads tiles without lists.
    const ScreenTiles& upload_screen_tiles(const FrameCamera& camera);
    void upload_geometry();
    cl::Buffer upload_triangle_ties() const;  // SceneArgs::triangle_ties

    DeviceContext& device_;
    Scene scene_;  // the renderer's own copy (images are shared)
    FrameGeometry frame_;  // scene_ as the current frame shows it: impostors placed for its key
    CompiledScene compiled_;  // frame_'s device form, without texels once they are uploaded
    bool screen_tiles_ = true;
    bool bvh_packets_ = false;  // with screen_tiles_: the packets walk the BVH, the tiles hold no lists
    Vec3 origin_;  // the scene point at device (0, 0, 0)
    bool uploaded_ = false;  // the device holds frame_ relative to origin_ (false after a failed upload)
    FeatureSet features_;
    cl::Program program_;
    TypedKernel<RenderPacketsSignature> render_packets_;  // with screen tiles
    TypedKernel<RenderSignature> render_;                 // without
    TileArgs tile_args_;  // the last frame's screen tiles
    // The last frame's screen tiles, binned frame after frame into the same arrays.
    ScreenTileBinner binner_;
    ScreenTiles tiles_;
    bool tiles_binned_ = false;  // tiles_ binned by show() for the next render_camera()
    // The texel buffer's host memory (CL_MEM_USE_HOST_PTR): alive and unwritten as long as
    // scene_args_.texels, which is declared after it and so released before it.
    PageAlignedVector<std::uint8_t> texel_storage_;
    SceneArgs scene_args_;  // the scene's buffers on the device
    MeshTrees mesh_trees_;  // built once; each frame's BVH joins them (render/scene_bvh.h)
    Bvh bvh_;
    std::vector<ClrBvhNode> device_bvh_nodes_;  // bvh_ relative to origin_, as last uploaded
    cl::Buffer pixels_;
    std::vector<std::uint8_t> spare_pixels_;  // a recycled image's storage (see recycle())
    bool render_in_place_ = false;  // the kernel writes into the image's own storage (CPU devices)
    std::size_t pixels_capacity_ = 0;
    double build_ms_ = 0;
    std::size_t max_buffer_bytes_ = 0;
    BandSizer band_sizer_;
    int fixed_band_rows_ = 0;
    std::function<void()> between_bands_;
    std::function<void(double)> band_done_;
    std::optional<PixelRect> crop_;
    int bands_ = 1;
};

}  // namespace clr
