// Testbed — `testbed render`: run a scene offscreen and write its frames as
// PNG files, a contact sheet and an animated GIF.
//
//   testbed render SCENE --frames N [--every K] --out DIR [--size WxH]
//                  [--assets DIR] [--ssaa S] [--contacts] [--aabbs]
//                  [--no-gif] [--no-sheet] [--no-caption] [--quiet]
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace tb {

/// `testbed render ...`; args are the words after "render". Returns the exit
/// code: 2 for bad arguments, 1 when the scene or an output cannot be made.
int runRenderCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace tb
