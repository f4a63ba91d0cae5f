// Stages shared among workers (see stage_runner.hpp). Memory order: the
// caller writes a stage's description (in the slot of its epoch's parity),
// then publishes its epoch in claim_ (release); a helper that reads that epoch
// (acquire) sees the description. A helper claims a chunk only by
// compare-and-swap on claim_ with the epoch it read the description under, so
// a description overwritten by a later stage is never acted on. done_ counts finished items; the caller starts the next
// stage only when it reaches the count, so no late addition reaches it.
#include "stage_runner.hpp"

#include <algorithm>
#include <thread>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace i2d::detail {

namespace {

/// Waits a little: a pause instruction while the wait is short, then gives
/// the core away (on a shared machine a spinning helper must not starve the
/// thread it waits for).
void relax(int& spins) {
    if (++spins < 2000) {
#if defined(__SSE2__)
        _mm_pause();
#endif
    } else {
        std::this_thread::yield();
    }
}

}  // namespace

void StageRunner::begin(TaskSystem* tasks) {
    tasks_ = tasks;
    handleActive_ = false;
    share_ = true;
    if (tasks == nullptr || tasks->workerCount() < 2) return;
    exit_.store(false, std::memory_order_relaxed);
    // Helpers start by waiting for an epoch after the current one.
    claim_.store(std::uint64_t{epoch_} << 32, std::memory_order_release);
    handle_ = tasks->enqueue(&StageRunner::helper, tasks->workerCount() - 1, 1, this);
    handleActive_ = true;
}

void StageRunner::end() {
    if (!handleActive_) return;
    exit_.store(true, std::memory_order_release);
    tasks_->finish(handle_);
    handleActive_ = false;
    handle_ = nullptr;
}

void StageRunner::work(std::uint32_t epoch, StageFn fn, void* context, int count, int grain) {
    std::uint64_t c = claim_.load(std::memory_order_acquire);
    while (static_cast<std::uint32_t>(c >> 32) == epoch) {
        const int next = static_cast<int>(c & 0xFFFFFFFFu);
        if (next >= count) return;
        if (!claim_.compare_exchange_weak(c, c + static_cast<std::uint64_t>(grain), std::memory_order_acq_rel,
                                          std::memory_order_acquire))
            continue;  // c now holds the current value
        const int end = std::min(next + grain, count);
        fn(context, next, end);
        done_.fetch_add(end - next, std::memory_order_release);
        c = claim_.load(std::memory_order_acquire);
    }
}

void StageRunner::run(StageFn fn, void* context, int count, int grain) {
    if (count <= 0) return;
    // One chunk's work is not worth a hand-over: the caller does it alone.
    if (!handleActive_ || !share_ || count <= grain) {
        fn(context, 0, count);
        return;
    }
    ++epoch_;
    Stage& stage = stages_[epoch_ & 1u];
    stage.fn.store(fn, std::memory_order_relaxed);
    stage.context.store(context, std::memory_order_relaxed);
    stage.count.store(count, std::memory_order_relaxed);
    stage.grain.store(grain, std::memory_order_relaxed);
    done_.store(0, std::memory_order_relaxed);
    claim_.store(std::uint64_t{epoch_} << 32, std::memory_order_release);
    work(epoch_, fn, context, count, grain);
    int spins = 0;
    while (done_.load(std::memory_order_acquire) < count) relax(spins);
}

void StageRunner::helper(int, int, int, void* context) {
    StageRunner& r = *static_cast<StageRunner*>(context);
    std::uint32_t seen = static_cast<std::uint32_t>(r.claim_.load(std::memory_order_acquire) >> 32);
    int spins = 0;
    while (!r.exit_.load(std::memory_order_acquire)) {
        const std::uint32_t epoch = static_cast<std::uint32_t>(r.claim_.load(std::memory_order_acquire) >> 32);
        if (epoch == seen) {
            relax(spins);
            continue;
        }
        spins = 0;
        seen = epoch;
        // Stage epoch's description stays in its slot until stage epoch + 2 is
        // written, which needs epoch + 1 finished: by then work() finds the
        // epoch moved on and claims nothing under a stale description.
        const Stage& stage = r.stages_[epoch & 1u];
        r.work(epoch, stage.fn.load(std::memory_order_relaxed), stage.context.load(std::memory_order_relaxed),
               stage.count.load(std::memory_order_relaxed), stage.grain.load(std::memory_order_relaxed));
    }
}

}  // namespace i2d::detail
