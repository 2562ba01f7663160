// png_frames.cpp — a frame sequence as numbered PNG files, encoded and written by a pool of
// workers, one per core, while the next frames are drawn.
//
// Encoding a 1920x1080 frame takes about twice as long as llvmpipe takes to draw an empty sky,
// and a GPU draws it in milliseconds: one thread that drew, read back and encoded in turn left
// the other cores idle. The queue holds at most one frame per worker, so memory stays bounded
// (two frames per core in all) and a slow disk slows the drawing rather than filling memory.
#include "frame_output.h"

#include <algorithm>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <sys/stat.h>
#include <thread>

namespace mb {

namespace {

class PngFrames : public FrameOutput {
public:
    PngFrames(const FramePattern& pattern, bool skipExisting)
        : pattern_(pattern), skipExisting_(skipExisting) {
        const int workers = int(std::max(1u, std::thread::hardware_concurrency()));
        for (int i = 0; i < workers; ++i) workers_.emplace_back([this] { work(); });
    }
    ~PngFrames() override { stop(false); }

    bool wanted(int frame) const override {
        struct stat st;
        return !skipExisting_ || ::stat(pattern_.name(frame).c_str(), &st) != 0;
    }
    // Hands the frame to a worker; false with the first failed frame's error, once one has.
    bool write(int frame, const Image& img, std::string* error) override {
        std::unique_lock<std::mutex> lock(mutex_);
        room_.wait(lock, [&] { return queue_.size() < workers_.size() || !error_.empty(); });
        if (!error_.empty()) return *error = error_, false;
        queue_.push_back({frame, img});
        ready_.notify_one();
        return true;
    }
    bool finish(std::string* error) override {
        stop(false);
        if (!error_.empty()) *error = error_;
        return error_.empty();
    }
    // Frames not yet begun are dropped; each one begun is finished, so every file is whole.
    void abandon() override { stop(true); }

private:
    struct Job {
        int frame;
        Image image;
    };

    // savePng writes a temporary file and renames it, and finishes even when Ctrl-C comes
    // meanwhile (catchInterrupts only notes it): a frame's file is whole or absent.
    void work() {
        for (;;) {
            Job job;
            {
                std::unique_lock<std::mutex> lock(mutex_);
                ready_.wait(lock, [&] { return !queue_.empty() || closing_; });
                if (queue_.empty()) return;
                job = std::move(queue_.front());
                queue_.pop_front();
                room_.notify_one();
            }
            std::string error;
            if (savePng(pattern_.name(job.frame), job.image, &error)) continue;
            std::lock_guard<std::mutex> lock(mutex_);
            if (error_.empty()) error_ = error;
            room_.notify_all();
        }
    }
    void stop(bool dropQueued) {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            if (dropQueued) queue_.clear();
            closing_ = true;
        }
        ready_.notify_all();
        for (std::thread& t : workers_) t.join();
        workers_.clear();
    }

    FramePattern pattern_;
    bool skipExisting_;
    std::mutex mutex_;
    std::condition_variable ready_, room_;  // a frame to encode; room in the queue
    std::deque<Job> queue_;
    std::string error_;  // the first frame that failed
    bool closing_ = false;
    std::vector<std::thread> workers_;
};

}  // namespace

std::unique_ptr<FrameOutput> pngFrames(const FramePattern& pattern, int firstFrame,
                                       bool skipExisting, std::string* error) {
    if (!checkSavePng(pattern.name(firstFrame), error)) return nullptr;
    return std::make_unique<PngFrames>(pattern, skipExisting);
}

}  // namespace mb
