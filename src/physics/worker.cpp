// worker.cpp — the helper thread: spin, then sleep, until the next job.
#include "worker.h"

#include <cassert>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace mb {

namespace {

void relax() {
#if defined(__x86_64__) || defined(__i386__)
    _mm_pause();  // lets the sibling hyperthread run while this one spins
#endif
}

// Returns once `value` differs from `old`: some tens of microseconds of spinning, then a sleep.
void awaitChange(const std::atomic<unsigned>& value, unsigned old) {
    for (int i = 0; i < 2000; ++i) {
        if (value.load(std::memory_order_acquire) != old) return;
        relax();
    }
    while (value.load(std::memory_order_acquire) == old) value.wait(old, std::memory_order_acquire);
}

}  // namespace

Worker::Worker() : thread_([this] { loop(); }) {}

Worker::~Worker() {
    quit_ = true;
    post(nullptr, nullptr);
    thread_.join();
}

void Worker::post(void (*fn)(void*), void* arg) {
    // One job at a time: a second post before wait() would change fn_ under the running job.
    assert(done_.load(std::memory_order_acquire) == posted_.load(std::memory_order_relaxed));
    fn_ = fn;
    arg_ = arg;
    posted_.fetch_add(1, std::memory_order_release);  // publishes fn_, arg_ and quit_
    posted_.notify_one();
}

void Worker::wait() {
    const unsigned target = posted_.load(std::memory_order_relaxed);
    for (unsigned done; (done = done_.load(std::memory_order_acquire)) != target;)
        awaitChange(done_, done);
}

void Worker::loop() {
    for (unsigned seen = 0;;) {
        awaitChange(posted_, seen);
        seen = posted_.load(std::memory_order_acquire);
        if (quit_) return;
        fn_(arg_);
        done_.store(seen, std::memory_order_release);
        done_.notify_one();
    }
}

}  // namespace mb
