// Testbed — a plain std::thread pool as the world's task system
// (impulse2d/tasks.hpp): `testbed run --threads N`, the tests and the
// benchmarks give it to a World to step it on N workers.
#pragma once

#include <atomic>
#include <condition_variable>
#include <deque>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include <impulse2d/tasks.hpp>

namespace tb {

class ThreadPool final : public i2d::TaskSystem {
public:
    /// `workers` ≥ 1 workers: the calling thread and workers − 1 threads.
    explicit ThreadPool(int workers);
    ~ThreadPool() override;
    ThreadPool(const ThreadPool&) = delete;
    ThreadPool& operator=(const ThreadPool&) = delete;

    int workerCount() const override { return static_cast<int>(threads_.size()) + 1; }
    /// Queues the task's ranges for the pool's threads (never the caller's).
    void* enqueue(i2d::TaskFunction task, int count, int minRange, void* context) override;
    void finish(void* handle) override;

private:
    struct Job {
        i2d::TaskFunction task;
        void* context;
        int count, range;
        int next = 0;      ///< first unclaimed item (under the pool's mutex)
        int finished = 0;  ///< items done (under the pool's mutex)
    };
    void loop(int worker);

    std::vector<std::thread> threads_;
    std::mutex mutex_;
    std::condition_variable work_, done_;
    std::deque<Job*> queue_;  ///< jobs with unclaimed ranges
    bool stop_ = false;
};

}  // namespace tb
