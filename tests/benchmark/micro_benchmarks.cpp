// Micro-benchmarks of the engine's primitives (Google Benchmark), with Box2D
// 2.4.1's equivalent beside ours where it has one, so a ratio comes from one
// run of one binary (issue: speed against error).
//
//   micro_benchmarks [--benchmark_filter=REGEX] [--benchmark_repetitions=N]
//
// Names: <engine>/<primitive>/<case>. "i2d" is Impulse2D, "b2d" is Box2D 2.4.1.
// Every timed loop feeds its result to benchmark::DoNotOptimize, and inputs
// vary from iteration to iteration where the primitive could otherwise be
// answered from a cache (tree moves).
#include <benchmark/benchmark.h>
#include <box2d/box2d.h>
#include <impulse2d/impulse2d.hpp>

#include "pyramid.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <vector>

#include "dynamic_tree.hpp"  // engine-internal broadphase tree

namespace {

using Clock = std::chrono::steady_clock;

// A small deterministic generator (xorshift32) so both engines get the same inputs.
struct Random {
    std::uint32_t state = 0x9E3779B9u;
    float next() {  // [0, 1)
        state ^= state << 13;
        state ^= state >> 17;
        state ^= state << 5;
        return static_cast<float>(state >> 8) * (1.0f / 16777216.0f);
    }
    float range(float lo, float hi) { return lo + (hi - lo) * next(); }
};

// ---------------------------------------------------------------------------
// Broadphase: N proxies of about 1 m in a square of side 2·√N m (density of a
// busy scene). One iteration moves one proxy (round robin) by a random step
// larger than the fattening margin, so the leaf is always re-inserted, then
// queries the moved box. Both trees get the same boxes and moves.

struct TreeCase {
    std::vector<i2d::AABB> boxes;
    std::vector<i2d::Vec2> moves;
};

TreeCase makeTreeCase(int n) {
    TreeCase c;
    Random rng;
    const float side = 2.0f * std::sqrt(static_cast<float>(n));
    for (int i = 0; i < n; ++i) {
        float x = rng.range(0.0f, side), y = rng.range(0.0f, side);
        float hx = rng.range(0.2f, 0.6f), hy = rng.range(0.2f, 0.6f);
        c.boxes.push_back({{x - hx - 0.1f, y - hy - 0.1f}, {x + hx + 0.1f, y + hy + 0.1f}});
    }
    // Steps of 0.2–0.5 m on each axis: always out of both engines' fat boxes
    // (margin 0.1 m), so every move re-inserts the leaf in both trees.
    auto step = [&] { return (rng.next() < 0.5f ? -1.0f : 1.0f) * rng.range(0.2f, 0.5f); };
    for (int i = 0; i < 4096; ++i) c.moves.push_back({step(), step()});
    return c;
}

i2d::AABB shifted(const i2d::AABB& b, i2d::Vec2 d) { return {b.lower + d, b.upper + d}; }

void I2dTreeMoveQuery(benchmark::State& state) {
    const int n = static_cast<int>(state.range(0));
    TreeCase c = makeTreeCase(n);
    i2d::detail::DynamicTree tree;
    std::vector<int> proxies;
    for (int i = 0; i < n; ++i) proxies.push_back(tree.createProxy(c.boxes[static_cast<std::size_t>(i)], i));
    std::size_t k = 0;
    long found = 0;
    for (auto _ : state) {
        std::size_t i = k % static_cast<std::size_t>(n);
        i2d::Vec2 d = c.moves[k % c.moves.size()];
        c.boxes[i] = shifted(c.boxes[i], d);
        tree.moveProxy(proxies[i], c.boxes[i]);
        tree.query(c.boxes[i], [&](int) {
            ++found;
            return true;
        });
        ++k;
    }
    benchmark::DoNotOptimize(found);
    state.counters["overlaps_per_query"] = static_cast<double>(found) /
                                           static_cast<double>(std::max<std::size_t>(k, 1));
}

struct B2QueryCounter {
    long found = 0;
    bool QueryCallback(int) {
        ++found;
        return true;
    }
};

void B2dTreeMoveQuery(benchmark::State& state) {
    const int n = static_cast<int>(state.range(0));
    TreeCase c = makeTreeCase(n);
    b2DynamicTree tree;
    auto toB2 = [](const i2d::AABB& b) {
        b2AABB a;
        a.lowerBound.Set(b.lower.x, b.lower.y);
        a.upperBound.Set(b.upper.x, b.upper.y);
        return a;
    };
    // Box2D fattens by b2_aabbExtension itself; give it the unfattened box.
    auto inner = [](i2d::AABB b) {
        return i2d::AABB{{b.lower.x + 0.1f, b.lower.y + 0.1f}, {b.upper.x - 0.1f, b.upper.y - 0.1f}};
    };
    std::vector<int> proxies;
    for (int i = 0; i < n; ++i)
        proxies.push_back(tree.CreateProxy(toB2(inner(c.boxes[static_cast<std::size_t>(i)])), nullptr));
    B2QueryCounter counter;
    std::size_t k = 0;
    for (auto _ : state) {
        std::size_t i = k % static_cast<std::size_t>(n);
        i2d::Vec2 d = c.moves[k % c.moves.size()];
        c.boxes[i] = shifted(c.boxes[i], d);
        // Displacement 0: 2.4.1 would otherwise stretch the fat box along it.
        tree.MoveProxy(proxies[i], toB2(inner(c.boxes[i])), b2Vec2(0.0f, 0.0f));
        tree.Query(&counter, tree.GetFatAABB(proxies[i]));
        ++k;
    }
    benchmark::DoNotOptimize(counter.found);
    state.counters["overlaps_per_query"] = static_cast<double>(counter.found) /
                                           static_cast<double>(std::max<std::size_t>(k, 1));
}

BENCHMARK(I2dTreeMoveQuery)->Name("i2d/tree_move_query")->Arg(1000)->Arg(10000);
BENCHMARK(B2dTreeMoveQuery)->Name("b2d/tree_move_query")->Arg(1000)->Arg(10000);

// ---------------------------------------------------------------------------
// Colliders: one manifold per call. Each pair is placed once (the same
// geometry for both engines where Box2D has the pair); B is slightly rotated
// so no axis ties. "overlap": 2 cm of penetration; "speculative": 5 mm apart
// (inside Impulse2D's speculative distance, 2 cm, and inside Box2D's
// polygon skin, 2 × 0.01 m); "side": two unrotated unit boxes side by side
// 1 mm apart, the pyramid's most common contact.

const i2d::Transform kIdentity{};
i2d::Transform placed(float x, float y, float angle) { return {{x, y}, i2d::makeRot(angle)}; }
b2Transform toB2(const i2d::Transform& t) {
    b2Transform x;
    x.p.Set(t.p.x, t.p.y);
    x.q.c = t.q.c;
    x.q.s = t.q.s;
    return x;
}

template <class F>
void runCollider(benchmark::State& state, F&& collide) {
    int points = 0;
    for (auto _ : state) {
        i2d::Manifold m = collide();
        benchmark::DoNotOptimize(m);
        points = m.pointCount;
    }
    state.counters["points"] = points;
}

template <class F>
void runB2Collider(benchmark::State& state, F&& collide) {
    b2Manifold m;
    for (auto _ : state) {
        collide(m);
        benchmark::DoNotOptimize(m);
    }
    state.counters["points"] = m.pointCount;
}

constexpr float kSpec = 0.02f;

void BM_I2dCircles(benchmark::State& s) {
    i2d::Circle a{{0, 0}, 0.5f}, b{{0, 0}, 0.5f};
    auto xb = placed(0.98f, 0.0f, 0.1f);
    runCollider(s, [&] { return i2d::collideCircles(a, kIdentity, b, xb, kSpec); });
}
void BM_B2dCircles(benchmark::State& s) {
    b2CircleShape a, b;
    a.m_radius = b.m_radius = 0.5f;
    auto xa = toB2(kIdentity), xb = toB2(placed(0.98f, 0.0f, 0.1f));
    runB2Collider(s, [&](b2Manifold& m) { b2CollideCircles(&m, &a, xa, &b, xb); });
}
void BM_I2dPolygonCircle(benchmark::State& s) {
    i2d::Polygon a = i2d::makeBox(0.5f, 0.5f);
    i2d::Circle b{{0, 0}, 0.5f};
    auto xb = placed(0.2f, 0.98f, 0.0f);
    runCollider(s, [&] { return i2d::collidePolygonAndCircle(a, kIdentity, b, xb, kSpec); });
}
void BM_B2dPolygonCircle(benchmark::State& s) {
    b2PolygonShape a;
    a.SetAsBox(0.5f, 0.5f);
    b2CircleShape b;
    b.m_radius = 0.5f;
    auto xa = toB2(kIdentity), xb = toB2(placed(0.2f, 0.98f, 0.0f));
    runB2Collider(s, [&](b2Manifold& m) { b2CollidePolygonAndCircle(&m, &a, xa, &b, xb); });
}

void polygonCase(int which, i2d::Transform& xb) {
    switch (which) {
        case 0: xb = placed(0.1f, 0.98f, 0.02f); break;   // overlap, box on box
        case 1: xb = placed(0.1f, 1.005f, 0.02f); break;  // speculative, box above box
        default: xb = placed(1.001f, 0.0f, 0.0f); break;  // side by side, unrotated
    }
}
void BM_I2dPolygons(benchmark::State& s) {
    i2d::Polygon a = i2d::makeBox(0.5f, 0.5f), b = i2d::makeBox(0.5f, 0.5f);
    i2d::Transform xb;
    polygonCase(static_cast<int>(s.range(0)), xb);
    runCollider(s, [&] { return i2d::collidePolygons(a, kIdentity, b, xb, kSpec); });
}
void BM_B2dPolygons(benchmark::State& s) {
    b2PolygonShape a, b;
    a.SetAsBox(0.5f, 0.5f);
    b.SetAsBox(0.5f, 0.5f);
    i2d::Transform xb;
    polygonCase(static_cast<int>(s.range(0)), xb);
    auto xa = toB2(kIdentity), x2 = toB2(xb);
    runB2Collider(s, [&](b2Manifold& m) { b2CollidePolygons(&m, &a, xa, &b, x2); });
}
void BM_I2dCapsuleCircle(benchmark::State& s) {
    i2d::Capsule a{{-0.5f, 0}, {0.5f, 0}, 0.25f};
    i2d::Circle b{{0, 0}, 0.5f};
    auto xb = placed(0.2f, 0.73f, 0.0f);
    runCollider(s, [&] { return i2d::collideCapsuleAndCircle(a, kIdentity, b, xb, kSpec); });
}
void BM_I2dCapsules(benchmark::State& s) {
    i2d::Capsule a{{-0.5f, 0}, {0.5f, 0}, 0.25f}, b{{-0.5f, 0}, {0.5f, 0}, 0.25f};
    auto xb = placed(0.3f, 0.48f, 0.05f);
    runCollider(s, [&] { return i2d::collideCapsules(a, kIdentity, b, xb, kSpec); });
}
void BM_I2dPolygonCapsule(benchmark::State& s) {
    i2d::Polygon a = i2d::makeBox(0.5f, 0.5f);
    i2d::Capsule b{{-0.5f, 0}, {0.5f, 0}, 0.25f};
    auto xb = placed(0.1f, 0.73f, 0.05f);
    runCollider(s, [&] { return i2d::collidePolygonAndCapsule(a, kIdentity, b, xb, kSpec); });
}
void BM_I2dSegmentCircle(benchmark::State& s) {
    i2d::Segment a{{-2, 0}, {2, 0}};
    i2d::Circle b{{0, 0}, 0.5f};
    auto xb = placed(0.3f, 0.48f, 0.0f);
    runCollider(s, [&] { return i2d::collideSegmentAndCircle(a, kIdentity, b, xb, kSpec); });
}
void BM_B2dEdgeCircle(benchmark::State& s) {
    b2EdgeShape a;
    a.SetTwoSided(b2Vec2(-2, 0), b2Vec2(2, 0));
    b2CircleShape b;
    b.m_radius = 0.5f;
    auto xa = toB2(kIdentity), xb = toB2(placed(0.3f, 0.48f, 0.0f));
    runB2Collider(s, [&](b2Manifold& m) { b2CollideEdgeAndCircle(&m, &a, xa, &b, xb); });
}
void BM_I2dSegmentCapsule(benchmark::State& s) {
    i2d::Segment a{{-2, 0}, {2, 0}};
    i2d::Capsule b{{-0.5f, 0}, {0.5f, 0}, 0.25f};
    auto xb = placed(0.3f, 0.23f, 0.02f);
    runCollider(s, [&] { return i2d::collideSegmentAndCapsule(a, kIdentity, b, xb, kSpec); });
}
void BM_I2dSegmentPolygon(benchmark::State& s) {
    i2d::Segment a{{-2, 0}, {2, 0}};
    i2d::Polygon b = i2d::makeBox(0.5f, 0.5f);
    auto xb = placed(0.3f, 0.48f, 0.02f);
    runCollider(s, [&] { return i2d::collideSegmentAndPolygon(a, kIdentity, b, xb, kSpec); });
}
void BM_B2dEdgePolygon(benchmark::State& s) {
    b2EdgeShape a;
    a.SetTwoSided(b2Vec2(-2, 0), b2Vec2(2, 0));
    b2PolygonShape b;
    b.SetAsBox(0.5f, 0.5f);
    auto xa = toB2(kIdentity), xb = toB2(placed(0.3f, 0.48f, 0.02f));
    runB2Collider(s, [&](b2Manifold& m) { b2CollideEdgeAndPolygon(&m, &a, xa, &b, xb); });
}

BENCHMARK(BM_I2dCircles)->Name("i2d/circle_circle");
BENCHMARK(BM_B2dCircles)->Name("b2d/circle_circle");
BENCHMARK(BM_I2dPolygonCircle)->Name("i2d/polygon_circle");
BENCHMARK(BM_B2dPolygonCircle)->Name("b2d/polygon_circle");
BENCHMARK(BM_I2dPolygons)->Name("i2d/polygon_polygon")->ArgName("overlap0_spec1_side2")->DenseRange(0, 2);
BENCHMARK(BM_B2dPolygons)->Name("b2d/polygon_polygon")->ArgName("overlap0_spec1_side2")->DenseRange(0, 2);
BENCHMARK(BM_I2dCapsuleCircle)->Name("i2d/capsule_circle");
BENCHMARK(BM_I2dCapsules)->Name("i2d/capsule_capsule");
BENCHMARK(BM_I2dPolygonCapsule)->Name("i2d/polygon_capsule");
BENCHMARK(BM_I2dSegmentCircle)->Name("i2d/segment_circle");
BENCHMARK(BM_B2dEdgeCircle)->Name("b2d/edge_circle");
BENCHMARK(BM_I2dSegmentCapsule)->Name("i2d/segment_capsule");
BENCHMARK(BM_I2dSegmentPolygon)->Name("i2d/segment_polygon");
BENCHMARK(BM_B2dEdgePolygon)->Name("b2d/edge_polygon");

// ---------------------------------------------------------------------------
// Solver: time per contact per velocity iteration, from whole steps. Two
// copies of a settled pyramid (base 20: 210 boxes, 630 contacts) are stepped
// side by side, one with `lo` and one with `hi` velocity iterations; the
// difference of their step times divided by (hi − lo) × contacts is the cost
// of one more sweep over one contact (normal and friction rows of both
// points), everything else in the step cancelling out. Impulse2D runs in the
// baumgarte mode (one step, N velocity iterations: the same contact row as
// the soft step's solve and relax passes); Box2D 2.4.1 with its velocity
// iterations (its 2-point block solver). Reported time = per contact-iteration.

constexpr int kSolverBase = 20;
constexpr int kLoIterations = 4, kHiIterations = 20;

i2d::World makeI2dPyramid(int iterations) {
    i2d::WorldSettings s;
    s.enableSleep = false;
    s.positionCorrection = i2d::PositionCorrection::baumgarte;
    s.velocityIterations = iterations;
    i2d::World world(s);
    bench::buildPyramid(world, kSolverBase, 40.0f);
    for (int i = 0; i < 60; ++i) world.step(1.0f / 60.0f);
    return world;
}

std::unique_ptr<b2World> makeB2dPyramid() {
    auto world = std::make_unique<b2World>(b2Vec2(0.0f, -10.0f));
    world->SetAllowSleeping(false);
    bench::buildPyramid(*world, kSolverBase, 40.0f);
    for (int i = 0; i < 60; ++i) world->Step(1.0f / 60.0f, 8, 3);
    return world;
}

double seconds(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }

void I2dContactIteration(benchmark::State& state) {
    i2d::World lo = makeI2dPyramid(kLoIterations), hi = makeI2dPyramid(kHiIterations);
    const double contacts = static_cast<double>(lo.contacts().size());
    for (auto _ : state) {
        auto t0 = Clock::now();
        lo.step(1.0f / 60.0f);
        auto t1 = Clock::now();
        hi.step(1.0f / 60.0f);
        auto t2 = Clock::now();
        double extra = seconds(t1, t2) - seconds(t0, t1);
        state.SetIterationTime(std::max(extra, 0.0) / ((kHiIterations - kLoIterations) * contacts));
    }
    state.counters["contacts"] = contacts;
}

void B2dContactIteration(benchmark::State& state) {
    auto lo = makeB2dPyramid(), hi = makeB2dPyramid();
    const double contacts = static_cast<double>(lo->GetContactCount());
    for (auto _ : state) {
        auto t0 = Clock::now();
        lo->Step(1.0f / 60.0f, kLoIterations, 3);
        auto t1 = Clock::now();
        hi->Step(1.0f / 60.0f, kHiIterations, 3);
        auto t2 = Clock::now();
        double extra = seconds(t1, t2) - seconds(t0, t1);
        state.SetIterationTime(std::max(extra, 0.0) / ((kHiIterations - kLoIterations) * contacts));
    }
    state.counters["contacts"] = contacts;
}

BENCHMARK(I2dContactIteration)->Name("i2d/contact_iteration")->UseManualTime()->Iterations(400);
BENCHMARK(B2dContactIteration)->Name("b2d/contact_iteration")->UseManualTime()->Iterations(400);

// ---------------------------------------------------------------------------
// Impacts. "closed_form": one call of i2d::resolveImpact (Baber (2011), "A Correction To Brian
// Mirtich's Thesis 'Impulse-based Dynamic Simulation of Rigid Body Systems'", §5) for a
// rotating box corner striking the ground at 2.8 m/s with friction (the
// counter `case` is the ImpactCase the law took). "velocity_bias": what the sequential-impulse
// restitution model spends on the same impact, written out here with the
// solver's own formulas (solver.cpp) because its rows are internal: prepare
// one 1-point contact (anchors, normal and tangent effective masses, approach
// speed), then the soft step's work on it — 4 substeps of {integrate
// gravity, warm start, solve (soft push), relax}, each pass the normal row
// then the friction row — then the restitution pass (target −e·v_n). This is
// the cost of that contact in one step with the velocity-bias model; its
// share due to restitution alone is the last pass (one normal row).

i2d::ImpactInput impactCase() {
    i2d::ImpactInput in;
    in.restitution = 0.5;
    in.friction = 0.3;
    in.normal = {0.0, 1.0};
    in.a = {1.0, 6.0, {0.4, -0.5}, {1.0, -4.0}, 3.0};
    in.b = {0.0, 0.0, {0.0, 0.0}, {0.0, 0.0}, 0.0};
    return in;
}

void I2dClosedFormImpact(benchmark::State& state) {
    i2d::ImpactInput in = impactCase();
    int kind = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(in);
        i2d::ImpactResult r = i2d::resolveImpact(in);
        benchmark::DoNotOptimize(r);
        kind = static_cast<int>(r.kind);
    }
    state.counters["case"] = kind;
}

struct BiasBody {
    i2d::Vec2 v;
    float w;
    float invMass, invI;
};

void I2dVelocityBiasImpact(benchmark::State& state) {
    const i2d::ImpactInput in = impactCase();
    const float e = 0.5f, mu = 0.3f, dt = 1.0f / 60.0f, h = dt / 4.0f;
    // The solver's soft contact coefficients against a static body: 60 Hz, ζ = 10.
    const float omega = 2.0f * 3.14159265f * 60.0f, zeta = 10.0f;
    const float a1 = 2.0f * zeta + h * omega, a2 = h * omega * a1, a3 = 1.0f / (1.0f + a2);
    const float biasRate = omega / a1, massScale = a2 * a3, impulseScale = a3;
    float check = 0.0f;
    for (auto _ : state) {
        // Our manifold normal points from the ground (A) to the box (B).
        BiasBody b{
            {static_cast<float>(in.a.v.x), static_cast<float>(in.a.v.y)}, static_cast<float>(in.a.w), 1.0f, 6.0f};
        benchmark::DoNotOptimize(b);
        const i2d::Vec2 n{0.0f, 1.0f}, t = i2d::rightPerp(n);
        const i2d::Vec2 r{static_cast<float>(in.a.r.x), static_cast<float>(in.a.r.y)};
        float separation = -0.001f;
        // Prepare.
        const float rn = i2d::cross(r, n), rt = i2d::cross(r, t);
        const float normalMass = 1.0f / (b.invMass + b.invI * rn * rn);
        const float tangentMass = 1.0f / (b.invMass + b.invI * rt * rt);
        const float approach = i2d::dot(b.v + i2d::cross(b.w, r), n);
        float ni = 0.0f, ti = 0.0f, maxNi = 0.0f;
        auto rows = [&](bool useBias) {
            float vn = i2d::dot(b.v + i2d::cross(b.w, r), n);
            float bias = 0.0f, ms = 1.0f, is = 0.0f;
            if (separation > 0.0f) {
                bias = separation / h;
            } else if (useBias) {
                bias = std::max(biasRate * separation, -3.0f);
                ms = massScale;
                is = impulseScale;
            }
            float impulse = -normalMass * ms * (vn + bias) - is * ni;
            float next = std::max(ni + impulse, 0.0f);
            impulse = next - ni;
            ni = next;
            maxNi = std::max(maxNi, impulse);
            b.v = i2d::mulAdd(b.v, b.invMass * impulse, n);
            b.w += b.invI * i2d::cross(r, impulse * n);
            float vt = i2d::dot(b.v + i2d::cross(b.w, r), t);
            float f = -tangentMass * vt;
            float nextT = i2d::clamp(ti + f, -mu * ni, mu * ni);
            f = nextT - ti;
            ti = nextT;
            b.v = i2d::mulAdd(b.v, b.invMass * f, t);
            b.w += b.invI * i2d::cross(r, f * t);
        };
        for (int sub = 0; sub < 4; ++sub) {
            b.v.y -= 10.0f * h;
            i2d::Vec2 P = ni * n + ti * t;  // warm start
            b.v = i2d::mulAdd(b.v, b.invMass, P);
            b.w += b.invI * i2d::cross(r, P);
            rows(true);
            separation += h * i2d::dot(b.v + i2d::cross(b.w, r), n);
            rows(false);
        }
        // Restitution pass.
        if (approach < -1.0f && maxNi > 0.0f) {
            float vn = i2d::dot(b.v + i2d::cross(b.w, r), n);
            float impulse = -normalMass * (vn + e * approach);
            float next = std::max(ni + impulse, 0.0f);
            impulse = next - ni;
            ni = next;
            b.v = i2d::mulAdd(b.v, b.invMass * impulse, n);
            b.w += b.invI * i2d::cross(r, impulse * n);
        }
        benchmark::DoNotOptimize(b);
        check = b.v.y;
    }
    state.counters["vy_after"] = check;
}

BENCHMARK(I2dClosedFormImpact)->Name("i2d/impact_closed_form");
BENCHMARK(I2dVelocityBiasImpact)->Name("i2d/impact_velocity_bias_soft_step");

}  // namespace

BENCHMARK_MAIN();
