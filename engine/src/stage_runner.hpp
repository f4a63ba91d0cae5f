// The parallel stages of a step (stage_runner.cpp). The thread that steps the
// world publishes a stage — a function over items [0, count) — takes part in
// it and waits until every item is done; helpers, enqueued once per solve on
// the game's task system (impulse2d/tasks.hpp), claim chunks of whatever stage
// is current. Items of a stage must be independent (the contact blocks of one
// colour, the bodies of an integration), so who runs which chunk changes
// nothing: a step is bit-identical on any number of workers. The caller never
// waits for a helper to start, so a helper that starts late only helps less.
//
// Each worker first claims chunks of its own share of a stage, the same part
// of [0, count) in every stage, and only then helps with the others' shares
// (as Box2D v3's solver stages do). Items are in slot order, which follows the
// bodies' order, so a worker meets mostly the same bodies in one colour after
// another and in the integration: their states stay in its core's cache.
// Claimed in turn from one counter, consecutive chunks went to alternating
// workers and every colour moved half the bodies' cache lines from one core
// to the other (pyramid100's sweeps ran 1.2 times faster on two workers).
#pragma once

#include <atomic>
#include <cstdint>
#include <thread>

#include "impulse2d/tasks.hpp"

namespace i2d::detail {

/// Items (contact rows, joints and awake bodies for the solve; contacts for
/// the narrowphase) from which a step shares a stage with the task system's
/// workers: below, a colour's sweep takes a few microseconds and handing it
/// out costs more than it saves (joint_grid, 2,600 items, and rain1000,
/// 3,000, ran slower on two workers than on one); pyramid100 (20,000) gained
/// a fifth. Columns of boxes (an awake body and a contact row each, sleeping
/// off; one and two workers interleaved, in four runs) ran 0.87 and 0.91
/// times as fast on two workers with 3,000 boxes (6,000 items, shared from
/// 4,096 before) and 0.89 and 0.96 with 4,000, 0.90 to 1.23 with 5,000, 0.98
/// to 1.26 with 7,000 and 1.13 to 1.31 with 10,000, as the machine's speed
/// changed from run to run, on a machine where a cache line takes about 200
/// ns to move between two cores (docs/performance.md).
inline constexpr int kParallelWork = 8192;

class StageRunner {
public:
    using StageFn = void (*)(void* context, int begin, int end);

    /// Enqueues tasks->workerCount() − 1 helpers when there is more than one
    /// worker; with none (or one worker) every stage runs on the caller.
    void begin(TaskSystem* tasks);
    /// Releases the helpers and waits for them (TaskSystem::finish).
    void end();
    bool parallel() const { return handleActive_; }
    /// Whether run() hands the next stages to the helpers (when begun with
    /// them) or runs them on the caller: a stage too small to gain from
    /// helpers that are already waiting.
    void share(bool on) { share_ = on; }
    /// Whether run() hands stages to helpers now.
    bool sharing() const { return handleActive_ && share_; }

    /// Runs fn over [0, count) in chunks of `grain` items; returns when all are done.
    void run(StageFn fn, void* context, int count, int grain);
    template <class F>
    void run(int count, int grain, F& f) {
        run([](void* c, int b, int e) { (*static_cast<F*>(c))(b, e); }, &f, count, grain);
    }

private:
    static void helper(int begin, int end, int worker, void* context);
    /// Claims and runs chunks of the stage of `epoch` until none is left:
    /// worker `self`'s share first, then the others' in turn; then adds
    /// the items it ran to its own count (done_).
    void work(int self, std::uint32_t epoch, StageFn fn, void* context, int count, int grain);
    /// Claims and runs chunks of share `share` of the stage of `epoch`;
    /// returns how many items it ran.
    int workShare(int share, std::uint32_t epoch, StageFn fn, void* context, int count, int grain);
    /// The items of the current stage the workers have reported done.
    int doneItems() const;
    /// The first item of share `share` of a stage of `count` items (a
    /// multiple of `grain`, so that chunks never cross shares).
    int shareBegin(int share, int count, int grain) const;

    static constexpr int kMaxShares = 16;  ///< workers beyond these share shares
    /// A stage's description.
    struct Stage {
        std::atomic<StageFn> fn{nullptr};
        std::atomic<void*> context{nullptr};
        std::atomic<int> count{0}, grain{1};
    };
    /// Per share, on one cache line: the current stage's epoch (high 32
    /// bits) and the share's next unclaimed item; the epoch published to the
    /// share's worker; and the stage's description, by epoch parity (the
    /// caller writes stage E + 1's while a late helper may still read stage
    /// E's). A helper waiting for a stage reads its own line, and one move
    /// of that line from the caller's core brings it everything the stage
    /// asks of it: published in lines of their own (the epoch, the
    /// description and the cursor), a stage cost three moves, about 200 ns
    /// each on a machine measured here.
    struct alignas(64) Share {
        std::atomic<std::uint64_t> claim{0};
        std::atomic<std::uint32_t> published{0};
        Stage stages[2];
    };
    static_assert(sizeof(Share) == 64, "a share is one cache line");
    Share shareLines_[kMaxShares];
    int shares_ = 1;
    /// The epoch when the helpers were enqueued: every stage after it is
    /// theirs to help with, however late they start.
    alignas(64) std::atomic<std::uint32_t> begunAt_{0};
    /// Per worker (by share, as the cursors): the items of the current
    /// stage it has finished, added once when it finds no chunk left, each
    /// on a cache line of its own. One counter that every worker added each
    /// chunk to went back and forth between the cores with every chunk
    /// (about 200 ns a move on a machine measured here), as did the
    /// caller's reads of it while it waited (stages of 470 items in chunks
    /// of 32, 2.1 microseconds on one worker: 3.51 on two, 3.25 with a count
    /// per worker, 2.92 with the shares' lines joined too; medians of ten
    /// runs).
    struct alignas(64) Done {
        std::atomic<int> items{0};
    };
    Done done_[kMaxShares];
    alignas(64) std::atomic<bool> exit_{false};
    std::uint32_t epoch_ = 0;
    TaskSystem* tasks_ = nullptr;
    void* handle_ = nullptr;
    bool handleActive_ = false;
    std::thread::id caller_;  ///< the thread that began the step
    bool share_ = true;
};

}  // namespace i2d::detail
