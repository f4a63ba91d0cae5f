// Testbed — scene-file text to JSON: a syntax error, a number too large for
// a double and a duplicate key are reported with the field path they are at.
#pragma once

#include <string>

#include "scene_file/json_checks.hpp"

namespace tb::scene_file {

/// The JSON value of `text`; throws SceneError naming `file` (and the field path when known).
json parseJson(const std::string& text, const std::string& file);

}  // namespace tb::scene_file
