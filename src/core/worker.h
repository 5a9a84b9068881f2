// One persistent thread that runs one task at a time beside the calling
// thread. The thread is made once and waits between tasks (none is created
// per frame). Two uses: a task started now and collected later (the
// floating bodies stepping ahead while the GPU draws), and a piece of work
// shared with the calling thread, run(theirs, mine) (the spectral twin's
// cascades, each thread taking the next not taken: parts each made the same
// way on either thread, into data of their own, give the same bits however
// the two threads run). Library-internal.
#pragma once

#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>

namespace swell::detail {

class Worker {
public:
    Worker();
    // After the task in hand, if any.
    ~Worker();
    Worker(const Worker&) = delete;
    Worker& operator=(const Worker&) = delete;

    // Hands `task` to the thread, once the task in hand is done.
    void start(std::function<void()> task);
    // Until the task in hand is done; an error it threw is kept for rethrow().
    void wait();
    // wait(), then rethrows (once) an error a task threw.
    void rethrow();
    // The thread's CPU time spent in tasks so far, ms (after wait()).
    double cpu_ms();

    // Runs `theirs` on the thread and `mine` here, both to their end; an
    // exception from either is rethrown here (the calling thread's first).
    void run(std::function<void()> theirs, const std::function<void()>& mine);

private:
    void loop();

    std::mutex mutex_;
    std::condition_variable changed_;
    std::function<void()> task_; // while busy_
    bool busy_ = false, quit_ = false;
    std::exception_ptr error_;
    double cpu_ms_ = 0.0;
    std::thread thread_; // last: it starts once the rest is there
};

} // namespace swell::detail
