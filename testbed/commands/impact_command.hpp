// `testbed impact`: resolve impacts given as JSON with the closed-form law
// (i2d::resolveImpact) and print the results as JSON.
//
// Input, one object or an array of them (every field required, no others):
//   {"e":0.5,"mu":0.3,"normal":[0,1],
//    "a":{"inv_mass":1,"inv_inertia":6,"r":[0.4,-0.5],"v":[1,-2],"w":3},
//    "b":{"inv_mass":0,"inv_inertia":0,"r":[0,0],"v":[0,0],"w":0}}
// Output, one object per input (an array for an array):
//   {"a":{"v":[..],"w":..},"b":{"v":[..],"w":..},"impulse":[..],"case":"..."}
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace tb {

/// `testbed impact ...`: --help, or resolve what `in` holds. Returns the exit code.
int runImpactCommand(const std::vector<std::string>& args, std::istream& in, std::ostream& out, std::ostream& err);

/// Returns 0 on success; on invalid input (malformed JSON, missing or unknown
/// fields, wrong types, or an input resolveImpact refuses) prints a message to
/// `err`, prints nothing to `out` and returns 1.
int runImpactCommand(std::istream& in, std::ostream& out, std::ostream& err);

}  // namespace tb
