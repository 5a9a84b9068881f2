// One persistent thread that shares a piece of work with the calling
// thread: run(theirs, mine) hands `theirs` to the worker, runs `mine` on
// the calling thread, and returns when both are done. The thread is made
// once and waits between calls (no thread is created per frame). Which
// thread does which part may follow the scheduling (the spectral twin's
// threads each take the next cascade not taken); parts that are each made
// the same way on either thread, into data of their own, give the same
// bits however the two threads run. Library-internal.
#pragma once

#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>

namespace swell::detail {

class SplitWorker {
public:
    SplitWorker();
    ~SplitWorker();
    SplitWorker(const SplitWorker&) = delete;
    SplitWorker& operator=(const SplitWorker&) = delete;

    // Runs `theirs` on the worker and `mine` here, both to their end; an
    // exception from either is rethrown here (the calling thread's first).
    void run(const std::function<void()>& theirs, const std::function<void()>& mine);

private:
    void loop();

    std::mutex mutex_;
    std::condition_variable changed_;
    const std::function<void()>* task_ = nullptr; // while busy_
    bool busy_ = false, quit_ = false;
    std::exception_ptr error_;
    std::thread thread_; // last: it starts once the rest is there
};

} // namespace swell::detail
