// Testbed — trace files to gnuplot charts (see trace_plot.hpp).
#include "trace_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

namespace tb {

namespace {

std::vector<std::string> splitCsv(const std::string& line) {
    std::vector<std::string> cells;
    std::string cell;
    std::istringstream in(line);
    while (std::getline(in, cell, ',')) cells.push_back(cell);
    return cells;
}

bool startsWith(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

/// A gnuplot single-quoted string.
std::string quoted(const std::string& s) {
    std::string q = "'";
    for (char c : s) {
        if (c == '\'')
            q += "''";
        else
            q += c;
    }
    return q + "'";
}

// One colour per trace, the same in every chart (first: Impulse2D by convention).
const char* const kColours[] = {"#1f6fb4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf"};

std::string colour(std::size_t i) { return kColours[i % (sizeof kColours / sizeof kColours[0])]; }

struct Series {
    std::string column;
    double scale = 1.0;
    bool dashed = false;
    bool titled = true;      ///< in the legend (dashed companions are not)
    bool fromFirst = false;  ///< less the first row's value (a change since the start)
};

/// "set yrange ...": automatic, or a fixed band around the value when every
/// trace holds one value throughout (gnuplot would warn of an empty range).
std::string yRange(const PlotRequest& r, const std::vector<Series>& series) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const TraceInfo& t : r.traces)
        for (const Series& s : series) {
            const int c = t.column(s.column);
            if (c == 0 || !std::isfinite(t.minimum[c - 1])) continue;
            const double base = s.fromFirst && std::isfinite(t.first[c - 1]) ? t.first[c - 1] : 0.0;
            lo = std::min(lo, (t.minimum[c - 1] - base) * s.scale);
            hi = std::max(hi, (t.maximum[c - 1] - base) * s.scale);
        }
    if (lo <= hi && hi - lo <= 1e-9 * std::max(1.0, std::abs(lo))) {
        std::ostringstream band;
        band.precision(10);
        band << "set yrange [" << lo - 1.0 << ":" << hi + 1.0 << "]\n";
        return band.str();
    }
    return "set yrange [*:*]\n";
}

/// "plot ..." with one line per trace and series.
std::string plotCommand(const PlotRequest& r, const std::vector<Series>& series) {
    std::string cmd = "plot";
    bool first = true;
    for (std::size_t t = 0; t < r.traces.size(); ++t) {
        const TraceInfo& info = r.traces[t];
        const int time = info.column("time[s]");
        for (const Series& s : series) {
            const int col = info.column(s.column);
            if (col == 0 || time == 0) continue;
            std::ostringstream y;
            y.precision(17);
            const double base = s.fromFirst && std::isfinite(info.first[col - 1]) ? info.first[col - 1] : 0.0;
            if (s.scale == 1.0 && base == 0.0)
                y << col;
            else
                y << "((column(" << col << ")-(" << base << "))*" << s.scale << ")";
            cmd += first ? " " : ", \\\n     ";
            first = false;
            cmd += quoted(info.path) + " skip 1 using " + std::to_string(time) + ":" + y.str() +
                   " with lines lw 2 lc rgb " + quoted(colour(t)) + (s.dashed ? " dt 2" : "") +
                   (s.titled ? " title " + quoted(r.labels[t]) : " notitle");
        }
    }
    // No trace has the column: an empty chart that says so, not a gnuplot error.
    if (first)
        return "set yrange [-1:1]\nset label 1 'no data' at graph 0.5, 0.5 center\nplot NaN notitle\n"
               "unset label 1\n";
    return yRange(r, series) + cmd + "\n";
}

const char* const kEnergyTitle = "total energy less its value at step 1 (solid), kinetic energy (dashed)";

std::string chartTitle(const PlotRequest& r, const std::string& what) {
    return r.title.empty() ? what : r.title + ": " + what;
}

std::string axes(const std::string& title, const std::string& ylabel) {
    return "set title " + quoted(title) + "\nset xlabel 'time (s)'\nset ylabel " + quoted(ylabel) + "\n";
}

}  // namespace

int TraceInfo::column(const std::string& name) const {
    for (std::size_t i = 0; i < columns.size(); ++i)
        if (columns[i] == name) return static_cast<int>(i) + 1;
    return 0;
}

std::vector<std::string> TraceInfo::bodies() const {
    std::vector<std::string> names;
    const std::string suffix = ".x[m]";
    for (const std::string& c : columns)
        if (c.size() > suffix.size() && c.compare(c.size() - suffix.size(), suffix.size(), suffix) == 0)
            names.push_back(c.substr(0, c.size() - suffix.size()));
    return names;
}

std::string TraceInfo::movingBody() const {
    const std::vector<std::string> names = bodies();
    for (const std::string& name : names) {
        for (const char* axis : {".x[m]", ".y[m]"}) {
            const int c = column(name + axis);
            if (c > 0 && maximum[c - 1] > minimum[c - 1]) return name;
        }
    }
    return names.empty() ? std::string() : names.front();
}

TraceInfo readTraceInfo(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw TraceReadError("cannot read '" + path + "'");
    TraceInfo info;
    info.path = path;
    std::string line;
    if (!std::getline(in, line)) throw TraceReadError("'" + path + "' is empty");
    info.columns = splitCsv(line);
    if (info.column("time[s]") != 2 || info.column("step[count]") != 1)
        throw TraceReadError("'" + path +
                             "' is not a trace of `testbed run --trace` (its header does not start "
                             "with step[count],time[s])");
    const double nan = std::numeric_limits<double>::quiet_NaN();
    info.first.assign(info.columns.size(), nan);
    info.minimum.assign(info.columns.size(), nan);
    info.maximum.assign(info.columns.size(), nan);
    while (std::getline(in, line)) {
        if (line.empty()) continue;
        if (line[0] == '#') {
            if (startsWith(line, "# scene: ")) info.scene = line.substr(9);
            if (startsWith(line, "# engine: ")) info.engine = line.substr(10);
            if (startsWith(line, "# stopped: ")) info.stopped = line.substr(11);
            continue;
        }
        ++info.rows;
        const std::vector<std::string> cells = splitCsv(line);
        if (cells.size() > 1) info.lastTime = std::strtod(cells[1].c_str(), nullptr);
        for (std::size_t i = 0; i < cells.size() && i < info.columns.size(); ++i) {
            const double v = std::strtod(cells[i].c_str(), nullptr);
            if (info.rows == 1) info.first[i] = v;
            if (!std::isfinite(v)) continue;
            if (!(v >= info.minimum[i])) info.minimum[i] = v;
            if (!(v <= info.maximum[i])) info.maximum[i] = v;
        }
    }
    return info;
}

std::vector<std::string> defaultLabels(const std::vector<TraceInfo>& traces) {
    std::vector<std::string> labels;
    std::multiset<std::string> engines;
    for (const TraceInfo& t : traces) engines.insert(t.engine);
    for (const TraceInfo& t : traces) {
        std::string label = t.engine;
        const std::string file = std::filesystem::path(t.path).filename().string();
        if (label.empty())
            label = file;
        else if (engines.count(t.engine) > 1)
            label += " (" + file + ")";
        if (!t.stopped.empty()) {
            std::ostringstream s;
            s.precision(3);
            s << " (stopped at t = " << t.lastTime << " s)";
            label += s.str();
        }
        labels.push_back(label);
    }
    return labels;
}

std::vector<PlotChart> plotCharts(const PlotRequest& r) {
    std::vector<PlotChart> charts{{"energy.png", "total energy less its value at step 1 (solid), kinetic (dashed)"},
                                  {"penetration.png", "deepest contact"},
                                  {"speed.png", "largest body speed"},
                                  {"joint_error.png", "joint error"}};
    if (!r.body.empty()) charts.push_back({"body_" + r.body + ".png", r.body + " x and y"});
    charts.push_back({"summary.png", "energy, deepest contact, largest speed" +
                                         (r.body.empty() ? std::string(", joint error") : ", " + r.body + " y")});
    return charts;
}

std::string plotScript(const PlotRequest& r) {
    const std::filesystem::path dir(r.outDir);
    const auto out = [&](const std::string& file) { return "set output " + quoted((dir / file).string()) + "\n"; };
    const std::string term = "set terminal pngcairo noenhanced font 'sans,10' size ";
    const std::string single = term + std::to_string(r.width) + "," + std::to_string(r.height) + "\n";
    const std::string bodyX = r.body + ".x[m]", bodyY = r.body + ".y[m]";

    const std::string energy = plotCommand(
        r, {{"total_energy[J]", 1.0, false, true, true}, {"kinetic_energy[J]", 1.0, true, false}});
    const std::string penetration = plotCommand(r, {{"max_penetration[m]", 1000.0}});
    const std::string speed = plotCommand(r, {{"max_speed[m/s]"}});
    const std::string joint = plotCommand(r, {{"joint_error[m]", 1000.0}});

    std::string s;
    s += "# Written by `testbed plot`: one line per trace.\n";
    s += "set datafile separator ','\nset datafile commentschars '#'\n";
    s += "set grid lc rgb '#d0d0d0'\nset key below left Left reverse samplen 2\nset border lc rgb '#404040'\n";
    s += "set xrange [0:*]\nset autoscale xfix\nset xtics nomirror\nset ytics nomirror\n";
    s += single;
    s += out("energy.png") + axes(chartTitle(r, kEnergyTitle), "energy (J)") + energy;
    s += out("penetration.png") + axes(chartTitle(r, "deepest contact"), "penetration (mm)") + penetration;
    s += out("speed.png") + axes(chartTitle(r, "largest body speed"), "speed (m/s)") + speed;
    s += out("joint_error.png") + axes(chartTitle(r, "joint error"), "largest joint error (mm)") + joint;
    if (!r.body.empty()) {
        s += "set terminal pngcairo noenhanced font 'sans,10' size " + std::to_string(r.width) + "," +
             std::to_string(r.height * 3 / 2) + "\n";
        s += out("body_" + r.body + ".png") + "set multiplot layout 2,1\n";
        s += axes(chartTitle(r, r.body + " x"), "x (m)") + plotCommand(r, {{bodyX}});
        s += axes(chartTitle(r, r.body + " y"), "y (m)") + plotCommand(r, {{bodyY}});
        s += "unset multiplot\n";
    }
    s += term + std::to_string(r.width * 3 / 2) + "," + std::to_string(r.height * 3 / 2) + "\n";
    s += "set key font ',8'\n";
    s += out("summary.png") + "set multiplot layout 2,2" +
         (r.title.empty() ? std::string() : " title " + quoted(r.title)) + "\n";
    s += axes(kEnergyTitle, "energy (J)") + energy;
    s += axes("deepest contact", "penetration (mm)") + penetration;
    s += axes("largest body speed", "speed (m/s)") + speed;
    if (r.body.empty())
        s += axes("joint error", "largest joint error (mm)") + joint;
    else
        s += axes(r.body + " y", "y (m)") + plotCommand(r, {{bodyY}});
    s += "unset multiplot\nunset output\n";
    return s;
}

}  // namespace tb
