// Testbed — everything about `testbed run` and `testbed list` in one include,
// for the tools built on it (validation cases, sweep, tests): the commands,
// their options, the run itself and its report.
#pragma once

#include "cli/arguments.hpp"
#include "cli/settings_options.hpp"
#include "commands/list_command.hpp"
#include "commands/run_command.hpp"
#include "report_format.hpp"
#include "run_report.hpp"
