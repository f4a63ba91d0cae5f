// Impulse2D — the game's task system, as a World uses it (World::setTaskSystem).
//
// A world runs on the calling thread unless it is given a task system with
// more than one worker. It then hands the parallel parts of a step to it as
// range tasks, in the manner of Box2D v3's enqueue/finish callbacks: enqueue
// starts a task over items [0, count), finish waits for it. The results do
// not depend on the task system or its number of workers: a step with any
// number of workers is bit-identical to a step on one (the work a task splits
// is independent item by item, and everything else runs in a fixed order).
#pragma once

namespace i2d {

/// Work on items [begin, end) by worker `worker` (0 ≤ worker < workerCount()).
using TaskFunction = void (*)(int begin, int end, int worker, void* context);

class TaskSystem {
public:
    virtual ~TaskSystem() = default;
    /// Workers that may run tasks at the same time, the thread that calls
    /// World::step included (≥ 1). With 1 the world never enqueues.
    virtual int workerCount() const = 0;
    /// Starts `task` over items [0, count), split into ranges of at least
    /// `minRange` items (but the last), each run exactly once. With more than
    /// one worker, the ranges must run on threads other than the caller's,
    /// concurrently with it: the world keeps working while they run and may
    /// wait for them to take part. (A range run inside enqueue, on the
    /// caller's thread, returns at once and the world does its work alone:
    /// slower, never stuck.) Returns a handle for finish (may be null).
    virtual void* enqueue(TaskFunction task, int count, int minRange, void* context) = 0;
    /// Returns once every range of the task `handle` came from has run.
    virtual void finish(void* handle) = 0;
};

}  // namespace i2d
