// A digest of everything in a scene that decides its pixels, for the PNG description
// (docs/command-line.md, PNG metadata): the scene file's text, the -D arguments as given, and
// the bytes of every image file it shows (a file's bytes decide its pixels, and hashing them
// costs a fraction of hashing the decoded pixels: 16 MB of PNGs against 69 MB of texels for
// the forest). Texts, not the parsed document: writing a document out recurses once per level
// of nesting, and a valid scene may nest millions of levels deep in a key clrender ignores. Two renders whose descriptions
// match are of the same scene even when a colour or a texture was edited in between, so that
// --resume, --join and --assemble never take an earlier render's file for this one's. The
// scene's folder and file names are not in it: the same scene elsewhere has the same digest.
#pragma once

#include <string>

#include <vector>

#include "scene/scene.h"
#include "scene/scene_overrides.h"

namespace clr {

// 16 lower-case hex digits (the first 64 bits of a SHA-256): a label that tells renders
// apart, not a key that must resist forgery. "" when libcrypto refuses to hash.
std::string scene_digest(const std::string& scene_text, const std::vector<SceneOverride>& overrides, const Scene& scene);

}  // namespace clr
