// worker.h — one helper thread that runs a job beside the caller.
//
// The caller posts a job, does its own share of the work and waits for the job. A solver pass
// lasts a fraction of a millisecond, of which a sleeping thread's wake-up alone would take a good
// part, so both sides spin a while before they sleep (std::atomic wait).
#pragma once

#include <atomic>
#include <thread>

namespace mb {

class Worker {
public:
    Worker();
    ~Worker();
    Worker(const Worker&) = delete;
    Worker& operator=(const Worker&) = delete;

    template <class Job>
    void post(Job& job) {
        post(&call<Job>, &job);
    }             // runs job() on the worker; job must outlive wait()
    void wait();  // until the posted job has returned

private:
    template <class Job>
    static void call(void* job) {
        (*static_cast<Job*>(job))();
    }
    void post(void (*fn)(void*), void* arg);
    void loop();

    std::atomic<unsigned> posted_{0}, done_{0};  // jobs posted, jobs finished
    void (*fn_)(void*) = nullptr;
    void* arg_ = nullptr;
    bool quit_ = false;
    std::thread thread_;
};

}  // namespace mb
