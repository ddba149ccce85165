#include "support/random_scene.h"

#include "render/device_structs.h"
#include "support/scene_builder.h"

namespace clr::testing {
namespace {

class Random {
public:
    explicit Random(std::uint32_t seed) : engine_(seed) {}
    double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(engine_); }
    int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(engine_); }
    Vec3 point(double half_size) { return {uniform(-half_size, half_size), uniform(-half_size, half_size), uniform(-half_size, half_size)}; }
    Vec3 direction() {
        for (;;) {
            Vec3 v = point(1);
            double len2 = dot(v, v);
            if (len2 > 1e-4 && len2 <= 1) return v / std::sqrt(len2);
        }
    }
    Color color() { return {uniform(0, 1), uniform(0, 1), uniform(0, 1)}; }

private:
    std::mt19937 engine_;
};

// A 7x5 image (odd sizes, so texel edges fall at awkward coordinates) whose texels are
// transparent in a diagonal pattern.
std::shared_ptr<Image> make_holey_image(Random& random) {
    std::uint8_t base = static_cast<std::uint8_t>(random.integer(0, 200));
    return make_image(7, 5, [base](int col, int row) {
        std::uint8_t alpha = (col + 2 * row) % 3 == 0 ? 0 : 255;
        return std::array<std::uint8_t, 4>{static_cast<std::uint8_t>(base + col * 7), static_cast<std::uint8_t>(row * 50),
                                           static_cast<std::uint8_t>(255 - base), alpha};
    });
}

}  // namespace

Scene make_random_scene(std::uint32_t seed, int spheres, int billboards) {
    Random random(seed);
    Scene scene = make_scene({0, 0, 30}, {0, 0, 0}, {0, 1, 0}, 60, 16, 16);
    for (int i = 0; i < spheres; ++i)
        scene.spheres.push_back(make_sphere(random.point(10), random.uniform(0.2, 3), random.color()));
    for (int i = 0; i < billboards; ++i) {
        Vec3 corner = random.point(10);
        Vec3 edge_a = random.direction() * random.uniform(0.5, 8);
        Vec3 edge_b = random.direction() * random.uniform(0.5, 8);
        if (length(cross(edge_a, edge_b)) < 0.1 * length(edge_a) * length(edge_b)) edge_b = cross(edge_a, random.direction());
        auto image = i % 2 == 0 ? make_holey_image(random) : nullptr;
        scene.billboards.push_back(make_billboard(corner, corner + edge_b, corner + edge_a, random.color(), image));
    }
    return scene;
}

Scene make_sunlit_mirror_scene() {
    Scene scene = make_random_scene(77, 8, 8);
    scene.camera_path = {{{3, 5, 30}, {0, 0, 0}}};
    scene.width = 90;
    scene.height = 61;
    scene.sampling.samples_per_pixel = 4;
    scene.has_sun = true;
    scene.sun_location = {20, 40, 30};
    scene.spheres[0].is_mirror = true;
    scene.spheres[1].is_mirror = true;
    scene.billboards[1].is_mirror = true;
    return scene;
}

std::vector<reference::Ray> make_random_rays(const Scene& scene, std::uint32_t seed, int count) {
    Random random(seed ^ 0x9e3779b9u);
    std::vector<reference::Ray> rays;
    for (int i = 0; i < count; ++i) {
        Vec3 origin = random.point(16);
        Vec3 direction = random.direction();
        bool aimed = i % 2 == 0 && (!scene.spheres.empty() || !scene.billboards.empty());
        if (aimed) {
            int pick = random.integer(0, static_cast<int>(scene.spheres.size() + scene.billboards.size()) - 1);
            Vec3 target;
            if (pick < static_cast<int>(scene.spheres.size())) {
                const Sphere& s = scene.spheres[pick];
                target = s.center + random.direction() * (s.radius * random.uniform(0, 1.05));
            } else {
                const Billboard& b = scene.billboards[pick - scene.spheres.size()];
                target = b.upper_left + (b.upper_right - b.upper_left) * random.uniform(-0.05, 1.05) +
                         (b.lower_left - b.upper_left) * random.uniform(-0.05, 1.05);
            }
            if (length(target - origin) > 1e-3) direction = normalize(target - origin);
        }
        rays.push_back(from_device_ray(to_device_ray({origin, direction})));
    }
    return rays;
}

ClrRay to_device_ray(const reference::Ray& ray) {
    ClrRay out;
    out.origin = to_float4(ray.origin);
    out.direction = to_float4(ray.direction);
    return out;
}

reference::Ray from_device_ray(const ClrRay& ray) {
    Vec3 origin{ray.origin.s[0], ray.origin.s[1], ray.origin.s[2]};
    Vec3 direction{ray.direction.s[0], ray.direction.s[1], ray.direction.s[2]};
    // The float direction is unit length to about 1e-7; the reference wants it exact.
    return {origin, normalize(direction)};
}

}  // namespace clr::testing
