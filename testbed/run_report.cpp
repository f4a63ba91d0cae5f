// Testbed — stepping a scene and measuring it (see run_report.hpp).
#include "run_report.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "crossing_check.hpp"
#include "metrics.hpp"

namespace tb {

RunReport runScene(const SceneDesc& desc, long steps, EngineKind engine, const Box2DSettings& box2d,
                   StepObserver* observer, bool checkCrossings) {
    std::unique_ptr<Simulation> sim = makeSimulation(desc, engine, box2d);
    RunReport rep;
    rep.scene = desc.name;
    rep.engine = engine;
    rep.notes = sim->notes();
    rep.settings = desc.settings;
    rep.box2d = box2d;
    rep.steps = steps;
    rep.dt = desc.dt;
    rep.bodies = sim->bodyCount();
    rep.joints = sim->jointCount();

    std::vector<std::pair<std::string, int>> named;
    for (std::size_t i = 0; i < desc.bodies.size(); ++i)
        if (!desc.bodies[i].name.empty()) named.emplace_back(desc.bodies[i].name, static_cast<int>(i));
    std::sort(named.begin(), named.end());
    for (const auto& [name, index] : named) {
        BodySample s = sim->sample(index);
        rep.named.push_back({name, s.x, s.y, s.angle, s.x, s.y, s.angle, s.vx, s.vy, s.w, 0.0f, s.y, s.y});
    }
    std::vector<BodySample> start;
    start.reserve(static_cast<std::size_t>(rep.bodies));
    for (int i = 0; i < rep.bodies; ++i) start.push_back(sim->sample(i));

    const i2d::Vec2 g = desc.settings.gravity;
    rep.energyInitial = rep.energyMax = rep.energyFinal = computeEnergy(*sim, g).total();
    rep.nan = !allFinite(*sim);
    rep.jointErrorMax = rep.jointErrorFinal = maxJointError(desc, *sim);
    ErrorTracker tracker(desc, errorMetricFor(desc.name));
    tracker.start(*sim);
    CrossingCheck crossings(desc);
    crossings.start(*sim);

    std::vector<double> ms;
    ms.reserve(static_cast<std::size_t>(steps));
    std::vector<std::vector<double>> stageMs;  // by stage, then step
    for (long i = 0; i < steps && !rep.nan; ++i) {
        auto t0 = std::chrono::steady_clock::now();
        sim->step(desc.dt);
        auto t1 = std::chrono::steady_clock::now();
        ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
        ++rep.stepsCompleted;
        const std::vector<std::pair<const char*, double>> stages = sim->stageTimes();
        if (rep.stageMedians.empty())
            for (const auto& st : stages) rep.stageMedians.emplace_back(st.first, 0.0);
        stageMs.resize(stages.size());
        for (std::size_t k = 0; k < stages.size(); ++k) stageMs[k].push_back(stages[k].second);
        if (observer) observer->afterStep(rep.stepsCompleted, *sim);

        rep.maxContacts = std::max(rep.maxContacts, sim->touchingContactCount());
        const float penetration = sim->maxPenetration();
        rep.maxPenetration = std::max(rep.maxPenetration, penetration);
        rep.finalPenetration = penetration;
        const double speed = largestBodySpeed(*sim);
        if (!(speed <= rep.maxSpeed)) rep.maxSpeed = speed;
        if (!allFinite(*sim)) {
            rep.nan = true;
            break;
        }
        double e = computeEnergy(*sim, g).total();
        rep.energyMax = std::max(rep.energyMax, e);
        rep.energyFinal = e;
        rep.jointErrorFinal = maxJointError(desc, *sim);
        rep.jointErrorMax = std::max(rep.jointErrorMax, rep.jointErrorFinal);
        tracker.observe(*sim, penetration, rep.jointErrorFinal);
        if (checkCrossings) crossings.observe(*sim);
        for (std::size_t k = 0; k < named.size(); ++k) {
            BodySample s = sim->sample(named[k].second);
            RunReport::Named& nb = rep.named[k];
            nb.maxDx = std::max(nb.maxDx, std::abs(s.x - nb.x0));
            nb.minY = std::min(nb.minY, s.y);
            nb.maxY = std::max(nb.maxY, s.y);
        }
    }
    rep.error = tracker.result(*sim);
    rep.tunnelled = crossings.tunnelled();
    rep.snagged = crossings.snagged();
    rep.driven = crossings.driven();
    rep.drivenMaxVerticalSpeed = crossings.drivenMaxVerticalSpeed();
    rep.contacts = sim->touchingContactCount();
    for (int i = 0; i < rep.bodies; ++i) {
        BodySample s = sim->sample(i);
        if (s.awake && s.dynamic) ++rep.awakeBodies;
        const BodySample& s0 = start[static_cast<std::size_t>(i)];
        if (s.dynamic && std::hypot(s.x - s0.x, s.y - s0.y) > RunReport::kDisplacedDistance) ++rep.displaced;
    }
    auto median = [](std::vector<double>& v) {
        std::sort(v.begin(), v.end());
        const std::size_t n = v.size();
        return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
    };
    if (!ms.empty()) {
        std::vector<double> sorted = ms;
        rep.msMedian = median(sorted);
        rep.msMin = sorted.front();
        rep.msMax = sorted.back();
    }
    for (std::size_t k = 0; k < rep.stageMedians.size() && k < stageMs.size(); ++k)
        if (!stageMs[k].empty()) rep.stageMedians[k].second = median(stageMs[k]);
    for (std::size_t k = 0; k < named.size(); ++k) {
        BodySample s = sim->sample(named[k].second);
        RunReport::Named& nb = rep.named[k];
        nb.x = s.x;
        nb.y = s.y;
        nb.angle = s.angle;
        nb.vx = s.vx;
        nb.vy = s.vy;
        nb.w = s.w;
    }
    return rep;
}

}  // namespace tb
