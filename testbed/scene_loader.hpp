// Testbed — reading scene files (JSON, format in docs/scene-format.md) into
// a tb::SceneDesc, and finding the shipped scenes.
//
// The implementation is in scene_file/: json_text and json_checks (JSON with
// field-path errors), world_settings, bodies, joints and generators (the
// parts of a scene), scene_parser (the whole file) and scene_paths (finding
// files and the assets directory).
//
// Every problem in a file (malformed JSON, unknown field, wrong type, value
// out of range or not finite, missing field, unknown body name, degenerate
// geometry) throws tb::SceneError whose message names the file, the field
// path (e.g. "bodies[3].shapes[0].radius") and what is wrong.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "scene.hpp"

namespace tb {

/// Load a scene: `nameOrPath` is either a path to a .json file (it contains a
/// '/' or ends in ".json") or the name of a shipped scene, looked up as
/// `assetsDir/scenes/NAME.json` (then `assetsDir/NAME.json`). An empty
/// assetsDir means defaultAssetsDir().
SceneDesc loadSceneDesc(const std::string& nameOrPath, const std::string& assetsDir);

/// Parse scene text. `file` is only used in error messages and stored in
/// SceneDesc::file; `name` is the scene name used when the file gives none.
SceneDesc parseSceneDesc(const std::string& text, const std::string& file, const std::string& name);

/// The file a scene name or path resolves to (throws SceneError when none exists).
std::string resolveScenePath(const std::string& nameOrPath, const std::string& assetsDir);

/// Shipped scenes as (name, description), sorted by name. Files that fail to
/// load are listed with the description "(invalid: <message>)".
std::vector<std::pair<std::string, std::string>> listScenes(const std::string& assetsDir);

/// The assets directory: the first of <exe dir>/assets, <exe dir>/../assets,
/// <exe dir>/../share/impulse2d/assets and the source tree's assets/ (a
/// compile-time path) that contains a scenes/ directory. Empty when none does.
std::string defaultAssetsDir();

}  // namespace tb
