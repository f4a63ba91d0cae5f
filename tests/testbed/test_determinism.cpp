// Determinism pinned across builds and refactors: several shipped scenes are
// stepped a fixed number of times and the final state of every body
// (position, angle, linear and angular velocity, as IEEE-754 bit patterns) is
// hashed with 64-bit FNV-1a. The expected hashes below are the values this
// engine produced when they were pinned.
//
// Two runs agreeing within one process (the older determinism test) cannot
// see a change of behaviour; a pinned hash can. A refactor must leave these
// values as they are. A deliberate change of behaviour updates the hash in
// the same commit and says why in the commit message.
//
// The hashes assume IEEE-754 single precision without fused multiply-add
// contraction (x86-64's default code generation with GCC or clang, any
// optimisation level); a build for another target may legitimately differ,
// and then only the in-process repeat below is meaningful.
#include <gtest/gtest.h>

#include <bit>
#include <cinttypes>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "scene_build.hpp"
#include "scene_loader.hpp"
#include "thread_pool.hpp"

namespace {

const std::string kAssets = TB_TEST_ASSETS_DIR;

struct Fnv1a {
    std::uint64_t h = 14695981039346656037ull;
    void add(std::uint32_t word) {
        for (int i = 0; i < 4; ++i) {
            h ^= (word >> (8 * i)) & 0xffu;
            h *= 1099511628211ull;
        }
    }
    void add(float f) { add(std::bit_cast<std::uint32_t>(f)); }
};

enum class Variant { as_shipped, baumgarte, split, velocity_bias, no_sleep };

/// `threads` workers (a tb::ThreadPool) when above 1.
std::uint64_t runAndHash(const std::string& name, int steps, Variant variant, int threads = 1) {
    tb::SceneDesc desc = tb::loadSceneDesc(name, kAssets);
    switch (variant) {
        case Variant::as_shipped: break;
        case Variant::baumgarte: desc.settings.positionCorrection = i2d::PositionCorrection::baumgarte; break;
        case Variant::split: desc.settings.positionCorrection = i2d::PositionCorrection::split; break;
        case Variant::velocity_bias: desc.settings.impactModel = i2d::ImpactModel::velocity_bias; break;
        case Variant::no_sleep: desc.settings.enableSleep = false; break;
    }
    tb::Scene scene = tb::buildScene(desc);
    std::unique_ptr<tb::ThreadPool> pool;
    if (threads > 1) {
        pool = std::make_unique<tb::ThreadPool>(threads);
        scene.world->setTaskSystem(pool.get());
    }
    for (int i = 0; i < steps; ++i) scene.world->step(desc.dt);
    scene.world->setTaskSystem(nullptr);
    Fnv1a hash;
    for (i2d::BodyId id : scene.bodies) {
        i2d::Vec2 p = scene.world->position(id);
        i2d::Vec2 v = scene.world->linearVelocity(id);
        hash.add(p.x);
        hash.add(p.y);
        hash.add(scene.world->angle(id));
        hash.add(v.x);
        hash.add(v.y);
        hash.add(scene.world->angularVelocity(id));
    }
    return hash.h;
}

struct PinnedRun {
    const char* label;  ///< test name
    const char* scene;
    Variant variant;
    int steps;
    std::uint64_t hash;
};

void PrintTo(const PinnedRun& run, std::ostream* os) { *os << run.label; }

// Step counts: long enough that contacts, joints, impacts, sleeping and the
// broadphase have all acted (pyramid20 settles, the bridge sags and swings,
// the balls bounce several times, rain1000's circles pile up, the cradle's
// balls exchange momentum through several impacts).
// The three position-correction modes and both impact models are covered,
// and one scene runs with sleeping off.
constexpr PinnedRun kPinned[] = {
    {"pyramid20", "pyramid20", Variant::as_shipped, 300, 0xfedeb124980c6a62ull},
    {"pyramid20_baumgarte", "pyramid20", Variant::baumgarte, 300, 0x6df129552f6fd544ull},
    {"pyramid20_split", "pyramid20", Variant::split, 300, 0x9bdc1700acafffe6ull},
    {"bridge", "bridge", Variant::as_shipped, 300, 0x17540913828f67d7ull},
    {"bridge_split", "bridge", Variant::split, 300, 0xe6c10add824d52c1ull},
    {"bounce", "bounce", Variant::as_shipped, 600, 0x2ebb730093f8a726ull},
    {"bounce_velocity_bias", "bounce", Variant::velocity_bias, 600, 0x0f4dcdf9ae63f08dull},
    {"rain1000", "rain1000", Variant::as_shipped, 400, 0x3caaa2cf29955c52ull},
    {"newtons_cradle", "newtons_cradle", Variant::as_shipped, 600, 0x95c574ab02e2a723ull},
    {"heavy_chain", "heavy_chain", Variant::as_shipped, 300, 0x4d63d20aabfcf0d8ull},
    {"tall_stack20_no_sleep", "tall_stack20", Variant::no_sleep, 600, 0x0c8b9031db3d0b75ull},
    {"bullets", "bullets", Variant::as_shipped, 120, 0x3b064b9a0215d174ull},
};

class PinnedDeterminism : public ::testing::TestWithParam<PinnedRun> {};

TEST_P(PinnedDeterminism, FinalStateHashIsPinned) {
    const PinnedRun& run = GetParam();
    std::uint64_t h = runAndHash(run.scene, run.steps, run.variant);
    char hex[32];
    std::snprintf(hex, sizeof hex, "0x%016" PRIx64, h);
    EXPECT_EQ(h, run.hash) << run.label << " after " << run.steps << " steps hashes to " << hex;
    // The same calls in the same process give the same bits.
    EXPECT_EQ(runAndHash(run.scene, run.steps, run.variant), h) << run.label;
}

// The same pinned bits on two and three workers: the work a step shares
// (integration body by body, contact blocks colour by colour) is independent
// item by item, so who does which cannot change a bit.
TEST_P(PinnedDeterminism, SameHashOnMoreWorkers) {
    const PinnedRun& run = GetParam();
    for (int threads : {2, 3})
        EXPECT_EQ(runAndHash(run.scene, run.steps, run.variant, threads), run.hash)
            << run.label << " on " << threads << " workers";
}

// A scene far above the size from which a step shares its work, over enough
// steps for every stage to have run many times on several workers.
TEST(ThreadedDeterminism, LargeScenesAreBitIdenticalOnAnyNumberOfWorkers) {
    for (const char* scene : {"pyramid100"}) {
        const std::uint64_t one = runAndHash(scene, 120, Variant::no_sleep);
        for (int threads : {2, 4})
            EXPECT_EQ(runAndHash(scene, 120, Variant::no_sleep, threads), one) << scene << " on " << threads;
    }
}

/// A 60×60 grid of discs hinged to their neighbours (3,600 bodies, 7,080
/// hinges: large enough to be shared among the workers), hanging from two
/// corners, stepped `steps` times on `threads` workers; the hash of the state.
/// `tasks`, when given, is the task system instead of a pool of `threads`.
std::uint64_t jointGridHash(int threads, int steps, i2d::TaskSystem* tasks = nullptr) {
    i2d::World world({.enableSleep = false});
    std::unique_ptr<tb::ThreadPool> pool;
    if (tasks) {
        world.setTaskSystem(tasks);
    } else if (threads > 1) {
        pool = std::make_unique<tb::ThreadPool>(threads);
        world.setTaskSystem(pool.get());
    }
    const int n = 60;
    const i2d::BodyId ceiling = world.createBody({});
    std::vector<i2d::BodyId> bodies;
    for (int row = 0; row < n; ++row)
        for (int column = 0; column < n; ++column) {
            const i2d::BodyId b = world.createBody(
                {.type = i2d::BodyType::dynamic_body,
                 .position = {static_cast<float>(column) - 0.5f * n, static_cast<float>(row)}});
            world.createCircleShape(b, {.filter = {.groupIndex = -1}}, {{0.0f, 0.0f}, 0.4f});
            bodies.push_back(b);
        }
    auto at = [&](int row, int column) { return bodies[static_cast<std::size_t>(row * n + column)]; };
    for (int row = 0; row < n; ++row)
        for (int column = 0; column < n; ++column) {
            if (column + 1 < n)
                world.createRevoluteJoint({.bodyA = at(row, column),
                                           .bodyB = at(row, column + 1),
                                           .localAnchorA = {0.5f, 0.0f},
                                           .localAnchorB = {-0.5f, 0.0f}});
            if (row + 1 < n)
                world.createRevoluteJoint({.bodyA = at(row, column),
                                           .bodyB = at(row + 1, column),
                                           .localAnchorA = {0.0f, 0.5f},
                                           .localAnchorB = {0.0f, -0.5f}});
        }
    for (int column : {0, n - 1}) {
        const i2d::Vec2 top = world.position(at(n - 1, column)) + i2d::Vec2{0.0f, 0.5f};
        world.createRevoluteJoint(
            {.bodyA = ceiling, .bodyB = at(n - 1, column), .localAnchorA = top, .localAnchorB = {0.0f, 0.5f}});
    }
    for (int i = 0; i < steps; ++i) world.step(1.0f / 60.0f);
    world.setTaskSystem(nullptr);
    Fnv1a hash;
    for (i2d::BodyId id : bodies) {
        hash.add(world.position(id).x);
        hash.add(world.position(id).y);
        hash.add(world.angle(id));
        hash.add(world.linearVelocity(id).x);
        hash.add(world.linearVelocity(id).y);
        hash.add(world.angularVelocity(id));
    }
    return hash.h;
}

TEST(ThreadedDeterminism, LargeJointGridIsBitIdenticalOnAnyNumberOfWorkers) {
    const std::uint64_t one = jointGridHash(1, 60);
    for (int threads : {2, 4}) EXPECT_EQ(jointGridHash(threads, 60), one) << threads << " workers";
}

/// A task system that claims two workers but runs every range inside
/// enqueue, on the caller's thread (against tasks.hpp's contract, and a
/// common fallback of game task systems).
class InlineTasks final : public i2d::TaskSystem {
public:
    int workerCount() const override { return 2; }
    void* enqueue(i2d::TaskFunction task, int count, int, void* context) override {
        task(0, count, 1, context);
        return nullptr;
    }
    void finish(void*) override {}
};

// Such a task system made the step wait forever for a helper that was
// running on its own thread; the step now does all the work itself, with the
// same result.
TEST(ThreadedDeterminism, ATaskSystemThatRunsTasksInlineNeitherHangsNorChangesTheResult) {
    InlineTasks inlineTasks;
    EXPECT_EQ(jointGridHash(1, 20, &inlineTasks), jointGridHash(1, 20));
}

INSTANTIATE_TEST_SUITE_P(Shipped, PinnedDeterminism, ::testing::ValuesIn(kPinned),
                         [](const ::testing::TestParamInfo<PinnedRun>& info) { return std::string(info.param.label); });

}  // namespace
