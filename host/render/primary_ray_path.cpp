#include "render/primary_ray_path.h"

namespace clr {

bool prefers_bvh_packets(std::size_t triangles, bool clips) { return triangles >= kPacketBvhMinTriangles && !clips; }

const char* primary_rays_name(PrimaryRays way) {
    switch (way) {
        case PrimaryRays::screen_tiles: return "screen tiles";
        case PrimaryRays::bvh_packets: return "BVH packets";
        case PrimaryRays::per_pixel: return "per pixel";
    }
    return "per pixel";
}

bool traces_per_pixel(cl_device_type type) { return (type & CL_DEVICE_TYPE_GPU) != 0 && (type & CL_DEVICE_TYPE_CPU) == 0; }

}  // namespace clr
