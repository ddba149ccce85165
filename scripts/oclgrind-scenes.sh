#!/usr/bin/env bash
# Writes small scenes into folder $1 that between them switch on every kernel feature
# (host/render/feature_set.h): spheres only, flat and textured billboards, transparent
# texels, sun and shadows, mirrors (sphere and billboard), a BVH, impostors, meshes (lit,
# mirrored and flat), planes and point lights (the fall 2019 format), an empty scene, a camera inside a sphere. Images come from scenes/demo (cutout.png has transparent texels).
# scripts/oclgrind.sh and scripts/second-opencl.sh render them.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="$1"
demo="$root/scenes/demo"
mkdir -p "$out"

camera='"eye": [0, 1, 12], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60, "width": 48, "height": 32'
ball='{"center": [-2, 0, 0], "radius": 1.5, "ambient": [0.9, 0.3, 0.2]}'
ball2='{"center": [2.5, 0.5, -2], "radius": 2, "ambient": [0.2, 0.6, 0.9]}'
mirror_ball='{"center": [0.5, -1, 3], "radius": 1, "ambient": [0, 0, 0], "IsMirror": 1}'
flat='{"UpperLeft": [-6, 5, -6], "LowerLeft": [-6, -4, -6], "UpperRight": [6, 5, -6], "ambient": [0.3, 0.8, 0.3]}'
backdrop="{\"UpperLeft\": [-9, 6, -8], \"LowerLeft\": [-9, -5, -8], \"UpperRight\": [9, 6, -8], \"filename\": \"$demo/backdrop.png\"}"
cutout="{\"UpperLeft\": [-3, 3, 2], \"LowerLeft\": [-3, -3, 2], \"UpperRight\": [3, 3, 2], \"filename\": \"$demo/cutout.png\"}"
# Seen from behind: the image shows mirrored, and a ray may graze its edge.
slanted="{\"UpperLeft\": [4, 3, 4], \"LowerLeft\": [4, -3, 4], \"UpperRight\": [1, 3, -2], \"filename\": \"$demo/checker.png\"}"
mirror_board='{"UpperLeft": [5, 4, -4], "LowerLeft": [5, -3, -4], "UpperRight": [7, 4, 2], "IsMirror": 1}'
sun='"SunLocation": [20, 30, 25]'

scene() { # name, keys after the camera, [camera keys]
    printf '{%s, %s}\n' "${3:-$camera}" "$2" > "$out/$1.json"
}

scene spheres_only "\"spheres\": [$ball, $ball2]"
scene flat_billboards "\"billboards\": [$flat, $slanted]"
scene opaque_textures "\"spheres\": [$ball], \"billboards\": [$backdrop, $slanted]"
scene transparent_texels "\"spheres\": [$ball2], \"billboards\": [$backdrop, $cutout]"
scene sun_and_shadows "$sun, \"spheres\": [$ball, $ball2], \"billboards\": [$backdrop, $cutout]"
scene only_ambient "$sun, \"OnlyAmbient\": 1, \"spheres\": [$ball], \"billboards\": [$flat]"
scene mirrors "\"MaxDepth\": 3, \"spheres\": [$ball, $mirror_ball], \"billboards\": [$backdrop, $cutout, $mirror_board]"
scene everything "$sun, \"MaxDepth\": 4, \"spheres\": [$ball, $ball2, $mirror_ball], \"billboards\": [$backdrop, $cutout, $slanted, $mirror_board, $flat]"
scene empty '"DefaultColor": [0.2, 0.3, 0.4]'
scene inside_a_sphere "$sun, \"spheres\": [$ball, $ball2]" "${camera/\"eye\": \[0, 1, 12\]/\"eye\": [-2, 0, 0]}"

# More than kBvhMinObjects objects with a sun and a mirror: secondary rays use the BVH.
many=""
for i in $(seq 0 23); do
    x=$(( i % 6 * 3 - 8 )); y=$(( i / 6 * 2 - 3 ))
    many+="{\"center\": [$x, $y, -$(( i % 3 ))], \"radius\": 0.9, \"ambient\": [0.$(( i % 9 + 1 )), 0.5, 0.4]},"
done
scene bvh "$sun, \"spheres\": [$many $mirror_ball], \"billboards\": [$backdrop, $cutout]"

# Meshes: a faceted cube (no normals) and a smooth octahedron (a normal at every corner), lit
# with shadows, one cube a mirror; and flat.
printf 'v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n%s\n' \
    'f 1 2 3 4
f 5 8 7 6
f 1 5 6 2
f 4 3 7 8
f 1 4 8 5
f 2 6 7 3' > "$out/cube.obj"
printf 'v 1 0 0\nv -1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv 0 0 -1\n%s\n%s\n' \
    'vn 1 0 0
vn -1 0 0
vn 0 1 0
vn 0 -1 0
vn 0 0 1
vn 0 0 -1' \
    'f 1//1 3//3 5//5
f 3//3 2//2 5//5
f 2//2 4//4 5//5
f 4//4 1//1 5//5
f 3//3 1//1 6//6
f 2//2 3//3 6//6
f 4//4 2//2 6//6
f 1//1 4//4 6//6' > "$out/octahedron.obj"
cube='{"filename": "cube.obj", "position": [-2.5, -1, 0], "scale": [1.5, 1, 1]}'
octahedron='{"filename": "octahedron.obj", "position": [2, 0.5, 1], "scale": 2, "ambient": [0.9, 0.8, 0.2]}'
mirror_cube='{"filename": "cube.obj", "position": [0, -3, -3], "scale": [6, 0.5, 2], "IsMirror": 1}'
scene meshes "$sun, \"MaxDepth\": 2, \"spheres\": [$ball2], \"billboards\": [$backdrop], \"obj\": [$cube, $octahedron, $mirror_cube]"
scene flat_meshes "\"obj\": [$cube, $octahedron]"
# The sun alone with a BVH: the lanes' shadow rays walk it together (kernels/packet/shadows16.cl),
# through transparent texels too.
scene sun_packets "$sun, \"spheres\": [$many $ball2], \"billboards\": [$backdrop, $cutout], \"obj\": [$cube, $octahedron]"

# The fall 2019 format: spheres and planes with Blinn-Phong materials, two point lights, a
# mirror share; with a billboard (unlit) and a mesh (the default material) beside them.
surfaces='"surfaces": [
  {"type": "sphere", "center": [-2, 0, 0], "radius": 1.5, "ambient": [0.2, 0.1, 0.1], "diffuse": [0.7, 0.3, 0.2],
   "specular": [0.8, 0.8, 0.8], "phong_exponent": 30, "mirror": [0.3, 0.3, 0.3]},
  {"type": "plane", "point": [0, -1.5, 0], "normal": [0, 1, 0], "ambient": [0.1, 0.1, 0.1], "diffuse": [0.5, 0.5, 0.5]},
  {"type": "plane", "point": [0, 0, -8], "normal": [0.1, 0, 1], "ambient": [0.05, 0.05, 0.1],
   "diffuse": [0.3, 0.3, 0.6], "specular": [0.2, 0.2, 0.2], "phong_exponent": 0}],
  "lights": [{"position": [6, 8, 6], "color": [0.7, 0.7, 0.7]}, {"position": [-8, 4, 2], "color": [0.4, 0.1, 0.1]}]'
scene lights_and_planes "\"MaxDepth\": 2, $surfaces, \"billboards\": [$flat], \"obj\": [$octahedron]"

# Impostors: upright views, a free-facing single picture, a flat colour; two frames.
cat > "$out/impostors.json" <<EOF
{"eyeLocations": [[0, 1, 12], [6, 2, 9]], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60,
 "width": 48, "height": 32, $sun, "MaxDepth": 2,
 "spheres": [$ball, $mirror_ball], "billboards": [$backdrop],
 "clrender": {
   "frames": 2,
   "view_sets": {"tree": [{"filename": "$demo/cutout.png", "direction": [0, 0, 1]},
                          {"filename": "$demo/checker.png", "direction": [1, 0, 0]}]},
   "impostors": [
     {"center": [2, 0, 1], "width": 2, "height": 3, "views": "tree"},
     {"center": [-3, 2, -1], "width": 2, "height": 2, "facing": "free", "filename": "$demo/cutout.png"},
     {"center": [0, -2, 2], "width": 1, "height": 1, "ambient": [1, 0.5, 0]}
   ]}}
EOF
