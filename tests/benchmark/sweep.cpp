// Speed against error: Impulse2D across its solver settings and Box2D 2.4.1
// across its iteration counts, on the benchmark scenes, in one run.
//
//   sweep [--quick] [--out DIR] [--images DIR] [--assets DIR] [--scenes a,b,...] [--no-scaling]
//         [--no-profile] [--revision TEXT]
//
// For each scene every point (one engine, one setting) is run R times; within
// a repeat the two engines' points alternate, so that a slow spell of a
// shared machine hits both. A point's time is the median over its repeats of
// the run's median ms/step; its error is the scene's error figure
// (tb::errorMetricFor). Sleeping is off in every sweep run.
//
// Writes to DIR (default build/perf): sweep.csv (one line per point),
// scaling.csv (ms/step against body count on 1 and 2 workers), profile.csv
// (ms per stage of a step, World::profile()), memory.csv, idle.csv (what
// sleeping and static bodies cost), plot data and plots.gp (a gnuplot
// script that draws IMAGES/perf_*.png), and generated.md (the generated part
// of docs/performance.md). scripts/performance.sh runs all of it.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "footprint.hpp"
#include "run_command.hpp"
#include "scene_build.hpp"
#include "scene_loader.hpp"
#include "simulation.hpp"
#include "thread_pool.hpp"

namespace {

using bench::columnsScene;
using bench::heldBytes;

using tb::EngineKind;

// ---------------------------------------------------------------- points --

struct Point {
    EngineKind engine = EngineKind::impulse2d;
    i2d::PositionCorrection correction = i2d::PositionCorrection::soft_step;
    int substeps = 1;
    int velocityIterations = 8;
    int positionIterations = 3;
    int stiffness = 1;  ///< soft_step: contact and joint hertz × this
    i2d::ImpactModel impact = i2d::ImpactModel::closed_form;
    bool reference = false;  ///< Impulse2D's defaults, or Box2D's 8/3

    // Results.
    std::vector<double> ms;  ///< per repeat: the run's median ms/step
    double msMedian = 0.0;
    double error = 0.0;
    bool collapsed = false;
    bool nan = false;
    int displaced = 0;
    float maxPenetration = 0.0f;
    float jointError = 0.0f;
};

const char* correctionName(i2d::PositionCorrection c) {
    switch (c) {
        case i2d::PositionCorrection::baumgarte: return "baumgarte";
        case i2d::PositionCorrection::split: return "split";
        case i2d::PositionCorrection::soft_step: return "soft_step";
    }
    return "";
}

std::string settingsLabel(const Point& p) {
    char buf[96];
    if (p.engine == EngineKind::box2d)
        std::snprintf(buf, sizeof buf, "%d/%d", p.velocityIterations, p.positionIterations);
    else if (p.correction == i2d::PositionCorrection::soft_step)
        std::snprintf(buf, sizeof buf, "soft %d sub%s", p.substeps,
                      p.stiffness == 1 ? "" : (" x" + std::to_string(p.stiffness) + " Hz").c_str());
    else if (p.correction == i2d::PositionCorrection::split)
        std::snprintf(buf, sizeof buf, "split %d/%d", p.velocityIterations, p.positionIterations);
    else
        std::snprintf(buf, sizeof buf, "baumgarte %d", p.velocityIterations);
    std::string s = buf;
    if (p.engine == EngineKind::impulse2d && p.impact == i2d::ImpactModel::velocity_bias) s += " vbias";
    return s;
}

Point impulse(i2d::PositionCorrection c, int substeps, int vel, int pos, int stiffness = 1,
              i2d::ImpactModel impact = i2d::ImpactModel::closed_form) {
    Point p;
    p.correction = c;
    p.substeps = substeps;
    p.velocityIterations = vel;
    p.positionIterations = pos;
    p.stiffness = stiffness;
    p.impact = impact;
    return p;
}

Point box2d(int vel, int pos) {
    Point p;
    p.engine = EngineKind::box2d;
    p.velocityIterations = vel;
    p.positionIterations = pos;
    p.reference = vel == 8 && pos == 3;
    return p;
}

bool samePoint(const Point& a, const Point& b) {
    if (a.engine != b.engine || a.correction != b.correction || a.impact != b.impact) return false;
    if (a.engine == EngineKind::impulse2d && a.correction == i2d::PositionCorrection::soft_step)
        return a.substeps == b.substeps && a.stiffness == b.stiffness;  // iteration counts: one per substep
    return a.velocityIterations == b.velocityIterations && a.positionIterations == b.positionIterations;
}

/// The settings swept. `level` 0 = quick, 1 = reduced (expensive scenes), 2 = full.
/// soft_step solves once and relaxes once per substep (the iteration counts
/// do not apply to it): its knobs are the substeps and the stiffness (contact
/// and joint hertz, each capped by the engine at a fraction of the substep rate).
std::vector<Point> sweepPoints(const i2d::WorldSettings& defaults, int level, bool withBox2D) {
    using PC = i2d::PositionCorrection;
    const auto vbias = i2d::ImpactModel::velocity_bias;
    std::vector<Point> pts;
    Point def = impulse(defaults.positionCorrection, defaults.substeps, defaults.velocityIterations,
                        defaults.positionIterations);
    def.impact = defaults.impactModel;
    def.reference = true;
    pts.push_back(def);
    auto add = [&](Point p) {
        for (const Point& q : pts)
            if (samePoint(p, q)) return;
        pts.push_back(p);
    };
    auto soft = [&](int substeps, int stiffness = 1, i2d::ImpactModel impact = i2d::ImpactModel::closed_form) {
        add(impulse(PC::soft_step, substeps, 1, 1, stiffness, impact));
    };
    if (level == 0) {
        for (int n : {1, 2, 4, 8}) soft(n);
        soft(8, 2);
        soft(4, 1, vbias);
        add(impulse(PC::baumgarte, 1, 4, 0));
        add(impulse(PC::baumgarte, 1, 16, 0));
        add(impulse(PC::split, 1, 8, 3));
        if (withBox2D)
            for (auto [v, p] : {std::pair{2, 1}, {8, 3}, {32, 10}}) add(box2d(v, p));
    } else if (level == 1) {
        for (int n : {1, 2, 4, 8}) soft(n);
        soft(8, 2);
        for (int v : {4, 16}) add(impulse(PC::baumgarte, 1, v, 0));
        for (auto [v, p] : {std::pair{4, 2}, {16, 6}}) add(impulse(PC::split, 1, v, p));
        if (withBox2D)
            for (auto [v, p] : {std::pair{2, 1}, {4, 2}, {8, 3}, {16, 6}, {32, 10}}) add(box2d(v, p));
    } else {
        for (int n : {1, 2, 3, 4, 6, 8, 12, 16, 24, 32}) soft(n);
        for (int n : {4, 8, 16}) soft(n, 2);
        for (int n : {8, 16, 32}) soft(n, 4);
        for (int n : {1, 4, 8}) soft(n, 1, vbias);
        for (int v : {1, 2, 4, 8, 16, 32}) add(impulse(PC::baumgarte, 1, v, 0));
        for (auto [v, p] : {std::pair{2, 1}, {4, 2}, {8, 3}, {16, 6}, {32, 10}}) add(impulse(PC::split, 1, v, p));
        if (withBox2D)
            for (auto [v, p] : {std::pair{1, 1}, {2, 1}, {4, 2}, {8, 3}, {16, 6}, {32, 10}}) add(box2d(v, p));
    }
    return pts;
}

// ---------------------------------------------------------------- scenes --

struct ScenePlan {
    std::string name;
    double seconds = 10.0;
    int repeats = 3;
    int level = 2;
    bool box2d = true;
    std::string box2dNote;  ///< why Box2D does not run this scene
};

std::vector<ScenePlan> plans(bool quick) {
    const std::string cardNote =
        "Box2D 2.4.1 cannot build a 2 mm card: b2PolygonShape::Set welds vertices closer than half its linear "
        "slop (2.5 mm) and stops on an assertion, so this scene has no Box2D points.";
    auto P = [](const char* name, double seconds, int repeats, int level, const std::string& noBox2D = "") {
        ScenePlan p;
        p.name = name;
        p.seconds = seconds;
        p.repeats = repeats;
        p.level = level;
        p.box2d = noBox2D.empty();
        p.box2dNote = noBox2D;
        return p;
    };
    if (quick)
        return {P("pyramid100", 1.0, 1, 0),
                P("many_pyramids_small", 2.0, 1, 0),
                P("tall_stack20", 5.0, 1, 0),
                P("tall_stack50", 5.0, 1, 0),
                P("rain1000", 3.0, 1, 0),
                P("circle_pile1000", 3.0, 1, 0),
                P("joint_grid", 3.0, 1, 0),
                P("heavy_chain", 5.0, 1, 0),
                P("card_house", 5.0, 1, 0, cardNote),
                P("bounce", 3.0, 1, 0),
                P("pendulum_wave", 10.0, 1, 0)};
    return {P("pyramid100", 3.0, 2, 2),
            P("many_pyramids", 1.5, 2, 1),
            P("many_pyramids_small", 4.0, 3, 2),
            P("tall_stack20", 10.0, 3, 2),
            P("tall_stack50", 10.0, 3, 2),
            P("rain1000", 5.0, 3, 2),
            P("circle_pile1000", 5.0, 3, 1),
            P("joint_grid", 5.0, 3, 2),
            P("heavy_chain", 10.0, 3, 2),
            P("card_house", 10.0, 3, 2, cardNote),
            P("bounce", 4.0, 3, 2),
            P("pendulum_wave", 30.0, 3, 2)};
}

// ------------------------------------------------------------- progress --

class Progress {
public:
    explicit Progress(double total) : total_(total), t0_(std::chrono::steady_clock::now()) {}
    void advance(double work, const std::string& what) {
        done_ += work;
        const double frac = std::min(1.0, total_ > 0 ? done_ / total_ : 1.0);
        const int width = 30, filled = static_cast<int>(frac * width);
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
        const double left = frac > 0.01 ? elapsed * (1.0 - frac) / frac : 0.0;
        std::string bar(static_cast<std::size_t>(filled), '#');
        bar.resize(width, '.');
        std::fprintf(stderr, "\r[%s] %3d%%  %4.0f s, ~%4.0f s left  %-44.44s", bar.c_str(),
                     static_cast<int>(frac * 100), elapsed, left, what.c_str());
        std::fflush(stderr);
    }
    void finish() { std::fprintf(stderr, "\n"); }

private:
    double total_, done_ = 0.0;
    std::chrono::steady_clock::time_point t0_;
};

/// Rough cost of one run, in arbitrary units, to weigh the progress bar.
double runCost(const Point& p, int bodies, long steps) {
    double iters = p.engine == EngineKind::box2d ? p.velocityIterations + p.positionIterations
                                                 : (p.correction == i2d::PositionCorrection::soft_step
                                                        ? p.substeps * 3.0
                                                        : p.velocityIterations + p.positionIterations);
    return (4.0 + iters) * (bodies + 50) * static_cast<double>(steps);
}

// ------------------------------------------------------------------ runs --

tb::RunReport runPoint(const tb::SceneDesc& base, const Point& p, long steps) {
    tb::SceneDesc desc = base;
    desc.settings.enableSleep = false;
    tb::Box2DSettings b2;
    if (p.engine == EngineKind::box2d) {
        b2.velocityIterations = p.velocityIterations;
        b2.positionIterations = p.positionIterations;
    } else {
        desc.settings.positionCorrection = p.correction;
        desc.settings.substeps = p.substeps;
        desc.settings.velocityIterations = p.velocityIterations;
        desc.settings.positionIterations = p.positionIterations;
        desc.settings.impactModel = p.impact;
        desc.settings.contactHertz *= static_cast<float>(p.stiffness);
        desc.settings.jointHertz *= static_cast<float>(p.stiffness);
    }
    return tb::runScene(desc, steps, p.engine, b2, nullptr, false);
}

double median(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/// Run order of one repeat: the two engines' points spread evenly over the
/// sequence (Impulse2D point i at i/nI, Box2D point j at j/nB), rotated by
/// the repeat so no point always runs first.
std::vector<std::size_t> interleavedOrder(const std::vector<Point>& pts, int repeat) {
    std::vector<std::size_t> ii, bb;
    for (std::size_t k = 0; k < pts.size(); ++k) (pts[k].engine == EngineKind::box2d ? bb : ii).push_back(k);
    std::vector<std::pair<double, std::size_t>> keyed;
    for (std::size_t i = 0; i < ii.size(); ++i)
        keyed.emplace_back((static_cast<double>(i) + 0.25) / static_cast<double>(ii.size()), ii[i]);
    for (std::size_t j = 0; j < bb.size(); ++j)
        keyed.emplace_back((static_cast<double>(j) + 0.75) / static_cast<double>(bb.size()), bb[j]);
    std::sort(keyed.begin(), keyed.end());
    std::vector<std::size_t> order;
    for (const auto& k : keyed) order.push_back(k.second);
    if (!order.empty())
        std::rotate(order.begin(), order.begin() + static_cast<long>(repeat) % static_cast<long>(order.size()),
                    order.end());
    return order;
}

struct SceneResult {
    ScenePlan plan;
    std::string metric, unit, description;
    int bodies = 0;
    long steps = 0;
    std::vector<Point> points;
};

// ---------------------------------------------------------------- fronts --

double errorOf(const Point& p) { return p.nan ? std::numeric_limits<double>::infinity() : p.error; }

/// Points of one engine on its Pareto front (no other point of that engine
/// is at most as slow and at most as wrong, one of them strictly), by time.
std::vector<const Point*> front(const std::vector<Point>& pts, EngineKind engine) {
    std::vector<const Point*> mine;
    for (const Point& p : pts)
        if (p.engine == engine && !p.nan) mine.push_back(&p);
    std::sort(mine.begin(), mine.end(), [](const Point* a, const Point* b) {
        return a->msMedian != b->msMedian ? a->msMedian < b->msMedian : errorOf(*a) < errorOf(*b);
    });
    std::vector<const Point*> f;
    double best = std::numeric_limits<double>::infinity();
    for (const Point* p : mine)
        if (errorOf(*p) < best) {
            f.push_back(p);
            best = errorOf(*p);
        }
    return f;
}

/// Smallest error among `engine`'s points at most `ms` per step (inf if none).
double bestWithin(const std::vector<Point>& pts, EngineKind engine, double ms) {
    double best = std::numeric_limits<double>::infinity();
    for (const Point& p : pts)
        if (p.engine == engine && p.msMedian <= ms) best = std::min(best, errorOf(p));
    return best;
}

const Point* reference(const std::vector<Point>& pts, EngineKind engine) {
    for (const Point& p : pts)
        if (p.engine == engine && p.reference) return &p;
    return nullptr;
}

// ---------------------------------------------------------- formatting --

std::string fmt(const char* f, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, f, v);
    return buf;
}

/// Three significant digits, plain notation when reasonable.
std::string num(double v) {
    if (!std::isfinite(v)) return "n/a";
    if (v == 0.0) return "0";
    const double a = std::abs(v);
    if (a >= 100) return fmt("%.0f", v);
    if (a >= 0.01) return fmt("%.3g", v);
    return fmt("%.2e", v);
}

std::string errText(const Point& p, const std::string& unit) {
    if (p.nan) return "non-finite";
    std::string s = num(p.error) + (unit == "1" ? "" : " " + unit);
    if (p.collapsed) s += ", collapsed";
    return s;
}

// ----------------------------------------------------- scaling and memory --

/// 100 awake boxes (10 columns of 10 that never sleep) plus `idle` boxes far
/// away: static boxes in a sparse grid, or dynamic boxes resting in columns
/// of 10 on their own ground, which fall asleep within the first second.
/// World sleeping on.
tb::SceneDesc idleScene(int idle, bool sleeping) {
    tb::SceneDesc d = columnsScene(100, true);
    d.name = "idle";
    for (tb::BodyDesc& b : d.bodies) b.def.enableSleep = false;
    if (sleeping) {
        tb::SceneDesc rest = columnsScene(idle, true);
        for (tb::BodyDesc& b : rest.bodies) {
            b.def.position.x += 1000.0f;
            d.bodies.push_back(b);
        }
    } else {
        const int side = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(idle))));
        for (int i = 0; i < idle; ++i) {
            tb::BodyDesc b;
            b.def.position = {1000.0f + 3.0f * static_cast<float>(i % side), 3.0f * static_cast<float>(i / side)};
            tb::ShapeDesc s;
            s.polygon = i2d::makeBox(0.5f, 0.5f);
            b.shapes.push_back(s);
            d.bodies.push_back(b);
        }
    }
    d.settings.enableSleep = true;
    return d;
}

/// The scaling runs, in this order: Impulse2D on 1 worker, on 2 workers, Box2D 2.4.1.
constexpr int kScalingRuns = 3;
const char* const kScalingRunNames[kScalingRuns] = {"impulse2d_1_worker", "impulse2d_2_workers", "box2d"};

/// The median ms per step of `steps` steps of each of `descs`, with nothing
/// between them: the testbed's run (tb::runScene) reads every body after
/// each step for its figures, which takes the engine's own data out of the
/// cache (there 10,000 static boxes made the 100 awake ones 1.16 times
/// slower, stepped alone 1.01). The worlds are stepped in turn, a block of
/// 10 steps each, so that the machine's changes of speed during the run
/// (this shared machine's steps of the same world vary by up to a third
/// from one run to the next) fall on every world alike. Measured one world
/// after the other, 10,000 static boxes beside 100 awake once read as 1.31
/// times the cost of the 100 alone where the same builds, interleaved, gave
/// 1.00.
std::vector<double> bareStepMsInterleaved(const std::vector<tb::SceneDesc>& descs, long steps, EngineKind kind) {
    constexpr long kBlock = 10;
    std::vector<std::unique_ptr<tb::Simulation>> sims;
    for (const tb::SceneDesc& d : descs) sims.push_back(tb::makeSimulation(d, kind));
    std::vector<std::vector<double>> ms(descs.size());
    for (long done = 0; done < steps; done += kBlock)
        for (std::size_t w = 0; w < sims.size(); ++w)
            for (long i = done; i < std::min(done + kBlock, steps); ++i) {
                const auto t0 = std::chrono::steady_clock::now();
                sims[w]->step(descs[w].dt);
                ms[w].push_back(
                    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
            }
    std::vector<double> medians;
    for (const std::vector<double>& m : ms) medians.push_back(median(m));
    return medians;
}

struct ScalingRow {
    int bodies = 0;
    double ms[kScalingRuns] = {0, 0, 0};  ///< medians over the repeats
    /// Per repeat, the ratio to Box2D of the same repeat (1 worker, 2 workers).
    std::vector<double> ratios[2];
    int contacts[kScalingRuns] = {0, 0, 0};
};

struct IdleRow {
    std::string world;
    double ms[2] = {0, 0};  ///< Impulse2D, Box2D
    int awake[2] = {0, 0};  ///< awake dynamic bodies after the last step
};

// ---------------------------------------------------------------- profile --

/// The stages of a step as World::profile() times them, in step order.
constexpr int kStages = 7;
const char* const kStageKeys[kStages] = {"pairs", "narrowphase", "impacts", "solve", "continuous", "proxies", "sleep"};

/// Stage times of one step (ms): the profile's fields, with `continuous`
/// split into the sweeps and the proxy refresh.
std::array<double, kStages> stageTimes(const i2d::Profile& p) {
    return {p.pairs, p.collide, p.impacts, p.solve, p.sweeps, p.continuous - p.sweeps, p.sleep};
}

struct ProfilePlan {
    std::string scene;
    long warm = 0;      ///< steps before the measured ones (the scene settles, pairs are found)
    long measured = 0;  ///< steps whose times are taken
    /// Box2D 2.4.1 runs the same steps; not on many_pyramids, whose first 45
    /// or so steps take 1–2.5 s each in Box2D (about 40 s a run): its ratio
    /// is in the sweep's table.
    bool box2d = true;
};

std::vector<ProfilePlan> profilePlans(bool quick) {
    if (quick)
        return {{"pyramid100", 30, 30, true},
                {"many_pyramids", 10, 10, false},
                {"rain1000", 120, 60, true},
                {"circle_pile1000", 120, 60, true}};
    return {{"pyramid100", 60, 240, true},
            {"many_pyramids", 30, 60, false},
            {"rain1000", 180, 180, true},
            {"circle_pile1000", 180, 180, true}};
}

/// Medians over the measured steps of one run.
struct ProfileRun {
    std::array<double, kStages> stage{};
    double step = 0.0;  ///< the engine's own step time (Profile::step)
    double wall = 0.0;  ///< World::step timed from outside
    int contacts = 0;   ///< touching contacts after the last step
};

/// One run of `desc` in Impulse2D on `workers` workers (a tb::ThreadPool
/// as the task system above 1): `warm` steps, then `measured` steps timed.
ProfileRun profileImpulse(const tb::SceneDesc& desc, int workers, long warm, long measured) {
    tb::Scene scene = tb::buildScene(desc);
    std::unique_ptr<tb::ThreadPool> pool;
    if (workers > 1) {
        pool = std::make_unique<tb::ThreadPool>(workers);
        scene.world->setTaskSystem(pool.get());
    }
    std::vector<double> stage[kStages], step, wall;
    for (long i = 0; i < warm + measured; ++i) {
        const auto t0 = std::chrono::steady_clock::now();
        scene.world->step(desc.dt);
        const auto t1 = std::chrono::steady_clock::now();
        if (i < warm) continue;
        const i2d::Profile& p = scene.world->profile();
        const std::array<double, kStages> t = stageTimes(p);
        for (int k = 0; k < kStages; ++k) stage[k].push_back(t[static_cast<std::size_t>(k)]);
        step.push_back(p.step);
        wall.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
    }
    ProfileRun r;
    for (int k = 0; k < kStages; ++k) r.stage[static_cast<std::size_t>(k)] = median(stage[k]);
    r.step = median(step);
    r.wall = median(wall);
    r.contacts = scene.world->contactCount();
    if (pool) scene.world->setTaskSystem(nullptr);
    return r;
}

/// The same run in Box2D 2.4.1 at 8/3: the median wall time of the measured steps.
double profileBox2D(const tb::SceneDesc& desc, long warm, long measured) {
    std::unique_ptr<tb::Simulation> sim = tb::makeSimulation(desc, EngineKind::box2d, {});
    std::vector<double> wall;
    for (long i = 0; i < warm + measured; ++i) {
        const auto t0 = std::chrono::steady_clock::now();
        sim->step(desc.dt);
        const auto t1 = std::chrono::steady_clock::now();
        if (i >= warm) wall.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
    }
    return median(wall);
}

/// One scene of the profile table: Impulse2D on 1 and 2 workers and Box2D
/// 2.4.1, each figure the median over the repeats of a run's median.
struct ProfileRow {
    ProfilePlan plan;
    int bodies = 0;
    int repeats = 0;
    ProfileRun run[2];              ///< 1 worker, 2 workers
    double box2d = 0.0;             ///< 0 when Box2D does not run the scene here
    std::vector<double> ratios[2];  ///< per repeat, Impulse2D's wall time over Box2D's
};

struct MemoryRow {
    EngineKind engine;
    double perBody = 0, perContact = 0;
    int bodies = 0, contacts = 0;
};

// ---------------------------------------------------------------- output --

struct Options {
    bool quick = false;
    bool scaling = true;
    bool profile = true;
    std::string revision;  ///< the source revision measured, named in the report (--revision)
    std::string out = "build/perf";
    std::string images = "docs/images";
    std::string assets;
    std::vector<std::string> scenes;
};

void writeCsv(const std::vector<SceneResult>& results, const std::string& path) {
    std::ofstream f(path);
    f << "scene,engine,correction,substeps,velocity_iterations,position_iterations,stiffness,impact,reference,seconds,"
         "steps,repeats,"
         "ms_per_step,ms_min_repeat,ms_max_repeat,metric,error,unit,collapsed,nan,displaced,max_penetration,"
         "joint_error_max,bodies\n";
    for (const SceneResult& r : results)
        for (const Point& p : r.points) {
            const auto [mn, mx] = std::minmax_element(p.ms.begin(), p.ms.end());
            f << r.plan.name << ',' << tb::engineName(p.engine) << ','
              << (p.engine == EngineKind::box2d ? "" : correctionName(p.correction)) << ','
              << (p.engine == EngineKind::box2d ? 0 : p.substeps) << ',' << p.velocityIterations << ','
              << p.positionIterations << ',' << (p.engine == EngineKind::box2d ? 0 : p.stiffness) << ','
              << (p.engine == EngineKind::box2d               ? ""
                  : p.impact == i2d::ImpactModel::closed_form ? "closed_form"
                                                              : "velocity_bias")
              << ',' << (p.reference ? 1 : 0) << ',' << r.plan.seconds << ',' << r.steps << ',' << p.ms.size() << ','
              << p.msMedian << ',' << *mn << ',' << *mx << ',' << r.metric << ',' << p.error << ',' << r.unit << ','
              << (p.collapsed ? 1 : 0) << ',' << (p.nan ? 1 : 0) << ',' << p.displaced << ',' << p.maxPenetration << ','
              << p.jointError << ',' << r.bodies << '\n';
        }
}

/// Error floor of the log-scale plots (an exact 0 has no place on them).
constexpr double kPlotFloor = 1e-6;

void writePlots(const std::vector<SceneResult>& results, const std::vector<ScalingRow>& scaling,
                const std::vector<ProfileRow>& profile, const Options& o) {
    namespace fs = std::filesystem;
    const std::string dataDir = o.out + "/plot";
    fs::create_directories(dataDir);
    std::ofstream gp(o.out + "/plots.gp");
    gp << "# Generated by the sweep program: one PNG per scene, error against ms/step.\n"
          "set terminal pngcairo noenhanced size 1000,650 font 'sans,11'\n"
          "set logscale xy\nset grid\nset key top right box opaque\n"
          "set xlabel 'ms per step (median, log scale)'\n";
    for (const SceneResult& r : results) {
        for (EngineKind e : {EngineKind::impulse2d, EngineKind::box2d}) {
            const std::string tag = e == EngineKind::box2d ? "box2d" : "impulse2d";
            std::ofstream all(dataDir + "/" + r.plan.name + "_" + tag + ".dat");
            for (const Point& p : r.points)
                if (p.engine == e && !p.nan)
                    all << p.msMedian << ' ' << std::max(p.error, kPlotFloor) << " \"" << settingsLabel(p) << "\" "
                        << (p.reference ? 1 : 0) << '\n';
            std::ofstream fr(dataDir + "/" + r.plan.name + "_" + tag + "_front.dat");
            for (const Point* p : front(r.points, e))
                fr << p->msMedian << ' ' << std::max(p->error, kPlotFloor) << " \"" << settingsLabel(*p) << "\"\n";
        }
        const std::string d = dataDir + "/" + r.plan.name;
        const bool hasBox2D = std::any_of(r.points.begin(), r.points.end(),
                                          [](const Point& p) { return p.engine == EngineKind::box2d; });
        gp << "\nset output '" << o.images << "/perf_" << r.plan.name << ".png'\n"
           << "set title '" << r.plan.name << ": " << r.metric << " against time per step (" << num(r.plan.seconds)
           << " s runs, sleeping off)'\n"
           << "set ylabel '" << r.metric << (r.unit == "1" ? "" : " (" + r.unit + ")") << ", log scale'\n"
           << "plot '" << d
           << "_impulse2d.dat' using 1:2 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'Impulse2D settings', \\\n"
           << "     '" << d
           << "_impulse2d_front.dat' using 1:2 with steps lw 2 lc rgb '#1f77b4' title 'Impulse2D front', \\\n"
           << "     '" << d
           << "_impulse2d.dat' using ($4 == 1 ? $1 : 1/0):2 with points pt 6 ps 3 lw 2 lc rgb '#1f77b4' title 'Impulse2D defaults', \\\n"
           << "     '" << d
           << "_impulse2d_front.dat' using 1:2:3 with labels offset 0,1 font 'sans,8' tc rgb '#1f77b4' notitle";
        if (hasBox2D)
            gp << ", \\\n     '" << d
               << "_box2d.dat' using 1:2 with points pt 5 ps 1.2 lc rgb '#d62728' title 'Box2D 2.4.1 iterations', \\\n"
               << "     '" << d
               << "_box2d_front.dat' using 1:2 with steps lw 2 dt 2 lc rgb '#d62728' title 'Box2D front', \\\n"
               << "     '" << d
               << "_box2d.dat' using ($4 == 1 ? $1 : 1/0):2 with points pt 4 ps 3 lw 2 lc rgb '#d62728' title 'Box2D 8/3', \\\n"
               << "     '" << d
               << "_box2d.dat' using 1:2:3 with labels offset 0,-1 font 'sans,8' tc rgb '#d62728' notitle";
        gp << "\n";
    }
    if (!scaling.empty()) {
        // bodies, ms (1 worker, 2 workers, Box2D), ratio 1 worker (median, min, max), ratio 2 workers (same).
        std::ofstream sd(dataDir + "/scaling.dat");
        for (const ScalingRow& s : scaling) {
            sd << s.bodies << ' ' << s.ms[0] << ' ' << s.ms[1] << ' ' << s.ms[2];
            for (const std::vector<double>& r : s.ratios)
                sd << ' ' << median(r) << ' ' << *std::min_element(r.begin(), r.end()) << ' '
                   << *std::max_element(r.begin(), r.end());
            sd << '\n';
        }
        const std::string sdat = "'" + dataDir + "/scaling.dat'";
        gp << "\nset output '" << o.images << "/perf_scaling.png'\n"
           << "set title 'ms per step against body count (columns of 10 boxes, sleeping off)'\n"
           << "set xlabel 'dynamic bodies (log scale)'\nset ylabel 'ms per step (median, log scale)'\n"
           << "set key top left box opaque\n"
           << "plot " << sdat
           << " using 1:2 with linespoints pt 7 lw 2 lc rgb '#1f77b4' title 'Impulse2D defaults, 1 worker', \\\n"
           << "     " << sdat
           << " using 1:3 with linespoints pt 9 lw 2 lc rgb '#2ca02c' title 'Impulse2D defaults, 2 workers', \\\n"
           << "     " << sdat
           << " using 1:4 with linespoints pt 5 lw 2 dt 2 lc rgb '#d62728' title 'Box2D 2.4.1 8/3'\n";
        gp << "\nset output '" << o.images << "/perf_scaling_ratio.png'\n"
           << "set title 'Impulse2D ms per step / Box2D 2.4.1 ms per step, same repeat (bars: spread over repeats)'\n"
           << "set xlabel 'dynamic bodies (log scale)'\nset ylabel 'ratio to Box2D 2.4.1 at 8/3'\n"
           << "unset logscale y\nset yrange [0:1.3<*]\nset key top left box opaque\n"
           << "plot " << sdat
           << " using 1:5:6:7 with yerrorlines pt 7 lw 2 lc rgb '#1f77b4' title 'Impulse2D, 1 worker', \\\n"
           << "     " << sdat
           << " using 1:8:9:10 with yerrorlines pt 9 lw 2 lc rgb '#2ca02c' title 'Impulse2D, 2 workers', \\\n"
           << "     1 with lines lw 1 dt 2 lc rgb '#d62728' title 'Box2D 2.4.1 (1.0)'\n"
           << "set logscale y\nset yrange [*:*]\n";
    }
    if (!profile.empty()) {
        // One bar per scene and worker count: each stage's share of the sum of the stage medians.
        std::ofstream pd(dataDir + "/profile.dat");
        for (const ProfileRow& r : profile)
            for (int w = 0; w < 2; ++w) {
                const ProfileRun& m = r.run[w];
                double sum = 0.0;
                for (double t : m.stage) sum += t;
                pd << '"' << r.plan.scene << ", " << w + 1 << (w ? " workers" : " worker") << '"';
                for (double t : m.stage) pd << ' ' << (sum > 0.0 ? 100.0 * t / sum : 0.0);
                pd << '\n';
            }
        const char* colours[kStages] = {"#9467bd", "#ff7f0e", "#8c564b", "#1f77b4", "#d62728", "#2ca02c", "#7f7f7f"};
        gp << "\nset output '" << o.images << "/perf_profile.png'\n"
           << "set title \"Where a step's time goes: each stage's share (Impulse2D defaults, sleeping off)\"\n"
           << "unset logscale xy\nset yrange [0:100]\nset xrange [*:*]\nset xlabel ''\n"
           << "set ylabel 'share of the step (% of the stage medians'' sum)'\n"
           << "set style data histograms\nset style histogram rowstacked\nset style fill solid 0.9 border -1\n"
           << "set boxwidth 0.7\nset key outside right box opaque\nset xtics rotate by -25 font 'sans,9'\n"
           << "plot ";
        for (int k = 0; k < kStages; ++k)
            gp << (k ? ", \\\n     '' using " : ("'" + dataDir + "/profile.dat' using ")) << k + 2
               << (k ? "" : ":xtic(1)") << " lc rgb '" << colours[k] << "' title '" << kStageKeys[k] << "'";
        gp << "\n";
    }
}

}  // namespace

// The markdown is long but plain: one function, in the order of the document.
namespace {

std::string machineLine() {
    std::string cpu = "unknown CPU";
    std::ifstream info("/proc/cpuinfo");
    for (std::string line; std::getline(info, line);)
        if (line.rfind("model name", 0) == 0) {
            cpu = line.substr(line.find(':') + 2);
            break;
        }
    std::ostringstream s;
    s << cpu << ", " << std::thread::hardware_concurrency() << " logical cores (shared with other work), "
      << "g++ " << __GNUC__ << "." << __GNUC_MINOR__ << " Release build (-O3)";
    return s.str();
}

/// Why a scene's front is not at or below Box2D's, where the data say so;
/// filled from what the sweep showed (see docs/performance.md).
const std::map<std::string, std::string>& shortfallNotes() {
    static const std::map<std::string, std::string> notes = {
        {"rain1000",
         "Why: Impulse2D's largest penetration hardly moves with any setting (about 0.3 m). The circles start in "
         "aligned columns and land column by column at about 11 m/s, each circle on the one below (dynamic against "
         "dynamic: continuous collision only sweeps against static shapes), and the impact law's eight sweeps per "
         "step do not carry the momentum through a 25-circle column in one step; Box2D 2.4.1 pushes the overlap out "
         "with its position iterations, which is why its figure falls with them. What it would take: speculative "
         "contact points out to the distance a pair can close in one step instead of the fixed 2 cm, or more impact "
         "sweeps for long columns."},
        {"joint_grid",
         "Why: soft_step caps the joint stiffness at a quarter of the substep rate (15 Hz at 1 substep, 30 at 2; the "
         "60 Hz asked for only from 4 substeps on), so at few substeps its joints are softer than Box2D's rigid rows "
         "with position iterations, and its cheapest step (1 substep) still costs more than Box2D at 2/1 here. What it would take: a joint that stays "
         "stiff at few substeps (a position pass for joints, or a higher cap with the relax pass keeping it stable), "
         "and a cheaper joint row."},
        {"bounce",
         "Why: Impulse2D's rebound falls short by the impact speed times one substep (10 m/s × 1/60 s = 0.167 m at 1 "
         "substep, 0.042 m at 4, 0.021 m at 8, whatever the other settings): in the substep of the impact the ball "
         "stops at the surface instead of travelling back up for the rest of the substep. Box2D 2.4.1 misses by "
         "0.6 mm at every iteration count. What it would take: advancing the rebounding body by its post-impact "
         "velocity over the remainder of the substep (time-of-impact), or more substeps."},
        {"pyramid100",
         "Why: the pyramid's error at Impulse2D's default stiffness is mostly sinking by the soft contacts' "
         "compliance (about 0.3 m at the default 50 Hz, 0.73 m at 30 Hz), which more substeps do not remove; the "
         "stiffer settings (x2, x4 Hz) remove more of it at a higher cost. What it would take: a cheaper substep."},
        {"tall_stack50",
         "Why: both engines let this stack (0.1 m gaps, ±1 cm offsets, friction 0.3) fall at every setting swept, so "
         "the figure compares how far the debris spreads, not whether it stands."},
    };
    return notes;
}

void writeMarkdown(const std::vector<SceneResult>& results, const std::vector<ScalingRow>& scaling,
                   const std::vector<ProfileRow>& profile, const std::vector<MemoryRow>& memory,
                   const std::vector<IdleRow>& idle, const Options& o, double sweepSeconds) {
    std::ofstream md(o.out + "/generated.md");
    md << "## Speed against error (generated)\n\n"
       << "Generated by `scripts/performance.sh" << (o.quick ? " --quick" : "") << "` (the `sweep` program in "
       << "`tests/benchmark/`); do not edit by hand"
       << (o.revision.empty() ? std::string() : ". Source revision `" + o.revision + "`")
       << ". Machine: " << machineLine() << ". dt = 1/60 s, sleeping off, one worker unless a table says otherwise. "
       << "Each point is the median over repeats of a run's median ms/step, the two engines' runs interleaved in "
       << "every repeat; ratios compare figures of the same run. The sweep took " << num(sweepSeconds / 60.0)
       << " minutes" << (o.quick ? " (quick mode: one repeat, few points, short runs; for development only)" : "")
       << ".\n\n";

    md << "**Settings swept.** Impulse2D: its defaults (the scene's settings: `soft_step`, 4 substeps, contact 50 Hz "
          "with damping ratio 25, joints 60 Hz, closed-form impacts); `soft_step` with 1, 2, 3, 4, 6, 8, 12, 16, 24, 32 substeps, with contact "
          "and joint stiffness ×2 (\"x2 Hz\") at 4, 8, 16 substeps and ×4 at 8, 16, 32 (the engine caps contact and "
          "joint hertz at a quarter of the substep rate), and with the velocity-bias impact model "
          "(\"vbias\") at 1, 4, 8 substeps; `baumgarte` with 1, 2, 4, 8, 16, 32 velocity iterations; `split` with 2/1, "
          "4/2, 8/3, 16/6, 32/10 velocity/position iterations. `soft_step` solves once and relaxes once per substep, so "
          "the iteration counts do not apply to it. Box2D 2.4.1: 1/1, 2/1, 4/2, 8/3, 16/6, 32/10 velocity/position "
          "iterations. Run lengths and repeats are in the table; many_pyramids (22,000 boxes) and "
          "circle_pile1000 (to keep the sweep short) run a reduced set (soft step 1, 2, 4, 8 substeps and 8 at ×2, "
          "baumgarte 4 and 16, split 4/2 and 16/6, Box2D 2/1 to 32/10); quick mode runs fewer points still, once "
          "each.\n\n";

    md << "**Error figures** (computed by the testbed, `error` in `testbed run --json`):\n\n"
          "| metric | scenes | definition |\n|---|---|---|\n"
          "| `max_excursion` (m) | pyramids, card_house | largest distance of any dynamic body from its start over the run: sway, sinking, collapse |\n"
          "| `max_sway` (m) | tall stacks (they start with 0.1 m gaps, so settling is no error) | largest sideways distance of any dynamic body from its start over the run |\n"
          "| `max_penetration` (m) | rain1000, circle_pile1000 | largest penetration over the touching contacts over the run |\n"
          "| `joint_stretch` (m) | joint_grid, heavy_chain | largest joint error over the run (`joint_error.max`) |\n"
          "| `rebound_error` (m) | bounce | largest \\|h − e²·d\\| over the balls: d the drop to the lowest point, h the first rebound's height above it, e = max(e_ball, e_ground) (both engines mix restitution by max) |\n"
          "| `energy_drift` (1) | pendulum_wave | largest \\|E(t) − E(0)\\| over the run divided by the pendulums' swing energy |\n\n"
          "*Collapsed*: at least 1% of the dynamic bodies (at least one) end more than 0.5 m sideways from their start.\n\n";

    md << "### Defaults against Box2D 2.4.1 at 8/3\n\n"
          "| scene | bodies | run | Impulse2D defaults ms/step | Box2D 8/3 ms/step | ratio | Impulse2D error | Box2D error | Impulse2D front at or below Box2D's |\n"
          "|---|---|---|---|---|---|---|---|---|\n";
    for (const SceneResult& r : results) {
        const Point* a = reference(r.points, EngineKind::impulse2d);
        const Point* b = reference(r.points, EngineKind::box2d);
        auto bf = front(r.points, EngineKind::box2d);
        int below = 0;
        for (const Point* p : bf)
            if (bestWithin(r.points, EngineKind::impulse2d, p->msMedian) <= errorOf(*p)) ++below;
        md << "| " << r.plan.name << " | " << r.bodies << " | " << num(r.plan.seconds) << " s × " << r.plan.repeats
           << " | " << (a ? num(a->msMedian) : "–") << " | " << (b ? num(b->msMedian) : "–") << " | "
           << (a && b ? "**" + fmt("%.2f", a->msMedian / b->msMedian) + "**" : "–") << " | "
           << (a ? errText(*a, r.unit) : "–") << " | " << (b ? errText(*b, r.unit) : "–") << " | "
           << (bf.empty() ? std::string("no Box2D run")
                          : std::to_string(below) + " of " + std::to_string(bf.size()) + " Box2D front points")
           << " |\n";
    }
    md << "\n";

    // The bar on pyramid100.
    for (const SceneResult& r : results) {
        if (r.plan.name != "pyramid100") continue;
        const Point* a = reference(r.points, EngineKind::impulse2d);
        const Point* b = reference(r.points, EngineKind::box2d);
        if (!a || !b) break;
        const double ratio = a->msMedian / b->msMedian;
        md << "**Bar: pyramid100.** At its defaults Impulse2D's pyramid " << (a->collapsed ? "**collapses**" : "stands")
           << " (" << (a->collapsed ? "" : "fewer than 1% of the boxes end more than 0.5 m sideways; ")
           << "largest excursion " << num(a->error) << " m; " << a->displaced
           << " boxes end more than 0.5 m from their start, sinking included) and costs **" << fmt("%.2f", ratio)
           << "×** Box2D 2.4.1's time at 8/3 in the same run (bar: ≤ 0.5×: " << (ratio <= 0.5 ? "met" : "**not met**")
           << "); Box2D's pyramid at 8/3 " << (b->collapsed ? "does not hold" : "stands") << " (largest excursion "
           << num(b->error) << " m; " << b->displaced << " boxes end more than 0.5 m from their start).\n\n";
    }

    md << "### Per scene\n\n";
    for (const SceneResult& r : results) {
        const Point* a = reference(r.points, EngineKind::impulse2d);
        const Point* b = reference(r.points, EngineKind::box2d);
        auto af = front(r.points, EngineKind::impulse2d);
        auto bf = front(r.points, EngineKind::box2d);
        md << "#### " << r.plan.name << "\n\n![" << r.plan.name << ": " << r.metric
           << " against ms per step](images/perf_" << r.plan.name << ".png)\n\n";
        md << r.description << " (" << r.bodies << " bodies; " << num(r.plan.seconds) << " s per run, "
           << r.plan.repeats << (r.plan.repeats == 1 ? " repeat" : " repeats") << "; metric `" << r.metric << "`). ";
        if (a && b) {
            md << "At its defaults Impulse2D takes " << num(a->msMedian) << " ms per step, "
               << fmt("%.2f", a->msMedian / b->msMedian) << "× Box2D's " << num(b->msMedian)
               << " ms at 8/3, with error " << errText(*a, r.unit) << " against " << errText(*b, r.unit) << ". ";
        } else if (a) {
            md << "At its defaults Impulse2D takes " << num(a->msMedian) << " ms per step with error "
               << errText(*a, r.unit) << ". " << r.plan.box2dNote << " ";
        }
        if (!af.empty()) {
            const Point* cheap = af.front();
            const Point* best = af.back();
            md << "Impulse2D's front runs from " << settingsLabel(*cheap) << " (" << num(cheap->msMedian) << " ms, "
               << errText(*cheap, r.unit) << ") to " << settingsLabel(*best) << " (" << num(best->msMedian) << " ms, "
               << errText(*best, r.unit) << ")";
        }
        if (!bf.empty()) {
            const Point* cheap = bf.front();
            const Point* best = bf.back();
            md << "; Box2D's from " << settingsLabel(*cheap) << " (" << num(cheap->msMedian) << " ms, "
               << errText(*cheap, r.unit) << ") to " << settingsLabel(*best) << " (" << num(best->msMedian) << " ms, "
               << errText(*best, r.unit) << "). ";
            std::vector<const Point*> above;
            for (const Point* p : bf)
                if (!(bestWithin(r.points, EngineKind::impulse2d, p->msMedian) <= errorOf(*p))) above.push_back(p);
            if (above.empty()) {
                md << "For every point of Box2D's front Impulse2D has a setting at most as slow with at most its error: "
                      "**Impulse2D's front is at or below Box2D's everywhere**.";
            } else {
                md << "**Impulse2D's front is not below Box2D's at " << above.size() << " of " << bf.size()
                   << " Box2D front points**: ";
                for (std::size_t k = 0; k < above.size(); ++k) {
                    const Point* p = above[k];
                    const double mine = bestWithin(r.points, EngineKind::impulse2d, p->msMedian);
                    md << (k ? "; " : "") << "Box2D " << settingsLabel(*p) << " (" << num(p->msMedian) << " ms, "
                       << errText(*p, r.unit) << ") against Impulse2D's best within that time: "
                       << (std::isfinite(mine) ? num(mine) + (r.unit == "1" ? "" : " " + r.unit)
                                               : "no setting that fast");
                }
                md << ".";
                auto it = shortfallNotes().find(r.plan.name);
                if (it != shortfallNotes().end()) md << " " << it->second;
            }
        } else if (!af.empty()) {
            md << ".";
        }
        md << "\n\n";
    }

    if (!scaling.empty()) {
        const ScalingRow& last = scaling.back();
        md << "### Scaling, on 1 and 2 workers\n\n![ms per step against body count](images/perf_scaling.png)\n\n"
              "![ratio to Box2D 2.4.1 against body count](images/perf_scaling_ratio.png)\n\n"
              "Columns of 10 boxes (1 m, resting, 1.5 m apart) on one ground box, "
           << (o.quick ? "20 steps per run, 1 repeat (quick mode)" : "1 s per run, 3 repeats")
           << "; Impulse2D at its defaults on 1 worker and on 2 workers (a `std::thread` pool as the world's task "
              "system, `testbed run --threads 2`), Box2D 2.4.1 at 8/3 (one thread: it has no other), sleeping off. In "
              "each repeat the three runs go in turn, in an order rotated by the repeat; a figure is the median over "
              "the repeats of a run's median ms/step, and a ratio is the median over the repeats of Impulse2D's time "
              "over Box2D's in the same repeat, with its spread (smallest–largest over the repeats) in brackets. The "
              "world hands work to its second worker only in steps large enough to gain from it, so the small "
              "worlds run on one either way. The two workers share the machine's "
           << std::thread::hardware_concurrency()
           << " cores with whatever else runs on it, so the 2-worker figures are the noisiest.\n\n"
              "| dynamic bodies | Impulse2D 1 worker ms/step | Impulse2D 2 workers ms/step | Box2D ms/step | ratio, 1 "
              "worker | ratio, 2 workers | 2 workers' speed-up | Impulse2D µs per body (1 worker) | Box2D µs per body "
              "|\n|---|---|---|---|---|---|---|---|---|\n";
        auto ratioText = [](const std::vector<double>& r) {
            std::string t = "**" + fmt("%.2f", median(r)) + "**";
            if (r.size() > 1)
                t += " (" + fmt("%.2f", *std::min_element(r.begin(), r.end())) + "–" +
                     fmt("%.2f", *std::max_element(r.begin(), r.end())) + ")";
            return t;
        };
        for (const ScalingRow& s : scaling)
            md << "| " << s.bodies << " | " << num(s.ms[0]) << " | " << num(s.ms[1]) << " | " << num(s.ms[2]) << " | "
               << ratioText(s.ratios[0]) << " | " << ratioText(s.ratios[1]) << " | " << fmt("%.2f", s.ms[0] / s.ms[1])
               << "× | " << num(1000.0 * s.ms[0] / s.bodies) << " | " << num(1000.0 * s.ms[2] / s.bodies) << " |\n";
        md << "\nAt " << last.bodies << " bodies Impulse2D takes " << num(last.ms[0]) << " ms per step on 1 worker and "
           << num(last.ms[1]) << " on 2 (" << fmt("%.2f", last.ms[0] / last.ms[1]) << "× faster), against Box2D "
           << "2.4.1's " << num(last.ms[2]) << " ms: " << fmt("%.2f", median(last.ratios[0])) << "× and "
           << fmt("%.2f", median(last.ratios[1])) << "× its time.\n\n";
    }
    if (!profile.empty()) {
        md << "### Where a step's time goes\n\n![each stage's share of a step](images/perf_profile.png)\n\n"
           << "Impulse2D at its defaults (the scene's settings), sleeping off, timed stage by stage by "
              "`World::profile()`"
           << (o.revision.empty() ? std::string() : ", source revision `" + o.revision + "`")
           << ". Each run steps the scene from its start, leaves the first steps untimed (the pile and the rain "
              "land, pairs are found) and times the next ones; a figure is the median over the timed steps of one "
              "run, then the median over the repeats. In each repeat Impulse2D on 1 worker, on 2 workers (a "
              "`std::thread` pool as the world's task system) and Box2D 2.4.1 at 8/3 (wall time of the same "
              "steps) run in turn, in an order rotated by the repeat; the ratio is the median over the repeats of "
              "Impulse2D's wall time over Box2D's in the same repeat, its spread (smallest–largest) in brackets. "
              "Stage medians need not add up to the step's median; the bracket after a stage is its share of "
              "their sum. ";
        for (const ProfileRow& r : profile)
            if (!r.plan.box2d)
                md << "Box2D does not run " << r.plan.scene << " here: its first 45 or so steps take 1–2.5 s each "
                   << "in Box2D 2.4.1 (about 40 s a run); its ratio is in the sweep's table of a full run. ";
        md << "The figures stand alone: the table of another revision, made by the same command on the same "
              "machine, is its before or after.\n\n"
              "| stage | what it times |\n|---|---|\n"
              "| pairs | the broadphase: new pairs among the moved boxes, their contacts created |\n"
              "| narrowphase | the contacts' manifolds, contacts whose boxes stopped overlapping destroyed |\n"
              "| impacts | the closed-form impact law at approaching contacts |\n"
              "| solve | the solver: awake bodies gathered, rows coloured and prepared, the substeps (integrate, warm "
              "start, solve, relax), restitution, impulses and positions stored |\n"
              "| continuous | fast bodies swept against static and kinematic shapes (and bullets) |\n"
              "| proxies | the broadphase boxes moved of the bodies the solve's write-back found outside them (or continuous collision moved) |\n"
              "| sleep | the sleep test and freeing the step's large arrays |\n\n"
              "| scene | bodies | touching contacts | steps untimed + timed × repeats | workers | step ms "
              "(wall) |";
        for (const char* k : kStageKeys) md << " " << k << " ms |";
        md << " Box2D 2.4.1 8/3 ms | ratio |\n|---|---|---|---|---|---|";
        for (int k = 0; k < kStages; ++k) md << "---|";
        md << "---|---|\n";
        for (const ProfileRow& r : profile)
            for (int w = 0; w < 2; ++w) {
                const ProfileRun& m = r.run[w];
                double sum = 0.0;
                for (double t : m.stage) sum += t;
                md << "| " << r.plan.scene << " | " << r.bodies << " | " << m.contacts << " | " << r.plan.warm << " + "
                   << r.plan.measured << " × " << r.repeats << " | " << w + 1 << " | **" << num(m.wall) << "** |";
                for (double t : m.stage)
                    md << " " << num(t) << " (" << fmt("%.0f", sum > 0.0 ? 100.0 * t / sum : 0.0) << " %) |";
                const std::vector<double>& q = r.ratios[w];
                if (q.empty()) {
                    md << " – | – |\n";
                    continue;
                }
                md << " " << num(r.box2d) << " | **" << fmt("%.2f", median(q)) << "**";
                if (q.size() > 1)
                    md << " (" << fmt("%.2f", *std::min_element(q.begin(), q.end())) << "–"
                       << fmt("%.2f", *std::max_element(q.begin(), q.end())) << ")";
                md << " |\n";
            }
        md << "\n";
    }
    if (!memory.empty()) {
        md << "### Memory\n\nMeasured as the growth of the C library's heap in use (glibc `mallinfo2()`: heap chunks in use plus separately mapped blocks) from "
              "before a world is built to after it has stepped: per body, "
              "N boxes scattered in empty space (no contacts) stepped twice, divided by N "
              "(body, shape, broadphase proxy and what the world keeps between steps); per contact, the same boxes in "
              "touching columns on a ground box stepped twice, minus the scattered figure, divided by the touching "
              "contacts (contact, manifold, pair set; speculative contacts that do not touch are counted "
              "in the cost but not in the divisor). This is the memory a world holds between steps: Impulse2D "
              "keeps its per-step arrays between steps while they hold at most 64 kB in all (so small worlds "
              "step without allocating) and frees them when the step ends otherwise, as Box2D 2.4.1 keeps a "
              "100 kB stack and allocates its solver arrays beyond it per step. Box2D 2.4.1 takes memory from its block allocator in 16 kB "
              "chunks, which this counts as allocated. The testbed keeps no copy of the scene description "
              "for either engine. Measured at several N: both engines' arrays grow in steps (Impulse2D's by an eighth, "
              "Box2D 2.4.1's tree and buffers by doubling), so each N lands at another point of their growth. "
              "`memory_footprint [N]` prints the same figures alone.\n\n"
              "| bodies N | touching contacts | Impulse2D bytes per body | Box2D 2.4.1 bytes per body | Impulse2D "
              "bytes per touching contact | Box2D 2.4.1 bytes per touching contact |\n|---|---|---|---|---|---|\n";
        for (const MemoryRow& m : memory) {
            if (m.engine != EngineKind::impulse2d) continue;
            const MemoryRow* b = nullptr;
            for (const MemoryRow& r : memory)
                if (r.engine == EngineKind::box2d && r.bodies == m.bodies) b = &r;
            md << "| " << m.bodies << " | " << m.contacts << " | " << fmt("%.0f", m.perBody) << " | "
               << (b ? fmt("%.0f", b->perBody) : std::string("–")) << " | " << fmt("%.0f", m.perContact) << " | "
               << (b ? fmt("%.0f", b->perContact) : std::string("–")) << " |\n";
        }
        md << "\n";
    }
    if (!idle.empty()) {
        md << "### What idle bodies cost\n\n100 awake boxes (10 columns of 10 that never sleep), alone, next to 10,000 "
              "static boxes, and next to 10,000 dynamic boxes resting in columns of 10 on their own ground, which fall "
              "asleep within the first second; far from the awake ones, world sleeping on, 300 steps per run (the "
              "median step is one with the columns asleep), engines in turn, an engine's three worlds stepped in turn, "
              "10 steps each, with nothing else between their steps (the testbed's per-step figures read every body and would charge the idle ones "
              "for the cache they take). Ratio to the 100 boxes alone "
              "(1.00 = free); *awake* counts the awake dynamic bodies after the last step:\n\n"
              "| world | Impulse2D ms/step | ratio | awake | Box2D ms/step | ratio | awake |\n|---|---|---|---|---|---|---|\n";
        const double base0 = idle.front().ms[0], base1 = idle.front().ms[1];
        for (const IdleRow& r : idle)
            md << "| " << r.world << " | " << num(r.ms[0]) << " | " << fmt("%.2f", r.ms[0] / base0) << " | "
               << r.awake[0] << " | " << num(r.ms[1]) << " | " << fmt("%.2f", r.ms[1] / base1) << " | " << r.awake[1]
               << " |\n";
        md << "\n";
    }
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto next = [&]() -> std::string {
            if (i + 1 >= argc) {
                std::fprintf(stderr, "sweep: %s needs a value\n", a.c_str());
                std::exit(2);
            }
            return argv[++i];
        };
        if (a == "--quick")
            o.quick = true;
        else if (a == "--no-scaling")
            o.scaling = false;
        else if (a == "--no-profile")
            o.profile = false;
        else if (a == "--revision")
            o.revision = next();
        else if (a == "--out")
            o.out = next();
        else if (a == "--images")
            o.images = next();
        else if (a == "--assets")
            o.assets = next();
        else if (a == "--scenes") {
            std::stringstream ss(next());
            for (std::string s; std::getline(ss, s, ',');) o.scenes.push_back(s);
        } else {
            std::fprintf(
                stderr,
                "usage: sweep [--quick] [--out DIR] [--images DIR] [--assets DIR] [--scenes a,b,...] [--no-scaling] "
                "[--no-profile] [--revision TEXT]\n");
            return a == "--help" || a == "-h" ? 0 : 2;
        }
    }
    if (!tb::box2dAvailable()) {
        std::fprintf(stderr, "sweep: the testbed was built without Box2D 2.4.1\n");
        return 1;
    }
    std::filesystem::create_directories(o.out);
    const auto t0 = std::chrono::steady_clock::now();

    // Plan: load every scene and its points first, so the progress bar knows the total.
    std::vector<SceneResult> results;
    std::vector<tb::SceneDesc> descs;
    double total = 0.0;
    for (const ScenePlan& plan : plans(o.quick)) {
        if (!o.scenes.empty() && std::find(o.scenes.begin(), o.scenes.end(), plan.name) == o.scenes.end()) continue;
        SceneResult r;
        r.plan = plan;
        tb::SceneDesc desc = tb::loadSceneDesc(plan.name, o.assets);
        r.description = desc.description;
        r.bodies = static_cast<int>(desc.bodies.size());
        r.steps = std::lround(plan.seconds / static_cast<double>(desc.dt));
        r.metric = tb::errorMetricName(tb::errorMetricFor(plan.name));
        r.unit = tb::errorMetricUnit(tb::errorMetricFor(plan.name));
        r.points = sweepPoints(desc.settings, plan.level, plan.box2d);
        for (const Point& p : r.points) total += plan.repeats * runCost(p, r.bodies, r.steps);
        results.push_back(std::move(r));
        descs.push_back(std::move(desc));
    }
    const std::vector<int> counts = o.quick ? std::vector<int>{100, 1000, 5000}
                                            : std::vector<int>{100, 300, 1000, 3000, 10000, 20000};
    const int scalingSteps = o.quick ? 20 : 60, scalingRepeats = o.quick ? 1 : 3;
    if (o.scaling)
        for (int n : counts) total += scalingRepeats * kScalingRuns * runCost(box2d(8, 3), n, scalingSteps) * 3;

    std::vector<ProfileRow> profile;
    std::vector<tb::SceneDesc> profileDescs;
    if (o.profile)
        for (const ProfilePlan& plan : profilePlans(o.quick)) {
            ProfileRow row;
            row.plan = plan;
            row.repeats = o.quick ? 1 : 3;
            tb::SceneDesc desc = tb::loadSceneDesc(plan.scene, o.assets);
            desc.settings.enableSleep = false;
            row.bodies = static_cast<int>(desc.bodies.size());
            Point def;
            total += row.repeats * (plan.box2d ? 3 : 2) * runCost(def, row.bodies, plan.warm + plan.measured);
            profile.push_back(row);
            profileDescs.push_back(std::move(desc));
        }

    Progress progress(total);
    for (std::size_t s = 0; s < results.size(); ++s) {
        SceneResult& r = results[s];
        for (int rep = 0; rep < r.plan.repeats; ++rep)
            for (std::size_t k : interleavedOrder(r.points, rep)) {
                Point& p = r.points[k];
                progress.advance(0.0,
                                 r.plan.name + " " + std::string(tb::engineName(p.engine)) + " " + settingsLabel(p));
                tb::RunReport rep_ = runPoint(descs[s], p, r.steps);
                p.ms.push_back(rep_.msMedian);
                if (rep == 0) {
                    p.error = rep_.error.value;
                    p.collapsed = rep_.error.collapsed;
                    p.nan = rep_.nan;
                    p.displaced = rep_.displaced;
                    p.maxPenetration = rep_.maxPenetration;
                    p.jointError = rep_.jointErrorMax;
                }
                progress.advance(runCost(p, r.bodies, r.steps), r.plan.name);
            }
        for (Point& p : r.points) p.msMedian = median(p.ms);
    }

    std::vector<ScalingRow> scaling;
    std::vector<MemoryRow> memory;
    std::vector<IdleRow> idle;
    if (o.scaling) {
        for (int n : counts) {
            ScalingRow row;
            row.bodies = n;
            tb::SceneDesc desc = columnsScene(n, true);
            desc.settings.enableSleep = false;
            std::vector<double> ms[kScalingRuns];
            for (int rep = 0; rep < scalingRepeats; ++rep) {
                double repMs[kScalingRuns] = {};
                // The three runs in a rotating order, so no run always goes first.
                for (int e = 0; e < kScalingRuns; ++e) {
                    const int which = (e + rep) % kScalingRuns;
                    const EngineKind kind = which == 2 ? EngineKind::box2d : EngineKind::impulse2d;
                    desc.threads = which == 1 ? 2 : 1;
                    progress.advance(0.0, "scaling " + std::to_string(n) + " " + kScalingRunNames[which]);
                    tb::RunReport rr = tb::runScene(desc, scalingSteps, kind, {}, nullptr, false);
                    ms[which].push_back(rr.msMedian);
                    repMs[which] = rr.msMedian;
                    row.contacts[which] = rr.contacts;
                    progress.advance(runCost(box2d(8, 3), n, scalingSteps) * 3, "scaling");
                }
                for (int w = 0; w < 2; ++w) row.ratios[w].push_back(repMs[w] / repMs[2]);
            }
            for (int k = 0; k < kScalingRuns; ++k) row.ms[k] = median(ms[k]);
            scaling.push_back(row);
        }
        // Several sizes: both engines' arrays grow in steps, so one size
        // lands each at one point of its growth.
        for (const int memBodies : {500, 1000, 2000, 5000, 7000, 10000, 20000})
            for (EngineKind kind : {EngineKind::impulse2d, EngineKind::box2d}) {
                progress.advance(0.0, std::string("memory ") + tb::engineName(kind));
                MemoryRow m;
                m.engine = kind;
                m.bodies = memBodies;
                const std::size_t scattered = heldBytes(columnsScene(memBodies, false), kind, 2, nullptr);
                const std::size_t columns = heldBytes(columnsScene(memBodies, true), kind, 2, &m.contacts);
                m.perBody = static_cast<double>(scattered) / memBodies;
                m.perContact = m.contacts > 0
                                   ? (static_cast<double>(columns) - static_cast<double>(scattered)) / m.contacts
                                   : 0.0;
                memory.push_back(m);
            }
        // Long enough that the resting columns sleep for most of the run
        // (the median step is then a step with them asleep).
        const long idleSteps = 300;
        const int idleRepeats = o.quick ? 1 : 3;
        const std::pair<const char*, tb::SceneDesc> worlds[] = {{"100 awake alone", idleScene(0, false)},
                                                                {"+ 10,000 static", idleScene(10000, false)},
                                                                {"+ 10,000 sleeping", idleScene(10000, true)}};
        std::vector<double> ms[3][2];
        int awake[3][2] = {};
        const std::vector<tb::SceneDesc> descs = {worlds[0].second, worlds[1].second, worlds[2].second};
        for (int rep = 0; rep < idleRepeats; ++rep)
            for (int e = 0; e < 2; ++e) {
                const EngineKind kind = e ? EngineKind::box2d : EngineKind::impulse2d;
                progress.advance(0.0, std::string("idle bodies ") + tb::engineName(kind));
                const std::vector<double> medians = bareStepMsInterleaved(descs, idleSteps, kind);
                for (int w = 0; w < 3; ++w) {
                    ms[w][e].push_back(medians[static_cast<std::size_t>(w)]);
                    if (rep == 0)
                        awake[w][e] = tb::runScene(worlds[w].second, idleSteps, kind, {}, nullptr, false).awakeBodies;
                }
            }
        for (int w = 0; w < 3; ++w)
            idle.push_back({worlds[w].first, {median(ms[w][0]), median(ms[w][1])}, {awake[w][0], awake[w][1]}});
    }
    for (std::size_t s = 0; s < profile.size(); ++s) {
        ProfileRow& row = profile[s];
        const tb::SceneDesc& desc = profileDescs[s];
        std::vector<ProfileRun> runs[2];
        std::vector<double> box;
        const double cost = runCost(Point{}, row.bodies, row.plan.warm + row.plan.measured);
        for (int rep = 0; rep < row.repeats; ++rep) {
            double repMs[3] = {};
            // Impulse2D on 1 worker, on 2, Box2D: in turn, the order rotated by the repeat.
            for (int e = 0; e < 3; ++e) {
                const int which = (e + rep) % 3;
                if (which == 2 && !row.plan.box2d) continue;
                progress.advance(0.0, "profile " + row.plan.scene + " " + kScalingRunNames[which]);
                if (which == 2) {
                    box.push_back(profileBox2D(desc, row.plan.warm, row.plan.measured));
                    repMs[2] = box.back();
                } else {
                    runs[which].push_back(profileImpulse(desc, which + 1, row.plan.warm, row.plan.measured));
                    repMs[which] = runs[which].back().wall;
                }
                progress.advance(cost, "profile");
            }
            if (row.plan.box2d)
                for (int w = 0; w < 2; ++w) row.ratios[w].push_back(repMs[w] / repMs[2]);
        }
        for (int w = 0; w < 2; ++w) {
            auto med = [&](auto field) {
                std::vector<double> v;
                for (const ProfileRun& r : runs[w]) v.push_back(field(r));
                return median(v);
            };
            ProfileRun& m = row.run[w];
            for (std::size_t k = 0; k < kStages; ++k) m.stage[k] = med([k](const ProfileRun& r) { return r.stage[k]; });
            m.step = med([](const ProfileRun& r) { return r.step; });
            m.wall = med([](const ProfileRun& r) { return r.wall; });
            m.contacts = runs[w].back().contacts;
        }
        row.box2d = median(box);
    }
    progress.finish();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    writeCsv(results, o.out + "/sweep.csv");
    if (!scaling.empty()) {
        std::ofstream f(o.out + "/scaling.csv");
        f << "bodies,impulse2d_1_worker_ms_per_step,impulse2d_2_workers_ms_per_step,box2d_ms_per_step,"
             "ratio_1_worker_min,ratio_1_worker_max,ratio_2_workers_min,ratio_2_workers_max,impulse2d_contacts,"
             "box2d_contacts\n";
        for (const ScalingRow& s : scaling) {
            f << s.bodies << ',' << s.ms[0] << ',' << s.ms[1] << ',' << s.ms[2];
            for (const std::vector<double>& r : s.ratios)
                f << ',' << *std::min_element(r.begin(), r.end()) << ',' << *std::max_element(r.begin(), r.end());
            f << ',' << s.contacts[0] << ',' << s.contacts[2] << '\n';
        }
        std::ofstream m(o.out + "/memory.csv");
        m << "engine,bytes_per_body,bytes_per_touching_contact,bodies,touching_contacts\n";
        for (const MemoryRow& r : memory)
            m << tb::engineName(r.engine) << ',' << r.perBody << ',' << r.perContact << ',' << r.bodies << ','
              << r.contacts << '\n';
        std::ofstream id(o.out + "/idle.csv");
        id << "world,impulse2d_ms_per_step,box2d_ms_per_step,impulse2d_awake,box2d_awake\n";
        for (const IdleRow& r : idle)
            id << '"' << r.world << "\"," << r.ms[0] << ',' << r.ms[1] << ',' << r.awake[0] << ',' << r.awake[1]
               << '\n';
    }
    if (!profile.empty()) {
        std::ofstream f(o.out + "/profile.csv");
        f << "scene,bodies,workers,warm_steps,measured_steps,repeats";
        for (const char* k : kStageKeys) f << ',' << k << "_ms";
        f << ",step_ms,wall_ms,box2d_wall_ms,ratio_median,ratio_min,ratio_max,touching_contacts\n";
        for (const ProfileRow& r : profile)
            for (int w = 0; w < 2; ++w) {
                const ProfileRun& m = r.run[w];
                f << r.plan.scene << ',' << r.bodies << ',' << w + 1 << ',' << r.plan.warm << ',' << r.plan.measured
                  << ',' << r.repeats;
                for (double t : m.stage) f << ',' << t;
                const std::vector<double>& q = r.ratios[w];
                f << ',' << m.step << ',' << m.wall << ',';
                if (q.empty())
                    f << ",,,,";
                else
                    f << r.box2d << ',' << median(q) << ',' << *std::min_element(q.begin(), q.end()) << ','
                      << *std::max_element(q.begin(), q.end()) << ',';
                f << m.contacts << '\n';
            }
    }
    writePlots(results, scaling, profile, o);
    writeMarkdown(results, scaling, profile, memory, idle, o, seconds);
    std::fprintf(stderr, "sweep: %.0f s; wrote %s/sweep.csv, plots.gp, generated.md\n", seconds, o.out.c_str());
    return 0;
}
