// frame_pattern.cpp — the one printf field of a frame sequence's file names, read by hand: the
// pattern is a user's text, and a stray %s handed to printf would read memory.
#include "frame_pattern.h"

#include "args.h"

#include <cctype>

namespace mb {

std::string FramePattern::name(int frame) const {
    std::string digits = std::to_string(frame);
    if (int(digits.size()) < width) digits.insert(0, size_t(width) - digits.size(), '0');
    return before + digits + after;
}

// Reads the conversion after the '%' at `at`: "%%", or the frame field %d or %0Nd (N from 1 to
// 99). Returns its length, 0 for anything else: %5d pads with spaces in printf and is not a
// field ffmpeg reads back, so it is refused too.
static size_t conversionLength(const std::string& p, size_t at, int* width) {
    size_t i = at + 1;
    if (i < p.size() && p[i] == '%') return 2;
    *width = 0;
    if (i < p.size() && p[i] == '0') {
        for (++i; i < p.size() && i < at + 4 && std::isdigit(static_cast<unsigned char>(p[i]));)
            *width = *width * 10 + (p[i++] - '0');
        if (*width == 0) return 0;
    }
    return i < p.size() && p[i] == 'd' ? i + 1 - at : 0;
}

bool parseFramePattern(const std::string& pattern, FramePattern* out, std::string* error) {
    FramePattern result;
    int fields = 0;
    std::string* text = &result.before;
    for (size_t at = 0; at < pattern.size();) {
        if (pattern[at] != '%') {
            *text += pattern[at++];
            continue;
        }
        int width = 0;
        size_t n = conversionLength(pattern, at, &width);
        if (n == 2 && pattern[at + 1] == '%') {
            *text += '%';
        } else if (n == 0 || ++fields > 1) {
            *error = "bad output pattern " + quoteArg(pattern) +
                     (n == 0 ? ": a '%' that is not %d, %05d or %%"
                             : ": two frame-number fields, it takes one");
            return false;
        } else {
            result.width = width;
            text = &result.after;
        }
        at += n;
    }
    if (fields == 1) return *out = result, true;
    *error = "bad output pattern " + quoteArg(pattern) +
             ": it needs one frame-number field such as %05d (out/frame_%05d.png)";
    return false;
}

}  // namespace mb
