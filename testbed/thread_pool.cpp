// Testbed — the thread pool (see thread_pool.hpp). A job's ranges are claimed
// under one mutex: the world enqueues a handful of long-running ranges per
// step (its stage helpers), not fine-grained work, so a lock costs nothing
// that matters and keeps the pool obviously correct.
#include "thread_pool.hpp"

#include <algorithm>

namespace tb {

ThreadPool::ThreadPool(int workers) {
    for (int i = 1; i < std::max(workers, 1); ++i) threads_.emplace_back([this, i] { loop(i); });
}

ThreadPool::~ThreadPool() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stop_ = true;
    }
    work_.notify_all();
    for (std::thread& t : threads_) t.join();
}

void* ThreadPool::enqueue(i2d::TaskFunction task, int count, int minRange, void* context) {
    if (count <= 0) return nullptr;
    Job* job = new Job{task, context, count, std::max(minRange, 1)};
    {
        std::lock_guard<std::mutex> lock(mutex_);
        queue_.push_back(job);
    }
    work_.notify_all();
    return job;
}

void ThreadPool::finish(void* handle) {
    if (handle == nullptr) return;
    Job* job = static_cast<Job*>(handle);
    {
        std::unique_lock<std::mutex> lock(mutex_);
        done_.wait(lock, [&] { return job->finished == job->count; });
    }
    delete job;
}

void ThreadPool::loop(int worker) {
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
        work_.wait(lock, [&] { return stop_ || !queue_.empty(); });
        if (stop_) return;
        Job* job = queue_.front();
        const int begin = job->next;
        const int end = std::min(begin + job->range, job->count);
        job->next = end;
        if (job->next == job->count) queue_.pop_front();
        lock.unlock();
        job->task(begin, end, worker, job->context);
        lock.lock();
        job->finished += end - begin;
        if (job->finished == job->count) done_.notify_all();
    }
}

}  // namespace tb
