// video_frames.cpp — a frame sequence as an MP4 video: raw RGB frames piped to ffmpeg, which
// encodes H.264. No PNG is written on the way.
#include "frame_output.h"

#include "interrupt.h"

#include "marchbox/scene/atomic_file.h"
#include "marchbox/scene/printable.h"

#include <cerrno>
#include <charconv>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

extern char** environ;

namespace mb {

namespace {

// The first executable file called `name` in the folders of PATH, or "".
std::string findOnPath(const std::string& name) {
    const char* path = std::getenv("PATH");
    std::string folders = path ? path : "";
    for (size_t at = 0; at <= folders.size();) {
        size_t end = std::min(folders.find(':', at), folders.size());
        std::string folder = end > at ? folders.substr(at, end - at) : ".";
        std::string file = folder + "/" + name;
        struct stat st;
        if (::stat(file.c_str(), &st) == 0 && S_ISREG(st.st_mode) &&
            ::access(file.c_str(), X_OK) == 0)
            return file;
        at = end + 1;
    }
    return "";
}

// The last line of what ffmpeg wrote to its standard error: its reason for failing.
std::string lastLine(std::FILE* log) {
    std::string text, line;
    std::rewind(log);
    for (int c; (c = std::fgetc(log)) != EOF;) text += char(c);
    for (size_t end = text.size(); end > 0;) {
        size_t start = text.rfind('\n', end - 1);
        start = start == std::string::npos ? 0 : start + 1;
        line = text.substr(start, end - start);
        if (!line.empty() && line.find_first_not_of(" \r") != std::string::npos) break;
        end = start > 0 ? start - 1 : 0;
        line.clear();
    }
    return printable(line);
}

std::string shortest(double v) {
    char buf[32];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, end);
}

// Raw RGB frames on standard input, H.264 in MP4 out.
std::vector<std::string> ffmpegArgs(int width, int height, double fps, const std::string& out) {
    return {"ffmpeg", "-hide_banner", "-loglevel", "error", "-y",        // errors only, on stderr
            "-f", "rawvideo", "-pix_fmt", "rgb24",                       // what write() sends
            "-s", std::to_string(width) + "x" + std::to_string(height),  //
            "-framerate", shortest(fps), "-i", "-",                      //
            // yuv420p is what players expect of H.264; crf 18 looks lossless to the eye
            "-c:v", "libx264", "-pix_fmt", "yuv420p", "-crf", "18",  //
            // the index first, for players that stream
            "-movflags", "+faststart",  //
            // the temporary's name does not end in .mp4; "file:" keeps a name with a colon or
            // a leading '-' a file name
            "-f", "mp4", "file:" + out};
}

class VideoFrames : public FrameOutput {
public:
    VideoFrames(std::string path, int width, int height)
        : path_(std::move(path)),
          temp_(path_ + ".tmp" + std::to_string(::getpid())),
          width_(width),
          height_(height) {}
    ~VideoFrames() override { abandon(); }

    bool start(const std::string& ffmpeg, double fps, std::string* error);
    bool wanted(int) const override { return true; }
    bool write(int frame, const Image& img, std::string* error) override;
    bool finish(std::string* error) override;
    void abandon() override;

private:
    bool failed(int status, std::string* error);  // from ffmpeg's wait status and its words
    int wait();  // closes the pipe, waits for ffmpeg; its wait status (0: it succeeded)

    std::string path_, temp_;
    int width_, height_;
    pid_t pid_ = -1;
    int pipe_ = -1;             // ffmpeg's standard input
    std::FILE* log_ = nullptr;  // ffmpeg's standard error
};

bool VideoFrames::start(const std::string& ffmpeg, double fps, std::string* error) {
    int fds[2];
    log_ = std::tmpfile();
    if (!log_ || ::pipe2(fds, O_CLOEXEC) != 0)
        return *error = std::string("cannot start ffmpeg: ") + std::strerror(errno), false;
    pipe_ = fds[1];
    // A write to an ffmpeg that has failed then returns EPIPE, and its reason is read, instead
    // of the signal ending this process without a word.
    std::signal(SIGPIPE, SIG_IGN);
    std::vector<std::string> args = ffmpegArgs(width_, height_, fps, temp_);
    std::vector<char*> argv;
    for (std::string& s : args) argv.push_back(s.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t io;
    posix_spawn_file_actions_init(&io);
    posix_spawn_file_actions_adddup2(&io, fds[0], STDIN_FILENO);
    posix_spawn_file_actions_addopen(&io, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_adddup2(&io, fileno(log_), STDERR_FILENO);
    int err = posix_spawn(&pid_, ffmpeg.c_str(), &io, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&io);
    ::close(fds[0]);
    if (err == 0) return true;
    pid_ = -1;
    *error = "cannot start " + printable(ffmpeg) + ": " + std::strerror(err);
    return false;
}

// Rows go top first, as the image holds them and as rawvideo reads them.
bool VideoFrames::write(int, const Image& img, std::string* error) {
    std::vector<uint8_t> rgb(size_t(img.width) * img.height * 3);
    for (size_t i = 0, n = size_t(img.width) * img.height; i < n; ++i)
        std::memcpy(&rgb[i * 3], &img.rgba[i * 4], 3);
    for (size_t done = 0; done < rgb.size();) {
        ssize_t n = ::write(pipe_, rgb.data() + done, rgb.size() - done);
        if (n > 0) done += size_t(n);
        else if (n < 0 && errno == EINTR) {
            if (interrupted()) return false;  // the caller abandons the video
        } else return failed(wait(), error);
    }
    return true;
}

int VideoFrames::wait() {
    if (pipe_ >= 0) ::close(pipe_), pipe_ = -1;  // end of input: ffmpeg finishes the file
    int status = 0;
    while (pid_ > 0 && ::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
    pid_ = -1;
    return status;
}

bool VideoFrames::failed(int status, std::string* error) {
    std::string why = lastLine(log_);
    *error = "ffmpeg could not write '" + printable(path_) + "' (" +
             (WIFSIGNALED(status) ? "killed by signal " + std::to_string(WTERMSIG(status))
                                  : "exit status " + std::to_string(WEXITSTATUS(status))) +
             ")" + (why.empty() ? "" : ": " + why);
    ::unlink(temp_.c_str());
    return false;
}

bool VideoFrames::finish(std::string* error) {
    if (int status = wait(); status != 0) return failed(status, error);
    if (::rename(temp_.c_str(), path_.c_str()) == 0) return true;
    *error = "cannot write '" + printable(path_) + "': " + std::strerror(errno);
    ::unlink(temp_.c_str());
    return false;
}

void VideoFrames::abandon() {
    if (pid_ > 0) {
        ::kill(pid_, SIGTERM);
        wait();
        ::unlink(temp_.c_str());
    }
    if (log_) std::fclose(log_), log_ = nullptr;
}

}  // namespace

std::unique_ptr<FrameOutput> videoFrames(const std::string& path, int width, int height, double fps,
                                         std::string* error) {
    const std::string ffmpeg = findOnPath("ffmpeg");
    if (ffmpeg.empty()) {
        *error =
            "video needs the ffmpeg program, which is not on PATH: install it "
            "(apt-get install ffmpeg)";
        return nullptr;
    }
    if (std::string why = checkReplaceFile(path); !why.empty()) {
        *error = "cannot write '" + printable(path) + "': " + why;
        return nullptr;
    }
    auto video = std::make_unique<VideoFrames>(path, width, height);
    if (!video->start(ffmpeg, fps, error)) return nullptr;
    return video;
}

}  // namespace mb
