// frame_output.cpp — choosing a frame sequence's output from its path.
#include "frame_output.h"

#include <cctype>
#include <filesystem>

namespace mb {

bool hasExtension(const std::string& path, const std::string& lowercase) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& ch : ext) ch = char(std::tolower(static_cast<unsigned char>(ch)));
    return ext == lowercase;
}

// .MP4 is as common a spelling as .mp4, and no frame pattern either way.
bool isVideo(const std::string& path) { return hasExtension(path, ".mp4"); }

std::string framesError(const Args& a, FramePattern* pattern) {
    const double fps = a.fps.value_or(30);
    std::string error;
    if (!a.frameRange) error = kFramesNotRange;  // bench's count N, typed into the editor
    else if (a.seconds) error = "--seconds does not go with --frames: frame k shows t = k / fps";
    else if (a.frameRange->last / fps > kMaxSeconds)
        error = "frame " + std::to_string(a.frameRange->last) + " is past 3600 s at this --fps";
    else if (isVideo(a.output) && a.skipExisting)
        error = "--skip-existing takes a PATTERN of files, not a video";
    else if (isVideo(a.output) && (a.width % 2 || a.height % 2))
        error = "an H.264 video needs an even width and height (--size)";
    else if (!isVideo(a.output) && !hasExtension(a.output, ".png"))
        error = "frames are PNG files: PATTERN must end in .png (or write OUT.mp4)";
    else if (!isVideo(a.output)) parseFramePattern(a.output, pattern, &error);
    return error;
}

std::unique_ptr<FrameOutput> openFrames(const std::string& path, const FramePattern& pattern,
                                        int first, int width, int height, double fps,
                                        bool skipExisting, std::string* error) {
    return isVideo(path) ? videoFrames(path, width, height, fps, error)
                         : pngFrames(pattern, first, skipExisting, error);
}

}  // namespace mb
