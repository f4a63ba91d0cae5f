// `testbed run --trace`: one CSV row per step with units in the header, the
// same figures as the JSON report, a closing line saying where the run ended
// (also when it stopped on a non-finite state); bad options refused with exit
// code 2; `testbed plot` turning traces into PNG charts.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "commands/impact_command.hpp"
#include "commands/plot_command.hpp"
#include "run_command.hpp"
#include "trace_plot.hpp"
#include "trace_writer.hpp"

namespace fs = std::filesystem;

namespace {

const std::string kAssets = TB_TEST_ASSETS_DIR;

fs::path workDir(const std::string& name) {
    fs::path dir = fs::path(TB_TEST_WORK_DIR) / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

struct Trace {
    std::vector<std::string> header;
    std::vector<std::vector<double>> rows;
    std::vector<std::string> comments;
};

std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> cells;
    std::string cell;
    std::istringstream in(line);
    while (std::getline(in, cell, ',')) cells.push_back(cell);
    return cells;
}

/// Reads a trace, failing the test on a cell that is not a whole number.
Trace readTrace(const fs::path& path) {
    Trace t;
    std::ifstream in(path);
    std::string line;
    EXPECT_TRUE(std::getline(in, line)) << path;
    t.header = split(line);
    while (std::getline(in, line)) {
        if (!line.empty() && line[0] == '#') {
            t.comments.push_back(line);
            continue;
        }
        EXPECT_TRUE(t.comments.empty()) << "a row after the closing comments: " << line;
        std::vector<double> row;
        for (const std::string& cell : split(line)) {
            char* end = nullptr;
            row.push_back(std::strtod(cell.c_str(), &end));
            EXPECT_TRUE(!cell.empty() && *end == '\0') << "not a number: '" << cell << "' in " << line;
        }
        EXPECT_EQ(row.size(), t.header.size()) << line;
        t.rows.push_back(row);
    }
    return t;
}

int col(const Trace& t, const std::string& name) {
    for (std::size_t i = 0; i < t.header.size(); ++i)
        if (t.header[i] == name) return static_cast<int>(i);
    ADD_FAILURE() << "no column " << name;
    return 0;
}

void checkTraceAgainstJson(const std::string& engine) {
    const fs::path dir = workDir("trace_" + engine);
    const fs::path csv = dir / "stack5.csv";
    std::ostringstream out, err;
    const int rc = tb::runRunCommand(
        {"stack5", "--steps", "90", "--json", "--engine", engine, "--trace", csv.string(), "--assets", kAssets}, out,
        err);
    ASSERT_EQ(rc, 0) << err.str();
    const nlohmann::json j = nlohmann::json::parse(out.str());
    const Trace t = readTrace(csv);

    EXPECT_EQ(t.header, tb::traceColumns({"bottom", "ground", "top"}));
    for (const std::string& h : t.header) {
        EXPECT_NE(h.find('['), std::string::npos) << h << " names no unit";
        EXPECT_EQ(h.back(), ']') << h;
    }
    ASSERT_EQ(t.rows.size(), 90u);
    const double dt = j.at("dt").get<double>();
    for (std::size_t k = 0; k < t.rows.size(); ++k) {
        EXPECT_EQ(t.rows[k][col(t, "step[count]")], static_cast<double>(k + 1));
        EXPECT_NEAR(t.rows[k][col(t, "time[s]")], static_cast<double>(k + 1) * dt, 1e-5);
        const auto& r = t.rows[k];
        EXPECT_NEAR(r[col(t, "total_energy[J]")], r[col(t, "kinetic_energy[J]")] + r[col(t, "potential_energy[J]")],
                    1e-6 * std::max(1.0, std::abs(r[col(t, "total_energy[J]")])));
    }
    const auto& last = t.rows.back();
    const double energy = j.at("energy").at("final").get<double>();
    EXPECT_NEAR(last[col(t, "total_energy[J]")], energy, 1e-7 * std::max(1.0, std::abs(energy)));
    EXPECT_EQ(last[col(t, "contacts[count]")], j.at("contacts").get<double>());
    EXPECT_NEAR(last[col(t, "top.y[m]")], j.at("named").at("top").at("y").get<double>(), 1e-5);
    double deepest = 0.0;
    for (const auto& r : t.rows) deepest = std::max(deepest, r[col(t, "max_penetration[m]")]);
    EXPECT_NEAR(deepest, j.at("max_penetration").get<double>(), 1e-6);
    // The run's max_speed and final_penetration are the trace's largest speed
    // column and its last deepest contact (the same quantities, per step).
    double fastest = 0.0;
    for (const auto& r : t.rows) fastest = std::max(fastest, r[col(t, "max_speed[m/s]")]);
    EXPECT_GT(fastest, 0.0);  // 1.5 s of falling and settling
    EXPECT_NEAR(fastest, j.at("max_speed").get<double>(), 1e-5 * std::max(1.0, fastest));
    EXPECT_NEAR(last[col(t, "max_penetration[m]")], j.at("final_penetration").get<double>(), 1e-6);
    ASSERT_EQ(t.comments.size(), 3u);
    EXPECT_EQ(t.comments[0], "# scene: stack5");
    EXPECT_EQ(t.comments[1].rfind("# engine: " + engine, 0), 0u) << t.comments[1];
    EXPECT_EQ(t.comments[2], "# end: 90 of 90 steps (t = 1.5000 s)");
}

}  // namespace

TEST(Trace, OneRowPerStepMatchingTheJsonReport) { checkTraceAgainstJson("impulse2d"); }

TEST(Trace, WorksWithBox2D) {
    if (!tb::box2dAvailable()) GTEST_SKIP() << "built without the Box2D 2.4.1 backend";
    checkTraceAgainstJson("box2d");
}

// Infinite gravity in Box2D 2.4.1 (which takes it as given): the first step
// turns the ball's velocity into NaN (its translation clamp multiplies
// infinity by zero) and the run stops. The trace holds every step up to and
// including that one, then a line saying where it stopped.
TEST(Trace, NonFiniteStopEndsWithWhereItStopped) {
    if (!tb::box2dAvailable()) GTEST_SKIP() << "built without the Box2D 2.4.1 backend";
    tb::SceneDesc desc;
    desc.name = "overflow";
    desc.settings.gravity = {0.0f, -INFINITY};
    tb::BodyDesc ball;
    ball.name = "ball";
    ball.def.type = i2d::BodyType::dynamic_body;
    tb::ShapeDesc circle;
    circle.type = i2d::ShapeType::circle;
    circle.circle = {{0.0f, 0.0f}, 0.5f};
    ball.shapes.push_back(circle);
    desc.bodies.push_back(ball);

    const fs::path csv = workDir("trace_nonfinite") / "overflow.csv";
    tb::RunReport rep;
    {
        tb::TraceWriter trace(csv.string());
        trace.begin(desc);
        rep = tb::runScene(desc, 1000, tb::EngineKind::box2d, {}, &trace);
        trace.finish(rep, "box2d");
    }
    ASSERT_TRUE(rep.nan);
    ASSERT_LT(rep.stepsCompleted, 1000);
    std::ifstream in(csv);
    std::string line, lastLine;
    long rows = -1;  // the header
    while (std::getline(in, line)) {
        if (line[0] != '#') ++rows;
        lastLine = line;
    }
    EXPECT_EQ(rows, rep.stepsCompleted);
    char expected[160];
    std::snprintf(expected, sizeof expected, "# stopped: non-finite state after step %ld of 1000", rep.stepsCompleted);
    EXPECT_EQ(lastLine.rfind(expected, 0), 0u) << lastLine;
}

TEST(Trace, BadOptionsAreUsageErrors) {
    struct Case {
        std::vector<std::string> args;
        std::string message;
    };
    const fs::path dir = workDir("trace_bad");
    const std::vector<Case> cases{
        {{"stack5", "--trace", (dir / "missing_dir" / "t.csv").string()}, "--trace: cannot write"},
        {{"stack5", "--trace", dir.string()}, "--trace: cannot write"},
        {{"stack5", "--trace"}, "--trace needs a value"},
        {{"stack5", "--engine", "bullet"}, "--engine: expected impulse2d or box2d, got 'bullet'"},
        {{"stack5", "--compare", "box2d"}, "--compare is an option of `testbed render`"},
    };
    for (const Case& c : cases) {
        std::vector<std::string> args{"--assets", kAssets};
        args.insert(args.end(), c.args.begin(), c.args.end());
        std::ostringstream out, err;
        EXPECT_EQ(tb::runRunCommand(args, out, err), 2) << c.message;
        EXPECT_NE(err.str().find("testbed run: " + c.message), std::string::npos) << err.str();
    }
    std::istringstream in("{}");
    std::ostringstream out, err;
    EXPECT_EQ(tb::runImpactCommand({"--compare", "box2d"}, in, out, err), 2);
    EXPECT_NE(err.str().find("testbed impact: --compare does not apply"), std::string::npos) << err.str();
}

TEST(Plot, BadArgumentsAreUsageErrors) {
    const fs::path dir = workDir("plot_bad");
    std::ofstream(dir / "not_a_trace.csv") << "a,b\n1,2\n";
    const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
        {{}, "no trace given"},
        {{(dir / "none.csv").string()}, "cannot read"},
        {{(dir / "not_a_trace.csv").string()}, "is not a trace"},
        {{"a.csv", "--compare", "box2d"}, "--compare does not apply"},
    };
    for (const auto& [args, message] : cases) {
        std::ostringstream out, err;
        EXPECT_EQ(tb::runPlotCommand(args, out, err), 2) << message;
        EXPECT_NE(err.str().find("testbed plot: "), std::string::npos) << err.str();
        EXPECT_NE(err.str().find(message), std::string::npos) << err.str();
    }
}

TEST(Plot, TwoTracesGiveChartsWithOneLinePerEngine) {
    if (std::system("command -v gnuplot > /dev/null 2>&1") != 0)
        GTEST_SKIP() << "gnuplot is not installed: `testbed plot` cannot draw charts here";
    const fs::path dir = workDir("plot_two");
    std::vector<std::string> traces;
    for (const char* engine : {"impulse2d", "box2d"}) {
        if (std::string(engine) == "box2d" && !tb::box2dAvailable()) continue;
        const std::string csv = (dir / (std::string(engine) + ".csv")).string();
        std::ostringstream out, err;
        ASSERT_EQ(tb::runRunCommand(
                      {"stack5", "--steps", "60", "--engine", engine, "--trace", csv, "--assets", kAssets}, out, err),
                  0)
            << err.str();
        traces.push_back(csv);
    }
    std::vector<std::string> args = traces;
    args.insert(args.end(), {"--out", (dir / "plots").string(), "--size", "640x360"});
    std::ostringstream out, err;
    ASSERT_EQ(tb::runPlotCommand(args, out, err), 0) << err.str();
    for (const char* file :
         {"energy.png", "penetration.png", "speed.png", "joint_error.png", "body_bottom.png", "summary.png"}) {
        const fs::path png = dir / "plots" / file;
        ASSERT_TRUE(fs::exists(png)) << png;
        std::ifstream in(png, std::ios::binary);
        char magic[8] = {};
        in.read(magic, 8);
        EXPECT_EQ(std::string(magic + 1, 3), "PNG") << png;
        EXPECT_GT(fs::file_size(png), 2000u) << png;
    }
    // The legend names each engine with its settings, one line per trace.
    std::ifstream script(dir / "plots" / "plot.gp");
    const std::string text((std::istreambuf_iterator<char>(script)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("title 'impulse2d: soft_step"), std::string::npos);
    if (traces.size() == 2) {
        EXPECT_NE(text.find("title 'box2d 2.4.1: 8 velocity + 3 position"), std::string::npos);
    }
}

TEST(Plot, DefaultBodyIsTheFirstThatMoves) {
    const fs::path dir = workDir("plot_body");
    const std::string csv = (dir / "t.csv").string();
    std::ostringstream out, err;
    ASSERT_EQ(tb::runRunCommand({"stack5", "--steps", "20", "--trace", csv, "--assets", kAssets}, out, err), 0);
    const tb::TraceInfo info = tb::readTraceInfo(csv);
    EXPECT_EQ(info.rows, 20);
    EXPECT_EQ(info.bodies(), (std::vector<std::string>{"bottom", "ground", "top"}));
    EXPECT_EQ(info.movingBody(), "bottom");  // ground is static and listed after it; bottom falls
    EXPECT_EQ(info.scene, "stack5");
    EXPECT_TRUE(info.stopped.empty());
}
