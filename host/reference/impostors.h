// Reference impostors: billboards that turn to face the camera and show the view taken from
// closest to the eye (docs/scene-format.md, "Impostors: billboards that face the camera").
// Written from that section alone, in double precision. Each frame, an impostor becomes an
// ordinary billboard; everything after that (hits, transparency, shadows, mirrors) is the
// billboard code's.
#pragma once

#include "reference/reference.h"

namespace clr::reference {

// The index of the view the impostor shows for this camera, or -1 when it has no views. The
// score of a view is e . direction with e = unit(eye - centre) (the camera's w when the eye is
// at the centre); the highest score wins, and of exactly equal scores the first in the list.
int chosen_view(const Impostor& impostor, const CameraFrame& camera);

// The billboard the impostor becomes for this camera: its front normal points towards the eye
// and its top row towards `up` (the scene's up vector, any length). It shows the chosen view's
// image, or its flat `ambient` colour when it has no views, and is never a mirror.
Billboard place_impostor(const Impostor& impostor, const CameraFrame& camera, const Vec3& up);

// A copy of the scene for this camera whose billboards are the scene's own followed by its
// impostors, placed, in order; `impostors` is empty in the copy.
Scene with_impostors_placed(const Scene& scene, const CameraFrame& camera);

}  // namespace clr::reference
