// Testbed — a run's report as text (for people) or as one JSON object (for
// tools: the field names are an interface, see docs/scene-format.md).
#pragma once

#include <iosfwd>
#include <string>

#include "run_report.hpp"

namespace tb {

/// The report as one JSON object (field names are relied on by other tools).
std::string reportToJson(const RunReport& report);

/// The report as a few lines of text.
void printReportText(const RunReport& report, std::ostream& out);

}  // namespace tb
