// frame_output.h — where render --frames puts its frames: numbered PNG files (frame_pattern.h)
// or an H.264 video made by the ffmpeg program. Either way a stopped or failed run leaves only
// whole files: each PNG is written beside its name and renamed; the video is encoded to a
// temporary file that is renamed when ffmpeg has finished it, and removed otherwise.
#pragma once

#include "args.h"
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

// The frame output render --frames and File > Render Animation... share (frame_output.cpp).
// Whether path's extension, in any case, is `lowercase` (".png").
bool hasExtension(const std::string& path, const std::string& lowercase);
bool isVideo(const std::string& path);  // .mp4 in any case; anything else is a PATTERN
// What the options alone show wrong with render --frames, in one line (a bad PATTERN, an odd
// size for H.264, a frame past 3600 s); "" when nothing, with *pattern parsed where -o is not
// a video.
std::string framesError(const Args& a, FramePattern* pattern);
// The video or the PATTERN's files for frames from `first` on; null with *error.
std::unique_ptr<FrameOutput> openFrames(const std::string& path, const FramePattern& pattern,
                                        int first, int width, int height, double fps,
                                        bool skipExisting, std::string* error);

}  // namespace mb
