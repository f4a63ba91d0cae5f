// Testbed — `testbed plot`: traces of `testbed run --trace` as PNG charts
// drawn by gnuplot (energy, deepest contact, largest speed, joint error, a
// named body's x and y, and a 2 × 2 summary), one line per trace.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace tb {

/// `testbed plot ...`; args are the words after "plot". Returns the exit
/// code: 2 for bad arguments (including a trace that cannot be read), 1 when
/// gnuplot is missing or fails.
int runPlotCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

extern const char* const kPlotHelp;

}  // namespace tb
