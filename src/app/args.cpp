// args.cpp — strict parsing of the options in docs/cli.md.
#include "args.h"

#include "marchbox/scene/printable.h"

#include <charconv>
#include <climits>
#include <cmath>

namespace mb {

std::string quoteArg(const std::string& arg) {
    constexpr size_t kMax = 60;
    return "'" + printable(arg.substr(0, kMax)) + (arg.size() > kMax ? "...'" : "'");
}

static bool parseInt(const std::string& s, int lo, int hi, int* out) {
    int v = 0;
    auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || end != s.data() + s.size() || v < lo || v > hi) return false;
    *out = v;
    return true;
}

bool validImageSize(long width, long height) {
    return width >= 1 && height >= 1 && width <= kMaxImageSide && height <= kMaxImageSide &&
           width * height <= kMaxImagePixels;
}

static bool parseSize(const std::string& s, int* w, int* h) {
    size_t x = s.find('x');
    int width = 0, height = 0;
    if (x == std::string::npos || !parseInt(s.substr(0, x), INT_MIN, INT_MAX, &width) ||
        !parseInt(s.substr(x + 1), INT_MIN, INT_MAX, &height) || !validImageSize(width, height))
        return false;
    *w = width, *h = height;
    return true;
}

// from_chars, unlike strtod, takes no hex ("0x10") and no leading blanks; it does read "inf"
// and "nan", which the range check refuses.
static bool parseSeconds(const std::string& s, std::optional<double>* out) {
    double v = 0;
    auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || end != s.data() + s.size() || !std::isfinite(v) || v < 0 ||
        v > kMaxSeconds)
        return false;
    *out = v;
    return true;
}

// --fps: frames per second, more than 0 and at most kMaxFps (a fraction such as 23.976 too).
static bool parseFps(const std::string& s, std::optional<double>* out) {
    double v = 0;
    auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || end != s.data() + s.size() || !(v > 0 && v <= kMaxFps)) return false;
    *out = v;
    return true;
}

// --voxel: export's voxel edge in metres, a finite number more than 0.
static bool parseVoxel(const std::string& s, std::optional<double>* out) {
    double v = 0;
    auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || end != s.data() + s.size() || !std::isfinite(v) || !(v > 0))
        return false;
    *out = v;
    return true;
}

// --frames takes bench's count N or render's range A-B; the command refuses the other form.
// *why is set where the value is a range in the wrong order.
static bool parseFrames(const std::string& s, Args* a, std::string* why) {
    size_t dash = s.find('-');
    if (dash == std::string::npos || dash == 0) {
        int n = 0;
        return parseInt(s, 1, 100000, &n) ? (a->frameCount = n, true) : false;
    }
    FrameRange r;
    if (!parseInt(s.substr(0, dash), 0, kMaxFrame, &r.first) ||
        !parseInt(s.substr(dash + 1), 0, kMaxFrame, &r.last))
        return false;
    if (r.last < r.first) return *why = "the last frame comes before the first", false;
    a->frameRange = r;
    return true;
}

// Applies one option that takes a value; false with *error when the value is bad.
static bool applyValue(const std::string& opt, const std::string& v, Args* a, std::string* error) {
    bool ok = true;
    std::string why;  // what is wrong, where the expected form below does not say it
    if (opt == "-o") a->output = v, ok = !v.empty();
    else if (opt == "--size") ok = parseSize(v, &a->width, &a->height);
    else if (opt == "--seconds") ok = parseSeconds(v, &a->seconds);
    else if (opt == "--frames") ok = parseFrames(v, a, &why);
    else if (opt == "--fps") ok = parseFps(v, &a->fps);
    else if (opt == "--voxel") ok = parseVoxel(v, &a->voxel);
    else if (opt == "--threads") ok = parseInt(v, 1, 2, &a->threads);
    else if (opt == "--mode") a->mode = v;
    else if (opt == "--post") a->post = v;
    else if (opt == "--backend") a->backend = v;
    else if (opt == "--quality") a->quality = v;
    if (!ok) {
        static const char* expected[][2] = {
            {"-o", "a file path"},
            {"--size", kImageSizeRule},
            {"--seconds", "a number of seconds from 0 to 3600"},
            {"--frames", "N, a whole number from 1 to 100000, or A-B, frames 0 to 10000000"},
            {"--fps", "a number of frames per second, more than 0 and at most 1000"},
            {"--threads", "1 or 2"},
            {"--voxel", "a voxel size in metres, more than 0"}};
        for (auto& e : expected)
            if (opt == e[0])
                *error = "bad value " + quoteArg(v) + " for " + opt + ": " +
                         (why.empty() ? "expected " + std::string(e[1]) : why);
    }
    return ok;
}

bool parseArgs(int argc, char** argv, int first, Args* out, std::string* error) {
    for (int i = first; i < argc; ++i) {
        std::string arg = argv[i];
        if (arg.size() > 1 && arg[0] == '-') out->given.push_back(arg);
        if (arg == "--uber") {
            out->uber = true;
        } else if (arg == "--skip-existing") {
            out->skipExisting = true;
        } else if (arg == "-o" || arg == "--size" || arg == "--seconds" || arg == "--frames" ||
                   arg == "--fps" || arg == "--voxel" || arg == "--threads" || arg == "--mode" ||
                   arg == "--post" || arg == "--backend" || arg == "--quality") {
            if (i + 1 >= argc) {
                *error = "missing value after " + arg;
                return false;
            }
            if (!applyValue(arg, argv[++i], out, error)) return false;
        } else if (arg.size() > 1 && arg[0] == '-') {
            *error = "unknown option " + quoteArg(arg);
            return false;
        } else {
            out->positional.push_back(arg);
        }
    }
    return true;
}

std::string optionNotIn(const Args& a, std::string_view allowed) {
    for (const std::string& option : a.given) {
        bool found = false;
        for (size_t at = allowed.find(option); at != std::string_view::npos && !found;
             at = allowed.find(option, at + 1)) {
            const size_t end = at + option.size();
            found = (at == 0 || allowed[at - 1] == ' ') &&
                    (end == allowed.size() || allowed[end] == ' ');
        }
        if (!found) return option;
    }
    return "";
}

}  // namespace mb
