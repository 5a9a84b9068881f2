#include "core/split_worker.h"

#include <utility>

namespace swell::detail {

SplitWorker::SplitWorker() : thread_([this] { loop(); }) {}

SplitWorker::~SplitWorker()
{
    {
        const std::lock_guard lock(mutex_);
        quit_ = true;
    }
    changed_.notify_all();
    thread_.join();
}

void SplitWorker::run(const std::function<void()>& theirs, const std::function<void()>& mine)
{
    {
        const std::lock_guard lock(mutex_);
        task_ = &theirs;
        busy_ = true;
    }
    changed_.notify_all();
    std::exception_ptr mineError;
    try {
        mine();
    } catch (...) {
        mineError = std::current_exception();
    }
    // `theirs` lives on the caller's stack: wait for the worker whatever happened here.
    std::exception_ptr theirError;
    {
        std::unique_lock lock(mutex_);
        changed_.wait(lock, [&] { return !busy_; });
        theirError = std::exchange(error_, nullptr);
    }
    if (mineError)
        std::rethrow_exception(mineError);
    if (theirError)
        std::rethrow_exception(theirError);
}

void SplitWorker::loop()
{
    std::unique_lock lock(mutex_);
    for (;;) {
        changed_.wait(lock, [&] { return quit_ || busy_; });
        if (!busy_)
            return; // quit_, with nothing in hand
        const std::function<void()>& task = *task_;
        lock.unlock();
        std::exception_ptr error;
        try {
            task();
        } catch (...) {
            error = std::current_exception();
        }
        lock.lock();
        error_ = error;
        task_ = nullptr;
        busy_ = false;
        changed_.notify_all();
    }
}

} // namespace swell::detail
