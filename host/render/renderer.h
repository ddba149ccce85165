// Renders frames of one scene on one OpenCL device. Construction builds the program for the
// scene's feature set and uploads the scene buffers once; each frame then only changes the
// camera.
#pragma once

#include <functional>
#include <optional>
#include <vector>
#include <string>

#include "device/device_context.h"
#include "render/band_sizer.h"
#include "render/bvh.h"
#include "render/compiled_scene.h"
#include "scene/scene.h"

namespace clr {

struct RendererOptions {
    std::string kernel_dir;                // read kernels from here instead of the embedded copies
    std::optional<FeatureSet> features;    // compile these instead of the scene's own (tests)
    // Largest pixel buffer to allocate on the device, in bytes; 0: the device's own limit.
    // No band is larger (see render_frame()).
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
    // Intersect and shade in double (the device needs cl_khr_fp64; DeviceError otherwise).
    bool double_precision = false;
};

struct FrameTiming {
    double kernel_ms = 0;  // device time of the render kernel (OpenCL profiling events)
    double total_ms = 0;   // wall time from enqueue to the finished image in host memory
};

class Renderer {
public:
    // Throws DeviceError on a build or upload failure.
    Renderer(DeviceContext& device, const Scene& scene, const RendererOptions& options = {});

    // Renders the frame seen from camera key `key` with the scene's up vector, field of view
    // and size. The scene's coordinates are first made relative to the key's eye (see
    // compile_scene), so float32 precision does not depend on where the scene lies.
    // `frame` (the animation frame index) seeds the sample pattern with the scene's seed.
    Image render_view(const CameraKey& key, FrameTiming* timing = nullptr, int frame = 0);

    // Renders one frame seen by `camera`, given in the renderer's current coordinates
    // (origin() subtracted; (0, 0, 0) until render_view() moves it). Its width and height set
    // the image size. Impostors stay placed as for the last render_view() (at first: for the
    // scene's first camera key).
    Image render_frame(const ClrCamera& camera, FrameTiming* timing = nullptr);

    // Hands back a frame's image once the caller is done with it: the next frame of the same
    // size renders into its storage instead of new memory.
    void recycle(Image&& image);

    // Makes device coordinates relative to `origin`, re-uploading the geometry if it moved.
    void set_origin(const Vec3& origin);
    const Vec3& origin() const { return origin_; }

    const FeatureSet& features() const { return features_; }
    int bands_of_last_frame() const { return bands_; }
    double build_ms() const { return build_ms_; }

    // For the stage tests: the scene's kernel arguments, bound from argument `first` on in the
    // order of CLR_SCENE_PARAMS (spheres, billboards, texels, info).
    void bind_scene(cl::Kernel& kernel, int first) const;
    static constexpr int kSceneArgs = 6;  // arguments bind_scene() sets

private:
    // Renders rows [first_row, first_row + rows) into `image`; returns the kernel time in ms.
    double render_band(const ClrCamera& camera, int first_row, int rows, Image& image);
    // Renders every row of `image` in bands (band_sizer_ started for this frame); returns the
    // summed kernel time in ms.
    double render_bands(const ClrCamera& camera, Image& image);
    void reserve_pixels(std::size_t bytes);
    ScreenTiles upload_screen_tiles(const ClrCamera& camera);
    void upload_geometry();
    void face_impostors(const CameraKey& key);
    // What the screen tiles and the BVH see: the scene, with its impostors as placed billboards.
    const Scene& geometry() const { return scene_.impostors.empty() ? scene_ : placed_; }

    DeviceContext& device_;
    Scene scene_;  // the geometry, for binning each frame's screen tiles (images are shared)
    Scene placed_;  // scene_ with its impostors placed as billboards (unused without impostors)
    CompiledScene compiled_;  // its device form, without texels once they are uploaded
    bool screen_tiles_ = true;
    Vec3 origin_;
    FeatureSet features_;
    ClrSceneInfo info_{};
    cl::Program program_;
    cl::Kernel render_kernel_;  // render_packets or render
    cl::Buffer tile_offsets_, tile_items_, tile_nearest_, tile_rows_;
    int tiles_x_ = 0;
    cl::Buffer spheres_, billboards_, texels_;
    Bvh bvh_;
    cl::Buffer bvh_nodes_, bvh_items_;
    cl::Buffer pixels_;
    std::vector<std::uint8_t> spare_pixels_;  // a recycled image's storage (see recycle())
    bool render_in_place_ = false;  // the kernel writes into the image's own storage (CPU devices)
    std::size_t pixels_capacity_ = 0;
    double build_ms_ = 0;
    std::size_t max_buffer_bytes_ = 0;
    BandSizer band_sizer_;
    int fixed_band_rows_ = 0;
    std::function<void()> between_bands_;
    int bands_ = 1;
};

}  // namespace clr
