// Stages shared among workers (see stage_runner.hpp). Memory order: on each
// share's line in turn the caller writes the stage's description (in the slot
// of its epoch's parity) and the share's cursor, then publishes the epoch
// there (release); the helper that reads that epoch on its line (acquire)
// sees its description and the cursors of that line and the lines before it
// (a cursor not yet set for the stage holds an older epoch, so a helper that
// reads it claims nothing there, and that share's own worker and the caller
// do its items). A worker claims
// a chunk only by compare-and-swap on a share's cursor with the epoch it read
// the description under, so a description overwritten by a later stage is
// never acted on. Each worker adds the items it finished to its own done_
// count once it finds no chunk left (nothing when it ran none); the caller
// starts the next stage only when the counts add up to the stage's, so no
// late addition reaches the next stage's counts, which it sets to zero
// before it publishes that stage.
#include "stage_runner.hpp"

#include <algorithm>
#include <thread>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace i2d::detail {

namespace {

/// Waits a little: pause instructions while the wait is short, then gives
/// the core away, so that a helper does not starve the thread it waits for
/// when the machine has fewer free cores than workers. Short is 20,000
/// pauses, about a millisecond where a pause takes 140 cycles: the waits
/// between the stages of a step are shorter than that (its serial parts take
/// tenths of a millisecond). After 2,000 pauses (tens of microseconds) a
/// helper yielded within a step, and beside two low-priority busy processes
/// the process that took its core kept it for a time slice: pyramid100 on two
/// workers took 4.5 to 4.8 ms per step against 2.7 to 2.8 ms with 20,000
/// (beside one busy process of equal priority both took 10 ms: a helper that
/// loses its core holds up its stage's end either way).
void relax(int& spins) {
    if (++spins < 20000) {
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
    shares_ = std::min(tasks->workerCount(), kMaxShares);
    exit_.store(false, std::memory_order_relaxed);
    caller_ = std::this_thread::get_id();
    // Helpers take part in every stage published after this one.
    begunAt_.store(epoch_, std::memory_order_release);
    for (int i = 0; i < shares_; ++i) shareLines_[i].published.store(epoch_, std::memory_order_release);
    // Helper i (of workerCount − 1, one item each) is worker i + 1.
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

int StageRunner::shareBegin(int share, int count, int grain) const {
    const int chunks = (count + grain - 1) / grain;
    const long long first = static_cast<long long>(chunks) * share / shares_;
    return static_cast<int>(std::min<long long>(first * grain, count));
}

int StageRunner::workShare(int share, std::uint32_t epoch, StageFn fn, void* context, int count, int grain) {
    std::atomic<std::uint64_t>& claim = shareLines_[share].claim;
    const int last = shareBegin(share + 1, count, grain);
    int ran = 0;
    std::uint64_t c = claim.load(std::memory_order_acquire);
    while (static_cast<std::uint32_t>(c >> 32) == epoch) {
        const int next = static_cast<int>(c & 0xFFFFFFFFu);
        if (next >= last) break;
        if (!claim.compare_exchange_weak(c, c + static_cast<std::uint64_t>(grain), std::memory_order_acq_rel,
                                         std::memory_order_acquire))
            continue;  // c now holds the current value
        const int end = std::min(next + grain, last);
        fn(context, next, end);
        ran += end - next;
        c = claim.load(std::memory_order_acquire);
    }
    return ran;
}

void StageRunner::work(int self, std::uint32_t epoch, StageFn fn, void* context, int count, int grain) {
    int ran = 0;
    for (int i = 0; i < shares_; ++i) ran += workShare((self + i) % shares_, epoch, fn, context, count, grain);
    // Released: whoever reads the count sees what these items wrote.
    if (ran > 0) done_[self].items.fetch_add(ran, std::memory_order_release);
}

int StageRunner::doneItems() const {
    int done = 0;
    for (int i = 0; i < shares_; ++i) done += done_[i].items.load(std::memory_order_acquire);
    return done;
}

void StageRunner::run(StageFn fn, void* context, int count, int grain) {
    if (count <= 0) return;
    // One chunk's work is not worth a hand-over: the caller does it alone.
    if (!handleActive_ || !share_ || count <= grain) {
        fn(context, 0, count);
        return;
    }
    ++epoch_;
    for (int i = 0; i < shares_; ++i) done_[i].items.store(0, std::memory_order_relaxed);
    for (int i = 0; i < shares_; ++i) {
        Share& line = shareLines_[i];
        Stage& stage = line.stages[epoch_ & 1u];
        stage.fn.store(fn, std::memory_order_relaxed);
        stage.context.store(context, std::memory_order_relaxed);
        stage.count.store(count, std::memory_order_relaxed);
        stage.grain.store(grain, std::memory_order_relaxed);
        line.claim.store(std::uint64_t{epoch_} << 32 | static_cast<std::uint32_t>(shareBegin(i, count, grain)),
                         std::memory_order_release);
        line.published.store(epoch_, std::memory_order_release);
    }
    work(0, epoch_, fn, context, count, grain);
    int spins = 0;
    while (doneItems() < count) relax(spins);
}

void StageRunner::helper(int begin, int, int, void* context) {
    StageRunner& r = *static_cast<StageRunner*>(context);
    // A task system that runs a range on the caller's thread, inside
    // enqueue, breaks its contract (tasks.hpp): this helper would wait there
    // for stages the caller can never publish, and the step hung. It returns
    // at once instead, and the caller does every stage's work itself (the
    // work of each stage is claimed by whoever comes, so nothing waits for
    // the missing helper).
    if (std::this_thread::get_id() == r.caller_) return;
    const int self = (begin + 1) % r.shares_;
    // The epoch at begin(), not the one published when this helper starts: a
    // helper that started while a stage ran took that stage for one it had
    // seen and waited for the next. On a machine slow to wake an idle core
    // the helper of a step started during its narrowphase, so the stepping
    // thread collided alone while the helper spun beside it (many_pyramids on
    // two workers: the narrowphase took 1.6 to 3.3 ms against 1.6 on one).
    std::uint32_t seen = r.begunAt_.load(std::memory_order_acquire);
    const Share& mine = r.shareLines_[self];
    int spins = 0;
    while (!r.exit_.load(std::memory_order_acquire)) {
        const std::uint32_t epoch = mine.published.load(std::memory_order_acquire);
        if (epoch == seen) {
            relax(spins);
            continue;
        }
        spins = 0;
        seen = epoch;
        // Stage epoch's description stays in its slot until stage epoch + 2 is
        // written, which needs epoch + 1 finished: by then every cursor holds
        // a later epoch and workShare claims nothing under a stale description.
        const Stage& stage = mine.stages[epoch & 1u];
        r.work(self, epoch, stage.fn.load(std::memory_order_relaxed), stage.context.load(std::memory_order_relaxed),
               stage.count.load(std::memory_order_relaxed), stage.grain.load(std::memory_order_relaxed));
    }
}

}  // namespace i2d::detail
