// Testbed renderer — animated GIF from PNG frames, made by ImageMagick's
// `convert` (Debian package imagemagick) run as a subprocess.
#pragma once

#include <string>
#include <vector>

namespace tb {

/// Full path of an executable found in PATH, or empty.
std::string findInPath(const std::string& program);

/// Assembles `pngFiles` into a looping GIF at `outPath`, `delayCentiseconds`
/// per frame, scaled down to at most `maxWidth` pixels wide (0: no limit).
/// Returns false with a reason in `message` (e.g. convert is not installed).
bool writeGifWithImageMagick(const std::vector<std::string>& pngFiles, const std::string& outPath,
                             int delayCentiseconds, int maxWidth, std::string& message);

}  // namespace tb
