// Planes and the Blinn-Phong model with point lights (the fall 2019 format) in whole kernel
// images (kernels/kinds/plane.cl and shade.cl's phong_color() against the reference's
// kinds/plane_reference.cpp and reference/shade.cpp): spheres and planes lit by coloured
// lights with shadows and highlights, mirror shares, both sides of a plane, and one pixel
// worked out by hand from the model's formula.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "support/render_helpers.h"
#include "support/scene_builder.h"

namespace clr {
namespace {

std::uint32_t add_material(Scene& scene, const Color& diffuse, const Color& specular, double exponent,
                           const Color& mirror = {}) {
    Material material;
    material.diffuse = diffuse;
    material.specular = specular;
    material.phong_exponent = exponent;
    material.mirror = mirror;
    scene.materials.push_back(material);
    return static_cast<std::uint32_t>(scene.materials.size() - 1);
}

void add_plane(Scene& scene, const Vec3& point, const Vec3& normal, const Color& ambient, std::uint32_t material) {
    Plane plane;
    plane.point = point;
    plane.normal = normalize(normal);
    plane.ambient = ambient;
    plane.material = material;
    scene.planes.push_back(plane);
}

void add_sphere(Scene& scene, const Vec3& center, double radius, const Color& ambient, std::uint32_t material) {
    Sphere sphere = testing::make_sphere(center, radius, ambient);
    sphere.material = material;
    scene.spheres.push_back(sphere);
}

// Two spheres on a floor before a tilted wall, two coloured lights: shading, highlights of
// several exponents (0 included), and each light's shadows.
Scene lit_room() {
    Scene scene = testing::make_scene({2, 6, 22}, {0, 2, 0}, {0, 1, 0}, 50, 160, 120);
    scene.background = {0.05, 0.05, 0.1};
    const std::uint32_t shiny = add_material(scene, {0.6, 0.3, 0.3}, {0.7, 0.7, 0.7}, 40);
    const std::uint32_t matte = add_material(scene, {0.2, 0.5, 0.3}, {0, 0, 0}, 0);
    const std::uint32_t floor = add_material(scene, {0.5, 0.5, 0.5}, {0.1, 0.1, 0.1}, 0);
    const std::uint32_t wall = add_material(scene, {0.3, 0.3, 0.6}, {0.2, 0.2, 0.2}, 10);
    add_sphere(scene, {-3, 3, 0}, 3, {0.2, 0.1, 0.1}, shiny);
    add_sphere(scene, {4, 2, -3}, 2, {0.05, 0.15, 0.1}, matte);
    add_plane(scene, {0, 0, 0}, {0, 1, 0}, {0.1, 0.1, 0.1}, floor);
    add_plane(scene, {0, 0, -12}, {0.2, 0.1, 1}, {0.05, 0.05, 0.1}, wall);
    scene.lights.push_back({{10, 18, 12}, {0.7, 0.7, 0.7}});
    scene.lights.push_back({{-14, 9, 6}, {0.5, 0.2, 0.2}});
    return scene;
}

TEST(Lights, SpheresAndPlanesLitByPointLightsMatchTheReference) {
    const Scene scene = lit_room();
    testing::expect_kernels_match_reference(scene, "screen tiles");
    RendererOptions brute_force;
    brute_force.screen_tiles = false;
    testing::expect_kernels_match_reference(scene, "brute force", brute_force);
    RendererOptions double_precision;
    double_precision.double_precision = true;
    testing::expect_kernels_match_reference(scene, "double", double_precision);
    // Each light counts: without the second, the image changes.
    Scene one_light = scene;
    one_light.lights.pop_back();
    EXPECT_NE(testing::render_with_kernels(scene).rgba, testing::render_with_kernels(one_light).rgba);
}

// A still of lights and planes, whose own program the program store does not hold, may render
// with the store's general program instead: the same bytes.
TEST(Lights, TheGeneralProgramRendersTheSameBytes) { testing::expect_general_program_renders_the_same(lit_room()); }

// A mesh lit by the lights with its own material: a smooth ball and a floor of triangles.
TEST(Lights, MeshesWithAMaterialAreLitAsSpheresAre) {
    Scene scene = lit_room();
    testing::add_mesh(scene, testing::sphere_mesh({1, 4, 4}, 1.5, 20, 10, true), {0.1, 0.05, 0.2});
    testing::add_mesh(scene, testing::grid_mesh({-6, 0.01, 6}, {12, 0, 0}, {0, 0, -12}, 4, 4), {0.05, 0.1, 0.05});
    scene.meshes[0].material = add_material(scene, {0.4, 0.2, 0.7}, {0.9, 0.9, 0.9}, 60);
    scene.meshes[1].material = add_material(scene, {0.3, 0.6, 0.3}, {0, 0, 0}, 0, {0.2, 0.2, 0.2});
    testing::expect_kernels_match_reference(scene, "lit meshes");
    RendererOptions double_precision;
    double_precision.double_precision = true;
    testing::expect_kernels_match_reference(scene, "lit meshes in double", double_precision);
}

// Without lights, or with OnlyAmbient, every surface shows its ambient colour, as flat shading.
TEST(Lights, WithoutLightsSurfacesShowTheirAmbientColour) {
    Scene scene = lit_room();
    scene.only_ambient = true;
    testing::expect_kernels_match_reference(scene, "OnlyAmbient");
    const Image image = testing::render_with_kernels(scene);
    // The floor at the bottom centre: its ambient 0.1 is byte floor(0.1 * 255 + 0.5) = 26.
    EXPECT_EQ(image.at(80, 118, 0), 26);
    scene.only_ambient = false;
    scene.lights.clear();
    EXPECT_EQ(testing::render_with_kernels(scene).rgba, image.rgba);
}

// A material's mirror share adds that share of the reflected ray's colour to its own, bounce
// after bounce up to MaxDepth.
TEST(Lights, MirrorSharesReflectTheLitScene) {
    Scene scene = lit_room();
    scene.materials[scene.spheres[0].material].mirror = {0.6, 0.6, 0.6};
    scene.materials[scene.planes[1].material].mirror = {0.3, 0.3, 0.5};
    scene.max_depth = 3;
    testing::expect_kernels_match_reference(scene, "mirror shares");
    RendererOptions double_precision;
    double_precision.double_precision = true;
    testing::expect_kernels_match_reference(scene, "mirror shares in double", double_precision);
    EXPECT_NE(testing::render_with_kernels(scene).rgba, testing::render_with_kernels(lit_room()).rgba);
}

// A plane is seen from both sides, out to its horizon; the same plane with its normal the
// other way shows the same.
TEST(Planes, APlaneIsLitAlikeFromBothSidesOutToTheHorizon) {
    Scene scene = testing::make_scene({0, 1, 0}, {0, 1, -10}, {0, 1, 0}, 70, 96, 64);
    scene.background = {0, 0, 1};
    const std::uint32_t plain = add_material(scene, {0.7, 0.6, 0.5}, {0.3, 0.3, 0.3}, 8);
    add_plane(scene, {0, 0, 0}, {0, 1, 0}, {0.1, 0.1, 0.1}, plain);    // floor, seen from above
    add_plane(scene, {0, 3, 0}, {0, 1, 0}, {0.2, 0.1, 0.1}, plain);    // ceiling, seen from below
    scene.lights.push_back({{0, 2, -6}, {0.9, 0.9, 0.9}});
    testing::expect_kernels_match_reference(scene, "floor and ceiling");
    Scene flipped = scene;
    for (Plane& plane : flipped.planes) plane.normal = plane.normal * -1.0;
    EXPECT_EQ(testing::render_with_kernels(scene).rgba, testing::render_with_kernels(flipped).rgba);
}

// A plane given by a point far along it (1e8 and 1e12 away, tilted by a tenth) passing 1.4 under
// the eye: the point, rounded to float relative to the eye, put the plane units off there (a
// fifth of the pixels lit wrongly at 1e8, nearly all at 1e12). The host's offset of the plane
// from the eye, in double, places it as the reference does.
TEST(Planes, APlaneThroughAFarPointIsWhereItPassesTheEye) {
    for (const double far : {1e8, 1e12}) {
        Scene scene = testing::make_scene({0.3, 0.4, 3}, {0, -1, 0}, {0, 1, 0}, 60, 96, 72);
        const std::uint32_t plain = add_material(scene, {0.7, 0.7, 0.7}, {0.3, 0.3, 0.3}, 8);
        add_plane(scene, {far, -1 + 0.1 * far, 0}, {-0.1, 1, 0}, {0.1, 0.1, 0.1}, plain);
        add_sphere(scene, {0.2, -0.6, -0.3}, 0.4, {0.2, 0.1, 0.1}, plain);
        scene.lights.push_back({{2, 3, 4}, {0.9, 0.9, 0.9}});
        testing::expect_kernels_match_reference(scene, far == 1e8 ? "plane through a point 1e8 away"
                                                                   : "plane through a point 1e12 away");
    }
}

// One pixel by hand: the camera looks straight at a plane with a light at the eye, so at the
// centre pixel n = l = h = (0, 0, 1): colour = ambient + I (k_d + k_s).
TEST(Lights, TheCentrePixelIsTheModelWorkedOutByHand) {
    Scene scene = testing::make_scene({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 40, 33, 33);
    const std::uint32_t material = add_material(scene, {0.2, 0.1, 0.3}, {0.3, 0.05, 0.1}, 7);
    add_plane(scene, {0, 0, 0}, {0, 0, 1}, {0.1, 0.2, 0.31}, material);
    scene.lights.push_back({{0, 0, 5}, {0.5, 0.5, 0.5}});
    // (0.1 + 0.5 * 0.5, 0.2 + 0.5 * 0.15, 0.31 + 0.5 * 0.4) = (0.35, 0.275, 0.51)
    const Image image = testing::render_with_kernels(scene);
    EXPECT_EQ(image.at(16, 16, 0), 89);   // floor(0.35 * 255 + 0.5)
    EXPECT_EQ(image.at(16, 16, 1), 70);   // floor(0.275 * 255 + 0.5)
    EXPECT_EQ(image.at(16, 16, 2), 130);  // floor(0.51 * 255 + 0.5)
    // A light at the point itself lights nothing there (as the sun): the ambient colour alone.
    Scene at_point = scene;
    at_point.lights[0].position = {0, 0, 0};
    const Image lit_at_point = testing::render_with_kernels(at_point);
    EXPECT_EQ(lit_at_point.at(16, 16, 0), 26);  // floor(0.1 * 255 + 0.5)
    EXPECT_EQ(lit_at_point.at(16, 16, 2), 79);  // floor(0.31 * 255 + 0.5)
    EXPECT_EQ(testing::render_with_reference(at_point).at(16, 16, 0), 26);
    // With the light moved aside and a small sphere halfway between it and that point, the
    // light is hidden there: the ambient colour alone.
    scene.lights[0].position = {4, 0, 4};
    add_sphere(scene, {2, 0, 2}, 0.2, {0, 0, 0}, 0);
    const Image shadowed = testing::render_with_kernels(scene);
    EXPECT_EQ(shadowed.at(16, 16, 0), 26);  // floor(0.1 * 255 + 0.5)
    EXPECT_EQ(shadowed.at(16, 16, 1), 51);  // floor(0.2 * 255 + 0.5)
    EXPECT_EQ(shadowed.at(16, 16, 2), 79);  // floor(0.31 * 255 + 0.5)
}

}  // namespace
}  // namespace clr
