// png_frames.cpp — a frame sequence as numbered PNG files, encoded by a pool of workers, one per
// core, while the next frames are drawn, and written in frame order.
//
// Encoding a 1920x1080 frame takes about twice as long as llvmpipe takes to draw an empty sky,
// and a GPU draws it in milliseconds: one thread that drew, read back and encoded in turn left
// the other cores idle. At most two frames per worker are in hand (waiting, being encoded, or
// encoded and waiting for their turn), so memory stays bounded and a slow disk slows the
// drawing rather than filling memory. Files are written in frame order, so a run that fails or
// stops leaves the frames before that point and none after, as a run on one thread did.
#include "frame_output.h"

#include <algorithm>
#include <condition_variable>
#include <deque>
#include <map>
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
        room_.wait(lock, [&] { return order_.size() < 2 * workers_.size() || !error_.empty(); });
        if (!error_.empty()) return *error = error_, false;
        queue_.push_back({frame, img});
        order_.push_back(frame);
        ready_.notify_one();
        return true;
    }
    bool finish(std::string* error) override {
        stop(false);
        if (!error_.empty()) *error = error_;
        return error_.empty();
    }
    // Frames not yet written are dropped; the one being written is finished, so every file is
    // whole.
    void abandon() override { stop(true); }

private:
    struct Job {
        int frame;
        Image image;
    };

    void work() {
        std::unique_lock<std::mutex> lock(mutex_);
        for (;;) {
            ready_.wait(lock, [&] { return !queue_.empty() || closing_; });
            if (queue_.empty()) return;
            Job job = std::move(queue_.front());
            queue_.pop_front();
            lock.unlock();
            std::string png = encodePng(job.image);
            lock.lock();
            encoded_[job.frame] = std::move(png);
            writeInOrder(lock);
        }
    }
    // Writes the encoded frames whose turn has come, one worker at a time. savePngBytes writes
    // a temporary file and renames it, and finishes even when Ctrl-C comes meanwhile
    // (catchInterrupts only notes it): a frame's file is whole or absent.
    void writeInOrder(std::unique_lock<std::mutex>& lock) {
        if (writing_) return;  // the writer takes this frame too when its turn comes
        writing_ = true;
        while (!order_.empty() && encoded_.count(order_.front()) && error_.empty() && !dropping_) {
            const int frame = order_.front();
            const std::string png = std::move(encoded_[frame]);
            encoded_.erase(frame);
            lock.unlock();
            std::string error;
            const bool ok = savePngBytes(pattern_.name(frame), png, &error);
            lock.lock();
            order_.pop_front();
            if (!ok) error_ = error;
            room_.notify_all();
        }
        writing_ = false;
    }
    void stop(bool dropUnwritten) {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            if (dropUnwritten) queue_.clear();
            dropping_ = dropUnwritten;
            closing_ = true;
        }
        ready_.notify_all();
        for (std::thread& t : workers_) t.join();
        workers_.clear();
    }

    FramePattern pattern_;
    bool skipExisting_;
    std::mutex mutex_;
    std::condition_variable ready_, room_;  // a frame to encode; room for another
    std::deque<Job> queue_;                 // handed in, not yet being encoded
    std::deque<int> order_;                 // handed in, not yet written, in frame order
    std::map<int, std::string> encoded_;    // encoded, waiting for their turn
    bool writing_ = false;                  // a worker is writing frames in order
    bool dropping_ = false;                 // abandoned: nothing more is written
    std::string error_;                     // the first frame that failed
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
