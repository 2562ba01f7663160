// png_frames.cpp — a frame sequence as numbered PNG files.
#include "frame_output.h"

#include <sys/stat.h>

namespace mb {

namespace {

class PngFrames : public FrameOutput {
public:
    PngFrames(const FramePattern& pattern, bool skipExisting)
        : pattern_(pattern), skipExisting_(skipExisting) {}

    bool wanted(int frame) const override {
        struct stat st;
        return !skipExisting_ || ::stat(pattern_.name(frame).c_str(), &st) != 0;
    }
    // savePng writes a temporary file and renames it, and finishes even when Ctrl-C comes
    // meanwhile (catchInterrupts only notes it): a frame's file is whole or absent.
    bool write(int frame, const Image& img, std::string* error) override {
        return savePng(pattern_.name(frame), img, error);
    }
    bool finish(std::string*) override { return true; }
    void abandon() override {}  // every file written is whole

private:
    FramePattern pattern_;
    bool skipExisting_;
};

}  // namespace

std::unique_ptr<FrameOutput> pngFrames(const FramePattern& pattern, int firstFrame,
                                       bool skipExisting, std::string* error) {
    if (!checkSavePng(pattern.name(firstFrame), error)) return nullptr;
    return std::make_unique<PngFrames>(pattern, skipExisting);
}

}  // namespace mb
