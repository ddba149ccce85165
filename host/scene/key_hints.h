// The likeliest mistaken keys of a scene file, each with the hint that fixes it
// (docs/scene-format.md, Warnings): keys spelt too differently from the right one for a
// spelling suggestion ("fov" for "fov_angle", "image" for "filename"), and clrender's own
// keys written at the top level instead of under "clrender".
#pragma once

#include "scene/json_reader.h"

namespace clr {

void hint_scene_keys(ObjectReader& scene);
void hint_extension_keys(ObjectReader& extensions);  // the "clrender" object
void hint_sphere_keys(ObjectReader& sphere);
void hint_billboard_keys(ObjectReader& billboard);
void hint_mesh_keys(ObjectReader& mesh);  // an "obj" object
void hint_impostor_keys(ObjectReader& impostor);

}  // namespace clr
