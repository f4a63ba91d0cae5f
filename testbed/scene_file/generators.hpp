// Testbed — scene-file generators: one entry of "bodies" that makes many
// bodies (row, grid, pyramid) or a jointed chain (docs/scene-format.md,
// "Generators").
#pragma once

#include "scene_file/parts.hpp"

namespace tb::scene_file {

/// Adds the generator's bodies (and joints) to `bld`.
void expandGenerator(const json& j, const Loc& loc, Builder& bld);

}  // namespace tb::scene_file
