// The stage runner (stage_runner.cpp): helpers enqueued on the game's task
// system take part in the stages of a step, whenever they start.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>

#include "stage_runner.hpp"

namespace {

using namespace i2d;

/// Two workers; the helper's thread runs its range only once the test lets
/// it (a machine slow to wake an idle core starts it late).
class LateTasks final : public TaskSystem {
public:
    std::atomic<bool> release{false};
    int workerCount() const override { return 2; }
    void* enqueue(TaskFunction task, int count, int, void* context) override {
        thread_ = std::thread([this, task, count, context] {
            while (!release.load(std::memory_order_acquire)) std::this_thread::yield();
            for (int i = 0; i < count; ++i) task(i, i + 1, 0, context);
        });
        return this;
    }
    void finish(void*) override { thread_.join(); }

private:
    std::thread thread_;
};

struct TwoChunks {
    LateTasks* tasks = nullptr;
    std::thread::id caller;
    std::atomic<bool> secondStarted{false};
    std::thread::id secondRanOn;
};

// A helper that starts while the step's first stage runs takes part in it.
// The stage has two chunks, one per worker's share; the caller, in the first,
// lets the helper start and waits (up to 10 s) for the second to start on
// another thread. A helper that took the running stage for one it had seen
// waited for the next, and the caller ran the second chunk itself.
TEST(StageRunner, AHelperThatStartsLateTakesPartInTheRunningStage) {
    LateTasks tasks;
    TwoChunks state;
    state.tasks = &tasks;
    state.caller = std::this_thread::get_id();
    detail::StageRunner runner;
    runner.begin(&tasks);
    runner.run(
        [](void* context, int begin, int) {
            TwoChunks& s = *static_cast<TwoChunks*>(context);
            if (begin == 1) {
                s.secondRanOn = std::this_thread::get_id();
                s.secondStarted.store(true, std::memory_order_release);
                return;
            }
            s.tasks->release.store(true, std::memory_order_release);
            const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
            while (!s.secondStarted.load(std::memory_order_acquire) && std::chrono::steady_clock::now() < deadline)
                std::this_thread::yield();
        },
        &state, 2, 1);
    runner.end();
    EXPECT_NE(state.secondRanOn, state.caller);
}

}  // namespace
