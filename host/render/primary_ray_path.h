// Which way a device traces primary rays by default (RendererOptions::per_pixel): one
// work-item a pixel through the BVH on a GPU, whose lanes each follow one ray, and 16-ray packets
// in screen tiles on a CPU, whose vector units take a packet (docs/opencl-devices.md, A GPU).
#pragma once

#include <cstddef>

#include "device/opencl.h"

namespace clr {

// From this many triangles on, a CPU's packets of primary rays walk the BVH instead of lists
// binned into screen tiles (RendererOptions::packets_walk_bvh): binning every triangle each
// frame then costs more than the walk saves (docs/benchmarks.md, Primary packets through the
// BVH, has the figures this comes from).
constexpr std::size_t kPacketBvhMinTriangles = 200000;

// Whether a scene of `triangles` triangles, clipped to near and far depths or not
// (`clips`), has its primary packets walk the BVH: from kPacketBvhMinTriangles on, and not
// where the camera clips, whose rays start each at its own depth and search the tile lists
// lane by lane (packet/intersect_packet.cl).
bool prefers_bvh_packets(std::size_t triangles, bool clips);

// How a renderer traces its primary rays: 16-ray packets over lists binned into screen tiles,
// 16-ray packets through the BVH, or one work-item a pixel (through the BVH where one is built).
enum class PrimaryRays { screen_tiles, bvh_packets, per_pixel };

// The way's name, as --stats reports it: "screen tiles", "BVH packets", "per pixel".
const char* primary_rays_name(PrimaryRays way);

// Whether a device of `type` (CL_DEVICE_TYPE) traces per pixel: one that says it is a GPU and
// not a CPU. Oclgrind's simulator says it is every type at once and runs one work-item at a
// time; it keeps the packets, which are the kernels it is there to check.
bool traces_per_pixel(cl_device_type type);

}  // namespace clr
