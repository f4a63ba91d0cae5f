// Testbed — trace files (testbed run --trace) read back and turned into a
// gnuplot script: one chart per figure against time, one line per trace.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace tb {

/// A trace that cannot be read or is not a trace; what() names the file.
class TraceReadError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// What a plot needs of a trace file: its columns and closing comment lines.
struct TraceInfo {
    std::string path;
    std::vector<std::string> columns;  ///< header names, with their units
    std::string scene;                 ///< "# scene:" line, empty if absent
    std::string engine;                ///< "# engine:" line, empty if absent
    std::string stopped;               ///< "# stopped:" line, empty when the run ended normally
    long rows = 0;
    double lastTime = 0.0;                 ///< time[s] of the last row
    std::vector<double> first;             ///< the first row's values (NaN where none)
    std::vector<double> minimum, maximum;  ///< each column's finite range over the rows (NaN: none)

    /// 1-based column number of `name` (gnuplot's numbering), 0 when absent.
    int column(const std::string& name) const;
    /// Named bodies, from the NAME.x[m] columns, in column order.
    std::vector<std::string> bodies() const;
    /// The first named body whose x or y changes over the trace, else the first one, else "".
    std::string movingBody() const;
};

/// Reads the header, counts the rows and reads the closing comment lines.
TraceInfo readTraceInfo(const std::string& path);

struct PlotRequest {
    std::vector<TraceInfo> traces;
    std::vector<std::string> labels;  ///< one per trace: the legend entries
    std::string body;                 ///< named body to plot (empty: none)
    std::string outDir;
    std::string title;              ///< prefix of every chart's title
    int width = 800, height = 450;  ///< one chart; the summary is 1.5 times larger each way
};

/// Legend entries: the engine line of each trace, or the file name when a
/// trace has none or two traces share one; "(stopped at t = T s)" appended
/// for runs that stopped on a non-finite state.
std::vector<std::string> defaultLabels(const std::vector<TraceInfo>& traces);

/// A chart written by the script: file name (in outDir) and what it shows.
struct PlotChart {
    std::string file;
    std::string what;
};
/// The charts plotScript writes, in order.
std::vector<PlotChart> plotCharts(const PlotRequest& request);

/// The gnuplot script writing every chart of plotCharts into request.outDir.
std::string plotScript(const PlotRequest& request);

}  // namespace tb
