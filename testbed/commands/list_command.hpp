// Testbed — `testbed list`: the shipped scenes with their descriptions.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace tb {

/// `testbed list ...`; returns the process exit code.
int runListCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

extern const char* const kListHelp;

}  // namespace tb
