// Scenes as JSON for the loader's tests: the smallest valid scene, objects to add to it,
// and checks of the error or warnings a user would see.
#pragma once

#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "scene/scene_loader.h"
#include "support/temp_folder.h"

namespace clr::testing::scene_json {

using Json = nlohmann::json;

// The smallest valid scene; tests add or change keys.
Json minimal_scene();
Json sphere(const Json& radius = 1);
Json flat_billboard();

Scene parse(const Json& scene, const LoadOptions& options = {});

// Passes when parsing `text` throws a SceneError at `location` whose detail contains
// `fragment`; otherwise says what happened instead.
::testing::AssertionResult TextFailsAt(const std::string& text, const std::string& location,
                                       const std::string& fragment, const LoadOptions& options = {},
                                       const std::string& path = "test.json");
::testing::AssertionResult FailsAt(const Json& scene, const std::string& location, const std::string& fragment,
                                   const LoadOptions& options = {});

bool has_warning(const Scene& scene, const std::string& text);
std::string all_warnings(const Scene& scene);

// Writes a binary PPM (P6) of `width` x `height` texels, all of colour (0x10, 0x20, 0x30),
// into `folder`; returns its path.
std::string write_ppm(const TempFolder& folder, const std::string& name, int width, int height);

}  // namespace clr::testing::scene_json
