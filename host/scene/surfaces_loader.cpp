#include "scene/surfaces_loader.h"

#include <array>
#include <cmath>
#include <string>

#include "scene/mesh_loader.h"
#include "scene/obj_text_checks.h"
#include "scene/value_ranges.h"

namespace clr {
namespace {

// Phong exponents above this make every highlight a single point: a typo, not a material.
constexpr double kMaxPhongExponent = 1e6;

// A material colour: finite, each channel within +-kMaxMaterialColor (far from float's
// overflow; values outside [0, 1] are kept as a scene's colours are).
Color read_coefficient(const Node& node) {
    const Color colour = node.color();
    for (double channel : {colour.x, colour.y, colour.z}) {
        if (std::fabs(channel) > kMaxMaterialColor)
            node.fail("each channel must be from " + number_text(-kMaxMaterialColor) + " to " +
                      number_text(kMaxMaterialColor) + ", got " + number_text(channel));
    }
    return colour;
}

// The index of `material` in the scene's list, added when new.
std::uint32_t material_index(Scene& scene, const Material& material) {
    for (std::size_t i = 0; i < scene.materials.size(); ++i)
        if (scene.materials[i] == material) return static_cast<std::uint32_t>(i);
    scene.materials.push_back(material);
    return static_cast<std::uint32_t>(scene.materials.size() - 1);
}

// The Blinn-Phong keys of a surface; `ambient` is required, the others default to zero.
std::uint32_t read_material(ObjectReader& fields, Scene& scene, Color& ambient) {
    ambient = read_coefficient(fields.required("ambient"));
    Material material;
    if (const auto diffuse = fields.optional("diffuse")) material.diffuse = read_coefficient(*diffuse);
    if (const auto specular = fields.optional("specular")) material.specular = read_coefficient(*specular);
    if (const auto mirror = fields.optional("mirror")) material.mirror = read_coefficient(*mirror);
    if (const auto exponent = fields.optional("phong_exponent")) {
        material.phong_exponent = exponent->number();
        if (material.phong_exponent < 0 || material.phong_exponent > kMaxPhongExponent)
            exponent->fail("phong_exponent must be from 0 to " + number_text(kMaxPhongExponent) + ", got " +
                           number_text(material.phong_exponent));
    }
    return material_index(scene, material);
}

void read_sphere_surface(ObjectReader& fields, Scene& scene) {
    Sphere sphere;
    sphere.center = read_position(fields.required("center"));
    sphere.radius = read_length(fields.required("radius"));
    sphere.material = read_material(fields, scene, sphere.ambient);
    scene.spheres.push_back(sphere);
}

void read_plane_surface(ObjectReader& fields, Scene& scene) {
    if (scene.planes.size() == kMaxPlanes)
        fields.node().fail("a scene may have at most " + std::to_string(kMaxPlanes) +
                           " planes: every ray tests every plane (a plane has no bounds)");
    Plane plane;
    plane.point = read_position(fields.required("point"));
    const Node normal = fields.required("normal");
    const Vec3 n = normal.vec3();
    const double n_length = length(n);
    // Normalised in double: any length the doubles can square is a direction.
    if (!(n_length > 0) || !std::isfinite(n_length)) normal.fail("normal must be a non-zero direction");
    plane.normal = n / n_length;
    plane.material = read_material(fields, scene, plane.ambient);
    scene.planes.push_back(plane);
}

// A triangle: "vertices", three positions, as a mesh of one triangle.
void read_triangle_surface(ObjectReader& fields, Scene& scene) {
    const Node vertices = fields.required("vertices");
    const std::vector<Node> elements = vertices.elements();
    if (elements.size() != 3)
        vertices.fail("vertices must be 3 positions [[x, y, z], [x, y, z], [x, y, z]], got " +
                      std::to_string(elements.size()));
    std::array<Vec3, 3> corners;
    for (int k = 0; k < 3; ++k) corners[k] = read_position(elements[k]);
    Mesh mesh;
    mesh.filename = "triangle";
    mesh.surface_triangle = true;
    mesh.material = read_material(fields, scene, mesh.ambient);
    add_triangle(scene, mesh, corners, vertices);
}

// A mesh: an OBJ file placed as an `obj` object is ("filename", "position", "scale"), read
// once the whole scene is valid.
PendingMesh read_mesh_surface(ObjectReader& fields, const Node& node, Scene& scene) {
    PendingMesh pending = read_mesh_placement(fields, node);
    pending.mesh.material = read_material(fields, scene, pending.mesh.ambient);
    pending.ambient_given = true;
    return pending;
}

void read_surface(const Node& node, Scene& scene, std::vector<PendingMesh>& meshes) {
    ObjectReader fields(node, "surface");
    const Node type = fields.required("type", "\"sphere\", \"plane\", \"triangle\" or \"mesh\"");
    const std::string kind = type.string();
    if (kind == "sphere") {
        read_sphere_surface(fields, scene);
    } else if (kind == "plane") {
        read_plane_surface(fields, scene);
    } else if (kind == "triangle") {
        read_triangle_surface(fields, scene);
    } else if (kind == "mesh") {
        meshes.push_back(read_mesh_surface(fields, node, scene));
    } else {
        type.fail("surface type must be \"sphere\", \"plane\", \"triangle\" or \"mesh\" (got " + type.shown() + ")");
    }
    fields.warn_about_unknown_keys();
}

void read_light(const Node& node, Scene& scene) {
    ObjectReader fields(node, "light");
    PointLight light;
    light.position = read_position(fields.required("position"));
    light.color = read_coefficient(fields.required("color"));
    fields.warn_about_unknown_keys();
    scene.lights.push_back(light);
}

}  // namespace

std::vector<PendingMesh> read_surfaces_and_lights(ObjectReader& file, Scene& scene) {
    std::vector<PendingMesh> meshes;
    if (const auto surfaces = file.optional("surfaces")) {
        for (const Node& surface : surfaces->elements()) read_surface(surface, scene, meshes);
    }
    if (const auto lights = file.optional("lights")) {
        const std::vector<Node> elements = lights->elements();
        if (elements.size() > kMaxLights)
            lights->fail("a scene may have at most " + std::to_string(kMaxLights) + " lights, this one has " +
                         std::to_string(elements.size()));
        if (scene.has_sun)
            lights->fail("'lights' (point lights with Blinn-Phong materials) and 'SunLocation' are two lighting "
                         "models; a scene uses one of them");
        for (const Node& light : elements) read_light(light, scene);
    }
    return meshes;
}

}  // namespace clr
