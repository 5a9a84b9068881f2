#include "core/worker.h"

#include "core/thread_cpu.h"

#include <utility>

namespace swell::detail {

Worker::Worker() : thread_([this] { loop(); }) {}

Worker::~Worker()
{
    {
        const std::lock_guard lock(mutex_);
        quit_ = true;
    }
    changed_.notify_all();
    thread_.join();
}

void Worker::start(std::function<void()> task)
{
    wait();
    {
        const std::lock_guard lock(mutex_);
        task_ = std::move(task);
        busy_ = true;
    }
    changed_.notify_all();
}

void Worker::wait()
{
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return !busy_; });
}

void Worker::rethrow()
{
    wait();
    const std::lock_guard lock(mutex_);
    if (std::exception_ptr e = std::exchange(error_, nullptr))
        std::rethrow_exception(e);
}

double Worker::cpu_ms()
{
    wait();
    const std::lock_guard lock(mutex_);
    return cpu_ms_;
}

void Worker::run(std::function<void()> theirs, const std::function<void()>& mine)
{
    start(std::move(theirs));
    try {
        mine();
    } catch (...) {
        // `theirs` may reach into the caller's stack: wait for it whatever
        // happened here; the calling thread's error goes first.
        wait();
        const std::lock_guard lock(mutex_);
        error_ = nullptr;
        throw;
    }
    rethrow();
}

void Worker::loop()
{
    std::unique_lock lock(mutex_);
    for (;;) {
        changed_.wait(lock, [&] { return quit_ || busy_; });
        if (!busy_)
            return; // quit_, with nothing in hand
        std::function<void()> task = std::move(task_);
        lock.unlock();
        const double before_ms = threadCpu_ms();
        std::exception_ptr error;
        try {
            task();
        } catch (...) {
            error = std::current_exception();
        }
        const double spent_ms = threadCpu_ms() - before_ms;
        lock.lock();
        cpu_ms_ += spent_ms;
        if (error)
            error_ = error;
        busy_ = false;
        changed_.notify_all();
    }
}

} // namespace swell::detail
