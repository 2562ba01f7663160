// frame_output.h — where render --frames puts its frames: numbered PNG files (frame_pattern.h)
// or an H.264 video made by the ffmpeg program. Either way a stopped or failed run leaves only
// whole files: each PNG is written beside its name and renamed; the video is encoded to a
// temporary file that is renamed when ffmpeg has finished it, and removed otherwise.
#pragma once

#include "frame_pattern.h"

#include "marchbox/gl/image.h"

#include <memory>
#include <string>

namespace mb {

class FrameOutput {
public:
    virtual ~FrameOutput() = default;
    // Whether frame `frame` is to be rendered: --skip-existing skips the files already there.
    virtual bool wanted(int frame) const = 0;
    virtual bool write(int frame, const Image& img, std::string* error) = 0;
    virtual bool finish(std::string* error) = 0;  // after the last frame
    virtual void abandon() = 0;                   // stopped or failed: remove what is not whole
};

// PNG files named by `pattern`. *error where the first frame's file cannot be written.
std::unique_ptr<FrameOutput> pngFrames(const FramePattern& pattern, int firstFrame,
                                       bool skipExisting, std::string* error);

// The frames, width × height at `fps`, piped as raw RGB to ffmpeg, which writes `path` (MP4).
// *error where ffmpeg is not on PATH, or `path` cannot be written, or ffmpeg does not start.
std::unique_ptr<FrameOutput> videoFrames(const std::string& path, int width, int height, double fps,
                                         std::string* error);

}  // namespace mb
