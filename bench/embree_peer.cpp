// The Embree peer. Choices that make it a strong, fair opponent (the figures behind them are
// in docs/benchmarks.md, The Embree peer):
// - user geometry for both spheres and billboards: Embree's built-in sphere type is slower on
//   these scenes, and a user quad applies the alpha test inside its own intersector instead
//   of paying for an intersection-filter call;
// - the same float data (compile_scene) and the same float arithmetic as clrender's kernels,
//   so that both decide the same way everywhere but on silhouettes and edges;
// - intersectors without branches, which the compiler vectorises over a packet's 16 lanes;
// - RTC_BUILD_QUALITY_HIGH, coherent 16-wide packets of 4x4 pixels (rtcIntersect16), every
//   hardware thread taking bands of rows from a shared counter;
// - mesh triangles as Embree's own triangle geometry (its fastest path), from the same float
//   corners as clrender's;
// - the output is one id per pixel, which costs less than clrender's flat shading; in a lit
//   scene also the lit colour, as clrender's kernels compute it: max(0, n.l) and a shadow ray
//   towards the sun, the 16 shadow rays of a packet traced together with rtcOccluded16.
#include "bench/embree_peer.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <thread>
#include <type_traits>

#include "bench/bench_scenes.h"
#include "bench/bench_stats.h"
#include "core/stopwatch.h"
#include "render/compiled_scene.h"

namespace clr::bench {
namespace {

constexpr unsigned kSphereGeometry = 0;
constexpr unsigned kBillboardGeometry = 1;
constexpr unsigned kTriangleGeometry = 2;
constexpr int kPacketSide = 4;  // 4x4 pixels: one rtcIntersect16 packet

// What the callbacks read: the scene exactly as clrender's kernels see it, each texel's
// alpha as a 32-bit word (so that 16 lanes fetch theirs with one gather), and the
// billboards' boxes (their corners are not in ClrBillboard, which holds only what the
// kernels need, so the boxes are computed once from the scene).
struct PeerScene {
    CompiledScene compiled;
    std::vector<std::uint32_t> texel_alpha;
    std::vector<RTCBounds> billboard_boxes;
    std::vector<std::uint32_t> triangle_mesh;  // each triangle's mesh (Scene::Triangle::mesh)
};

struct Lane {
    float ox, oy, oz, dx, dy, dz;
};

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// kernels/intersect.cl sphere_distance() in the same float operations, written without
// branches (selects instead of early returns) so that the 16 lanes of a packet vectorise.
inline float sphere_distance(const ClrSphere& sphere, const Lane& ray) {
    float cx = sphere.center_radius.s[0], cy = sphere.center_radius.s[1], cz = sphere.center_radius.s[2];
    float radius = sphere.center_radius.s[3];
    float ocx = ray.ox - cx, ocy = ray.oy - cy, ocz = ray.oz - cz;
    float b = -(ocx * ray.dx + ocy * ray.dy + ocz * ray.dz);
    float px = ocx + b * ray.dx, py = ocy + b * ray.dy, pz = ocz + b * ray.dz;
    float discriminant = radius * radius - (px * px + py * py + pz * pz);
    float c = (ocx * ocx + ocy * ocy + ocz * ocz) - radius * radius;
    float root = std::sqrt(discriminant > 0.0f ? discriminant : 0.0f);
    float q = b + std::copysign(root, b);
    float t0 = c / q, t1 = q;
    float t_near = t0 < t1 ? t0 : t1, t_far = t0 < t1 ? t1 : t0;
    float t = t_near > 0.0f ? t_near : (t_far > 0.0f ? t_far : kInfinity);
    return discriminant < 0.0f || q == 0.0f ? kInfinity : t;
}

// kernels/intersect.cl billboard_distance() and common/texture.cl billboard_texel(), also
// branch-free: the plane distance, the parallelogram's (a, b) from the dual vectors, then a
// hole wherever the texel's alpha is below 255. A lane that misses still reads a texel, at
// clamped coordinates inside the image, so that the fetch is one gather for all lanes.
template <bool kTextured>
inline float billboard_distance(const ClrBillboard& bb, const std::uint32_t* texel_alpha, const Lane& ray) {
    const float* n = bb.normal.s;
    const float* ul = bb.corner.s;
    float t = ((ul[0] - ray.ox) * n[0] + (ul[1] - ray.oy) * n[1] + (ul[2] - ray.oz) * n[2]) /
              (ray.dx * n[0] + ray.dy * n[1] + ray.dz * n[2]);
    float fx = (ray.ox - ul[0]) + t * ray.dx, fy = (ray.oy - ul[1]) + t * ray.dy, fz = (ray.oz - ul[2]) + t * ray.dz;
    float a = fx * bb.dual_a.s[0] + fy * bb.dual_a.s[1] + fz * bb.dual_a.s[2];
    float b = fx * bb.dual_b.s[0] + fy * bb.dual_b.s[1] + fz * bb.dual_b.s[2];
    bool hit = t > 0.0f && a >= 0.0f && a <= 1.0f && b >= 0.0f && b <= 1.0f;
    if (kTextured) {
        // In [0, 1], floor() is truncation; a == 1 or b == 1 clamps to the last texel.
        int col = static_cast<int>((hit ? a : 0.0f) * bb.texture_width);
        int row = static_cast<int>((hit ? b : 0.0f) * bb.texture_height);
        col = col < bb.texture_width ? col : bb.texture_width - 1;
        row = row < bb.texture_height ? row : bb.texture_height - 1;
        // A signed 32-bit index: what a vector gather takes.
        int texel = static_cast<int>(bb.texel_offset) + row * bb.texture_width + col;
        std::uint32_t alpha = texel_alpha[texel];
        hit = hit && alpha == 255;
    }
    return hit ? t : kInfinity;
}

// The structure-of-arrays fields of an RTCRayHitN packet of width n.
struct PacketView {
    PacketView(RTCRayHitN* rayhit, unsigned n) {
        RTCRayN* ray = RTCRayHitN_RayN(rayhit, n);
        RTCHitN* hit = RTCRayHitN_HitN(rayhit, n);
        org_x = &RTCRayN_org_x(ray, n, 0), org_y = &RTCRayN_org_y(ray, n, 0), org_z = &RTCRayN_org_z(ray, n, 0);
        dir_x = &RTCRayN_dir_x(ray, n, 0), dir_y = &RTCRayN_dir_y(ray, n, 0), dir_z = &RTCRayN_dir_z(ray, n, 0);
        tnear = &RTCRayN_tnear(ray, n, 0), tfar = &RTCRayN_tfar(ray, n, 0);
        geom_ids = &RTCHitN_geomID(hit, n, 0), prim_ids = &RTCHitN_primID(hit, n, 0);
        inst_ids = &RTCHitN_instID(hit, n, 0, 0);
    }
    const float *org_x, *org_y, *org_z, *dir_x, *dir_y, *dir_z, *tnear;
    float* tfar;
    unsigned *geom_ids, *prim_ids, *inst_ids;
};

constexpr unsigned kMaxLanes = 16;

// Runs `distance` for lanes [first, first + count) of the packet and records a hit where the
// lane is valid and the distance lies in the ray's (tnear, tfar). Two loops: the first only
// reads (so that texel fetches may become gathers without aliasing checks against the hit
// stores), the second updates with selects rather than branches. `Count` is
// std::integral_constant for the usual packet widths, so both loops become vector code.
template <typename Count, typename Distance>
void intersect_lanes(const RTCIntersectFunctionNArguments* args, const PacketView& p, unsigned first, Count count,
                     Distance distance) {
    float t[kMaxLanes];
    for (unsigned i = 0; i < count; ++i) {
        unsigned l = first + i;
        t[i] = distance(Lane{p.org_x[l], p.org_y[l], p.org_z[l], p.dir_x[l], p.dir_y[l], p.dir_z[l]});
    }
    const unsigned geom_id = args->geomID, prim_id = args->primID, inst_id = args->context->instID[0];
    for (unsigned i = 0; i < count; ++i) {
        unsigned l = first + i;
        bool take = args->valid[l] == -1 && t[i] > p.tnear[l] && t[i] < p.tfar[l];
        p.tfar[l] = take ? t[i] : p.tfar[l];
        p.geom_ids[l] = take ? geom_id : p.geom_ids[l];
        p.prim_ids[l] = take ? prim_id : p.prim_ids[l];
        p.inst_ids[l] = take ? inst_id : p.inst_ids[l];
    }
}

template <typename Distance>
void dispatch_lanes(const RTCIntersectFunctionNArguments* args, Distance distance) {
    PacketView packet(args->rayhit, args->N);
    switch (args->N) {
        case 16: intersect_lanes(args, packet, 0, std::integral_constant<unsigned, 16>{}, distance); break;
        case 8: intersect_lanes(args, packet, 0, std::integral_constant<unsigned, 8>{}, distance); break;
        case 4: intersect_lanes(args, packet, 0, std::integral_constant<unsigned, 4>{}, distance); break;
        case 1: intersect_lanes(args, packet, 0, std::integral_constant<unsigned, 1>{}, distance); break;
        default:  // other widths (streams), in groups of at most kMaxLanes
            for (unsigned first = 0; first < args->N; first += kMaxLanes)
                intersect_lanes(args, packet, first, std::min(kMaxLanes, args->N - first), distance);
            break;
    }
}

// The shadow rays' test (rtcOccluded16): a lane whose ray meets the object within (tnear,
// tfar) is marked occluded by setting its tfar to -inf, as Embree's own geometries do.
template <typename Distance>
void occlude_lanes(const RTCOccludedFunctionNArguments* args, Distance distance) {
    RTCRayN* rays = args->ray;
    const unsigned n = args->N;
    for (unsigned l = 0; l < n; ++l) {
        if (args->valid[l] != -1) continue;
        float& tfar = RTCRayN_tfar(rays, n, l);
        float t = distance(Lane{RTCRayN_org_x(rays, n, l), RTCRayN_org_y(rays, n, l), RTCRayN_org_z(rays, n, l),
                                RTCRayN_dir_x(rays, n, l), RTCRayN_dir_y(rays, n, l), RTCRayN_dir_z(rays, n, l)});
        if (t > RTCRayN_tnear(rays, n, l) && t < tfar) tfar = -kInfinity;
    }
}

void intersect_sphere(const RTCIntersectFunctionNArguments* args) {
    const auto* peer = static_cast<const PeerScene*>(args->geometryUserPtr);
    const ClrSphere& sphere = peer->compiled.spheres[args->primID];
    dispatch_lanes(args, [&](const Lane& ray) { return sphere_distance(sphere, ray); });
}

void intersect_billboard(const RTCIntersectFunctionNArguments* args) {
    const auto* peer = static_cast<const PeerScene*>(args->geometryUserPtr);
    const ClrBillboard& billboard = peer->compiled.billboards[args->primID];
    const std::uint32_t* texel_alpha = peer->texel_alpha.data();
    // Textured or not is the same for every lane: chosen once, outside the lane loop.
    if (billboard.flags & CLR_SURFACE_TEXTURED)
        dispatch_lanes(args, [&](const Lane& ray) { return billboard_distance<true>(billboard, texel_alpha, ray); });
    else
        dispatch_lanes(args, [&](const Lane& ray) { return billboard_distance<false>(billboard, texel_alpha, ray); });
}

void occlude_sphere(const RTCOccludedFunctionNArguments* args) {
    const auto* peer = static_cast<const PeerScene*>(args->geometryUserPtr);
    const ClrSphere& sphere = peer->compiled.spheres[args->primID];
    occlude_lanes(args, [&](const Lane& ray) { return sphere_distance(sphere, ray); });
}

void occlude_billboard(const RTCOccludedFunctionNArguments* args) {
    const auto* peer = static_cast<const PeerScene*>(args->geometryUserPtr);
    const ClrBillboard& billboard = peer->compiled.billboards[args->primID];
    const std::uint32_t* texel_alpha = peer->texel_alpha.data();
    if (billboard.flags & CLR_SURFACE_TEXTURED)
        occlude_lanes(args, [&](const Lane& ray) { return billboard_distance<true>(billboard, texel_alpha, ray); });
    else
        occlude_lanes(args, [&](const Lane& ray) { return billboard_distance<false>(billboard, texel_alpha, ray); });
}

// Boxes are padded by a relative 1e-5 so that float rounding in the box test never culls a
// hit that the float intersector above would report.
void set_padded(RTCBounds* box, const float lo[3], const float hi[3]) {
    float pad = 1e-5f * std::fmax(hi[0] - lo[0], std::fmax(hi[1] - lo[1], hi[2] - lo[2]));
    box->lower_x = lo[0] - pad, box->lower_y = lo[1] - pad, box->lower_z = lo[2] - pad;
    box->upper_x = hi[0] + pad, box->upper_y = hi[1] + pad, box->upper_z = hi[2] + pad;
}

void sphere_bounds(const RTCBoundsFunctionArguments* args) {
    const auto* peer = static_cast<const PeerScene*>(args->geometryUserPtr);
    const float* cr = peer->compiled.spheres[args->primID].center_radius.s;
    float lo[3] = {cr[0] - cr[3], cr[1] - cr[3], cr[2] - cr[3]};
    float hi[3] = {cr[0] + cr[3], cr[1] + cr[3], cr[2] + cr[3]};
    set_padded(args->bounds_o, lo, hi);
}

void billboard_bounds(const RTCBoundsFunctionArguments* args) {
    const auto* peer = static_cast<const PeerScene*>(args->geometryUserPtr);
    *args->bounds_o = peer->billboard_boxes[args->primID];
}

std::vector<RTCBounds> compute_billboard_boxes(const FrameGeometry& frame) {
    std::vector<RTCBounds> boxes;
    for (std::size_t i = 0; i < frame.billboard_count(); ++i) {
        const Billboard& bb = frame.billboard(i);
        Vec3 corners[4] = {bb.upper_left, bb.lower_left, bb.upper_right,
                           bb.lower_left + (bb.upper_right - bb.upper_left)};
        float lo[3], hi[3];
        for (int axis = 0; axis < 3; ++axis) {
            double l = corners[0][axis], h = l;
            for (const Vec3& c : corners) l = std::fmin(l, c[axis]), h = std::fmax(h, c[axis]);
            lo[axis] = static_cast<float>(l), hi[axis] = static_cast<float>(h);
        }
        RTCBounds box;
        set_padded(&box, lo, hi);
        boxes.push_back(box);
    }
    return boxes;
}

struct DeviceDeleter {
    void operator()(RTCDevice device) const { rtcReleaseDevice(device); }
};
struct SceneDeleter {
    void operator()(RTCScene scene) const { rtcReleaseScene(scene); }
};
using DevicePtr = std::unique_ptr<RTCDeviceTy, DeviceDeleter>;
using ScenePtr = std::unique_ptr<RTCSceneTy, SceneDeleter>;

void throw_on_error(RTCDevice device, const char* what) {
    RTCError error = rtcGetDeviceError(device);
    if (error != RTC_ERROR_NONE)
        throw std::runtime_error(std::string("Embree: ") + what + " failed (RTCError " + std::to_string(error) + ")");
}

void attach_user_geometry(RTCDevice device, RTCScene scene, unsigned id, unsigned count, void* user,
                          RTCBoundsFunction bounds, RTCIntersectFunctionN intersect, RTCOccludedFunctionN occluded) {
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(geometry, count);
    rtcSetGeometryUserData(geometry, user);
    rtcSetGeometryBoundsFunction(geometry, bounds, user);
    rtcSetGeometryIntersectFunction(geometry, intersect);
    rtcSetGeometryOccludedFunction(geometry, occluded);
    rtcCommitGeometry(geometry);
    rtcAttachGeometryByID(scene, geometry, id);
    rtcReleaseGeometry(geometry);  // the scene holds it now
}

// The compiled triangles as Embree's triangle geometry: three vertices of their own each (the
// same float corners the kernels read) and the index buffer 0 1 2, 3 4 5, ...
void attach_triangles(RTCDevice device, RTCScene scene, const std::vector<ClrTriangle>& triangles) {
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                  3 * sizeof(float), 3 * triangles.size()));
    auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                    3 * sizeof(unsigned), triangles.size()));
    if (!vertices || !indices) {
        rtcReleaseGeometry(geometry);
        throw_on_error(device, "allocating the triangle buffers");
        throw std::runtime_error("Embree: allocating the triangle buffers failed");
    }
    for (std::size_t i = 0; i < triangles.size(); ++i) {
        const cl_float4* corners[3] = {&triangles[i].corner0, &triangles[i].corner1, &triangles[i].corner2};
        for (int c = 0; c < 3; ++c) {
            for (int axis = 0; axis < 3; ++axis) vertices[(3 * i + c) * 3 + axis] = corners[c]->s[axis];
            indices[3 * i + c] = static_cast<unsigned>(3 * i + c);
        }
    }
    rtcCommitGeometry(geometry);
    rtcAttachGeometryByID(scene, geometry, kTriangleGeometry);
    rtcReleaseGeometry(geometry);
}

struct Float3 {
    float x, y, z;
};
inline Float3 operator+(Float3 a, Float3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Float3 operator-(Float3 a, Float3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Float3 operator*(float s, Float3 a) { return {s * a.x, s * a.y, s * a.z}; }
inline float dot3(Float3 a, Float3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Float3 xyz(const cl_float4& v) { return {v.s[0], v.s[1], v.s[2]}; }
// kernels/common/math.cl unit3() and kernels/kinds/triangle.cl edge_cross(), in the same order.
inline Float3 unit3(Float3 v) {
    float length = std::sqrt(dot3(v, v));
    return {v.x / length, v.y / length, v.z / length};
}
inline Float3 edge_cross(Float3 p, Float3 q) {
    return {p.y * q.z - p.z * q.y, p.z * q.x - p.x * q.z, p.x * q.y - p.y * q.x};
}

// kernels/common/math.cl color_to_byte().
// The clamp written as comparisons and the floor of a non-negative value as the conversion's
// truncation: the same bytes (a NaN still gives 0) without libm's fminf, fmaxf and floorf
// calls, which were most of a flat frame's shading in the peer.
inline std::uint8_t color_to_byte(float c) {
    const float clamped = c > 0.0f ? (c < 1.0f ? c : 1.0f) : 0.0f;
    return static_cast<std::uint8_t>(clamped * 255.0f + 0.5f);
}

// A shadow ray leaving a surface ignores hits nearer than this share of its origin's distance
// from (0, 0, 0): float rounding puts the point a little off the surface it lies on
// (kernels/kinds/triangle.cl, CLR_TRIANGLE_SELF_GAP, uses the same share).
constexpr float kShadowGap = 1.5e-5f;

// One frame: the object id seen through every pixel, written to ids (width * height), and
// its colour as RGB bytes (3 * width * height): flat, or in a lit scene shaded by the sun.
class FrameTracer {
public:
    FrameTracer(RTCScene scene, const ClrCamera& camera, const PeerScene& peer, int sphere_count, int billboard_count)
        : scene_(scene), camera_(camera), peer_(peer), sphere_count_(sphere_count), billboard_count_(billboard_count) {}

    void trace(std::vector<std::uint32_t>& ids, std::vector<std::uint8_t>& rgb) const {
        ids.resize(static_cast<std::size_t>(camera_.width) * camera_.height);
        rgb.resize(3 * ids.size());
        std::atomic<int> next_band{0};
        auto worker = [&] {
            for (int band = next_band++; band * kPacketSide < camera_.height; band = next_band++)
                trace_band(band * kPacketSide, ids.data(), rgb.data());
        };
        unsigned count = std::max(1u, std::thread::hardware_concurrency());
        std::vector<std::thread> threads;
        for (unsigned i = 1; i < count; ++i) threads.emplace_back(worker);
        worker();  // this thread is one of the workers
        for (std::thread& thread : threads) thread.join();
    }

private:
    // One row of 4x4 packets, starting at image row `top`.
    void trace_band(int top, std::uint32_t* ids, std::uint8_t* rgb) const {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;  // neighbouring primary rays
        for (int left = 0; left < camera_.width; left += kPacketSide) {
            RTCRayHit16 packet;
            alignas(64) int valid[16];
            fill_packet(left, top, packet, valid);
            rtcIntersect16(valid, scene_, &context, &packet);
            store_ids(left, top, packet, valid, ids);
            shade_packet(left, top, packet, valid, ids, rgb);
        }
    }

    // The rays of kernels/raygen.cl camera_ray(), in the same float operations.
    void fill_packet(int left, int top, RTCRayHit16& packet, int* valid) const {
        const float* f = camera_.forward.s;
        const float* r = camera_.right.s;
        const float* u = camera_.up.s;
        for (int lane = 0; lane < 16; ++lane) {
            int col = left + lane % kPacketSide, row = top + lane / kPacketSide;
            valid[lane] = col < camera_.width && row < camera_.height ? -1 : 0;
            float sx = 2.0f * (static_cast<float>(col) + 0.5f) / static_cast<float>(camera_.width) - 1.0f;
            float sy = 1.0f - 2.0f * (static_cast<float>(row) + 0.5f) / static_cast<float>(camera_.height);
            float dx = f[0] + sx * r[0] + sy * u[0], dy = f[1] + sx * r[1] + sy * u[1], dz = f[2] + sx * r[2] + sy * u[2];
            float inv_length = 1.0f / std::sqrt(dx * dx + dy * dy + dz * dz);
            packet.ray.org_x[lane] = camera_.eye.s[0];
            packet.ray.org_y[lane] = camera_.eye.s[1];
            packet.ray.org_z[lane] = camera_.eye.s[2];
            packet.ray.dir_x[lane] = dx * inv_length;
            packet.ray.dir_y[lane] = dy * inv_length;
            packet.ray.dir_z[lane] = dz * inv_length;
            packet.ray.tnear[lane] = 0.0f;
            packet.ray.tfar[lane] = std::numeric_limits<float>::infinity();
            packet.ray.time[lane] = 0.0f;
            packet.ray.mask[lane] = ~0u;
            packet.ray.id[lane] = 0;
            packet.ray.flags[lane] = 0;
            packet.hit.geomID[lane] = RTC_INVALID_GEOMETRY_ID;
        }
    }

    void store_ids(int left, int top, const RTCRayHit16& packet, const int* valid, std::uint32_t* ids) const {
        for (int lane = 0; lane < 16; ++lane) {
            if (!valid[lane]) continue;
            int col = left + lane % kPacketSide, row = top + lane / kPacketSide;
            unsigned geom = packet.hit.geomID[lane], prim = packet.hit.primID[lane];
            std::uint32_t id = geom == kSphereGeometry      ? sphere_id(static_cast<int>(prim))
                               : geom == kBillboardGeometry ? billboard_id(sphere_count_, static_cast<int>(prim))
                               : geom == kTriangleGeometry
                                   ? mesh_id(sphere_count_, billboard_count_,
                                             static_cast<int>(peer_.triangle_mesh[prim]))
                                   : kBackgroundId;
            ids[static_cast<std::size_t>(row) * camera_.width + col] = id;
        }
    }

    // kernels/shade.cl surface_color() for the packet's lanes: the id's colour (what clrender
    // shows flat), scaled in a lit scene on spheres and triangles by max(0, n.l), and black
    // where the shadow ray towards the sun meets anything.
    void shade_packet(int left, int top, const RTCRayHit16& packet, const int* valid, const std::uint32_t* ids,
                      std::uint8_t* rgb) const {
        const bool lit = peer_.compiled.info.lit != 0;
        float cosine[16];
        RTCRay16 shadow;
        alignas(64) int shadow_valid[16];
        bool any_shadow = false;
        for (int lane = 0; lane < 16; ++lane) {
            cosine[lane] = 1.0f;
            shadow_valid[lane] = 0;
            unsigned geom = packet.hit.geomID[lane];
            if (!valid[lane] || !lit || (geom != kSphereGeometry && geom != kTriangleGeometry)) continue;
            Float3 origin{packet.ray.org_x[lane], packet.ray.org_y[lane], packet.ray.org_z[lane]};
            Float3 direction{packet.ray.dir_x[lane], packet.ray.dir_y[lane], packet.ray.dir_z[lane]};
            Float3 point = origin + packet.ray.tfar[lane] * direction;
            Float3 normal = geom == kSphereGeometry
                                ? unit3(point - xyz(peer_.compiled.spheres[packet.hit.primID[lane]].center_radius))
                                : triangle_normal(packet.hit.primID[lane], packet.hit.u[lane], packet.hit.v[lane], direction);
            Float3 to_sun = xyz(peer_.compiled.info.sun) - point;
            float sun_distance = std::sqrt(dot3(to_sun, to_sun));
            Float3 light{to_sun.x / sun_distance, to_sun.y / sun_distance, to_sun.z / sun_distance};
            cosine[lane] = dot3(normal, light);
            if (cosine[lane] <= 0.0f) continue;  // facing away: black, no shadow ray
            shadow_valid[lane] = -1;
            any_shadow = true;
            shadow.org_x[lane] = point.x, shadow.org_y[lane] = point.y, shadow.org_z[lane] = point.z;
            shadow.dir_x[lane] = light.x, shadow.dir_y[lane] = light.y, shadow.dir_z[lane] = light.z;
            shadow.tnear[lane] = kShadowGap * (std::fabs(point.x) + std::fabs(point.y) + std::fabs(point.z));
            shadow.tfar[lane] = sun_distance;
            shadow.time[lane] = 0.0f;
            shadow.mask[lane] = ~0u;
            shadow.id[lane] = 0;
            shadow.flags[lane] = 0;
        }
        if (any_shadow) {
            RTCIntersectContext context;
            rtcInitIntersectContext(&context);
            rtcOccluded16(shadow_valid, scene_, &context, &shadow);
        }
        // A packet's lanes mostly see one object: its flat colour's bytes are made once.
        std::uint32_t flat_id = ~0u;
        std::uint8_t flat[3] = {0, 0, 0};
        for (int lane = 0; lane < 16; ++lane) {
            if (!valid[lane]) continue;
            int col = left + lane % kPacketSide, row = top + lane / kPacketSide;
            std::size_t pixel = static_cast<std::size_t>(row) * camera_.width + col;
            bool shadowed = shadow_valid[lane] && shadow.tfar[lane] < 0.0f;  // rtcOccluded16 sets -inf
            float scale = cosine[lane] <= 0.0f || shadowed ? 0.0f : cosine[lane];
            if (scale == 1.0f) {  // flat, as every lane of an unlit scene
                if (ids[pixel] != flat_id) {
                    flat_id = ids[pixel];
                    Color color = id_color(flat_id);
                    flat[0] = color_to_byte(static_cast<float>(color.x));
                    flat[1] = color_to_byte(static_cast<float>(color.y));
                    flat[2] = color_to_byte(static_cast<float>(color.z));
                }
                std::memcpy(&rgb[3 * pixel], flat, 3);
                continue;
            }
            Color color = id_color(ids[pixel]);
            rgb[3 * pixel + 0] = color_to_byte(static_cast<float>(color.x) * scale);
            rgb[3 * pixel + 1] = color_to_byte(static_cast<float>(color.y) * scale);
            rgb[3 * pixel + 2] = color_to_byte(static_cast<float>(color.z) * scale);
        }
    }

    // kernels/kinds/triangle.cl triangle_normal(), with Embree's barycentric u, v (the weights
    // of corners 1 and 2) for the corner normals' blend.
    Float3 triangle_normal(unsigned index, float u, float v, Float3 direction) const {
        const ClrTriangle& triangle = peer_.compiled.triangles[index];
        Float3 c0 = xyz(triangle.corner0);
        Float3 geometric = edge_cross(xyz(triangle.corner1) - c0, xyz(triangle.corner2) - c0);
        Float3 normal = geometric;
        if (triangle.normals >= 0) {
            const cl_float4* n = &peer_.compiled.triangle_normals[triangle.normals];
            Float3 blended = (1.0f - u - v) * xyz(n[0]) + u * xyz(n[1]) + v * xyz(n[2]);
            if (dot3(blended, blended) > 0.0f) normal = blended;
        }
        normal = unit3(normal);
        return dot3(normal, direction) > 0.0f ? -1.0f * normal : normal;
    }

    RTCScene scene_;
    ClrCamera camera_;
    const PeerScene& peer_;
    int sphere_count_;
    int billboard_count_;
};

}  // namespace

// Declared in this order so that the scene goes before the device that made it, and the
// callbacks' data outlives both.
struct EmbreePeer::State {
    PeerScene peer;
    DevicePtr device;
    ScenePtr scene;
    std::optional<FrameTracer> tracer;
};

EmbreePeer::EmbreePeer(const Scene& scene, const ClrCamera& camera) : state_(std::make_unique<State>()) {
    const Stopwatch stopwatch;
    PeerScene& peer = state_->peer;
    FrameGeometry frame(scene);
    frame.place_impostors(scene.camera_path.front());  // clrender's frames place them likewise
    peer.compiled = compile_scene(frame);
    peer.billboard_boxes = compute_billboard_boxes(frame);
    for (std::size_t i = 3; i < peer.compiled.texels.size(); i += 4) peer.texel_alpha.push_back(peer.compiled.texels[i]);
    for (const Triangle& triangle : scene.triangles) peer.triangle_mesh.push_back(triangle.mesh);

    state_->device.reset(rtcNewDevice(nullptr));
    if (!state_->device) throw std::runtime_error("Embree: rtcNewDevice failed");
    RTCDevice device = state_->device.get();
    state_->scene.reset(rtcNewScene(device));
    RTCScene rtc_scene = state_->scene.get();
    rtcSetSceneBuildQuality(rtc_scene, RTC_BUILD_QUALITY_HIGH);
    if (!peer.compiled.spheres.empty())
        attach_user_geometry(device, rtc_scene, kSphereGeometry, static_cast<unsigned>(peer.compiled.spheres.size()),
                             &peer, sphere_bounds, intersect_sphere, occlude_sphere);
    if (!peer.compiled.billboards.empty())
        attach_user_geometry(device, rtc_scene, kBillboardGeometry,
                             static_cast<unsigned>(peer.compiled.billboards.size()), &peer, billboard_bounds,
                             intersect_billboard, occlude_billboard);
    if (!peer.compiled.triangles.empty()) attach_triangles(device, rtc_scene, peer.compiled.triangles);
    rtcCommitScene(rtc_scene);
    throw_on_error(device, "building the scene");
    build_ms_ = stopwatch.elapsed_ms();
    state_->tracer.emplace(rtc_scene, camera, peer, static_cast<int>(scene.spheres.size()),
                           static_cast<int>(peer.compiled.billboards.size()));
}

EmbreePeer::~EmbreePeer() = default;

double EmbreePeer::trace_frame() {
    const Stopwatch stopwatch;
    state_->tracer->trace(ids_, rgb_);
    double ms = stopwatch.elapsed_ms();
    throw_on_error(state_->device.get(), "tracing");
    return ms;
}

std::string embree_version() { return std::string("Embree ") + RTC_VERSION_STRING; }

}  // namespace clr::bench
