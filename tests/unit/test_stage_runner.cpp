// The stage runner (stage_runner.cpp): helpers enqueued on the game's task
// system take part in the stages of a step, whenever they start.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <memory>
#include <random>
#include <thread>
#include <vector>

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

/// `workers` workers, each helper on a thread of its own started at enqueue.
class ThreadTasks final : public TaskSystem {
public:
    explicit ThreadTasks(int workers) : workers_(workers) {}
    int workerCount() const override { return workers_; }
    void* enqueue(TaskFunction task, int count, int, void* context) override {
        for (int i = 0; i < count; ++i) threads_.emplace_back([task, i, context] { task(i, i + 1, i + 1, context); });
        return this;
    }
    void finish(void*) override {
        for (std::thread& t : threads_) t.join();
        threads_.clear();
    }

private:
    int workers_;
    std::vector<std::thread> threads_;
};

// Every item of every stage runs exactly once, whatever the stage's size and
// grain and however many workers share it: each share's cursor, epoch and
// description on one line, each worker's count of finished items on its own,
// and with more workers than shares (17 against 16) two helpers on one
// share's line and count. Random stages of 0 to 4,999 items in chunks of 1 to
// 100, up to 20 a step.
TEST(StageRunner, EveryItemOfEveryStageRunsOnceOnAnyNumberOfWorkers) {
    std::mt19937 rng(7);
    std::unique_ptr<std::atomic<int>[]> hits(new std::atomic<int>[5000]);
    for (const int workers : {2, 3, 17}) {
        ThreadTasks tasks(workers);
        detail::StageRunner runner;
        long wrong = 0, items = 0;
        const int steps = workers > 3 ? 10 : 100;
        for (int step = 0; step < steps; ++step) {
            runner.begin(&tasks);
            const int stages = 1 + static_cast<int>(rng() % 20);
            for (int s = 0; s < stages; ++s) {
                const int count = static_cast<int>(rng() % 5000), grain = 1 + static_cast<int>(rng() % 100);
                for (int i = 0; i < count; ++i) hits[i].store(0, std::memory_order_relaxed);
                auto run = [&](int b, int e) {
                    for (int i = b; i < e; ++i) hits[i].fetch_add(1, std::memory_order_relaxed);
                };
                runner.run(count, grain, run);
                for (int i = 0; i < count; ++i) wrong += hits[i].load(std::memory_order_relaxed) != 1;
                items += count;
            }
            runner.end();
        }
        EXPECT_EQ(wrong, 0) << workers << " workers, " << items << " items";
        EXPECT_GT(items, 0);
    }
}

}  // namespace
