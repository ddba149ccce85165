// Which optional code paths the kernels compile in for a scene. A scene pays only for what
// it uses: without billboards no billboard loop, without transparent texels no alpha test,
// without a sun no shadow rays, without mirrors no reflection path.
#pragma once

#include <string>

#include "scene/scene.h"

namespace clr {

// Scenes with secondary rays and more objects than this trace them through a BVH.
constexpr std::size_t kBvhMinObjects = 16;

struct FeatureSet {
    bool spheres = false;      // at least one sphere
    bool billboards = false;   // at least one billboard
    bool triangles = false;    // at least one mesh triangle
    // Hits on shared mesh edges and corners settled on one triangle (Scene::triangle_ties): where
    // the triangles there can shade differently (lit, mirrors, or `triangle` surfaces of
    // different colours sharing corners).
    bool triangle_ties = false;
    bool planes = false;       // at least one plane (unbounded: outside the BVH and the tiles)
    bool lights = false;       // Blinn-Phong point lights (the fall 2019 format), with shadow rays
    bool clip = false;         // near/far clip depths for primary rays (the 2025 WebGL scenes)
    bool textures = false;     // a billboard shows an image
    bool alpha = false;        // a shown image has a texel with alpha below 255
    bool sun = false;          // sun lighting with shadow rays
    bool mirrors = false;      // a mirror surface
    bool double_precision = false;  // geometry in double (--precision double), not a scene property
    bool bvh = false;          // secondary rays (shadows, mirrors) among enough objects to need a BVH
    // Pixels as float4 (linear mean colour, coverage) instead of RGBA bytes: for EXR and
    // --alpha outputs (docs/command-line.md, HDR and alpha outputs), not a scene property.
    bool float_output = false;

    // The objects that a BVH holds: spheres, billboards, impostors and triangles.
    static std::size_t bvh_objects(const Scene& scene);
    // Every scene feature on: the general kernel that every specialised variant must match
    // (in the same precision).
    static FeatureSet all();
    // The general program that can stand in for `specialised` (the same pixels: FeatureVariants
    // tests): every scene feature on, except near/far clipping, which changes how the packet
    // kernel searches (about 4x slower) and so is on only where `specialised` clips; and,
    // where `specialised` has neither mirrors nor point lights, those two: without them the
    // packet kernel takes flat colours from its intersection loop and traces a row's shadow
    // rays together (packet/shading_modes.cl), as the scene's own program would. The precision
    // and output mode are `specialised`'s. A
    // still takes it from the program store rather than compiling `specialised` (Renderer,
    // RendererOptions::general_stand_in).
    static FeatureSet general(const FeatureSet& specialised);
    static FeatureSet of(const Scene& scene);

    // The -D options, sorted and always listing every macro (0 or 1), so that equal
    // feature sets give byte-identical option strings.
    std::string build_options() const;

    bool operator==(const FeatureSet& other) const { return build_options() == other.build_options(); }
};

}  // namespace clr
