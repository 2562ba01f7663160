// frame_pattern.h — render --frames' output PATTERN: a file name with one printf field for the
// frame number, such as out/frame_%05d.png.
#pragma once

#include <string>

namespace mb {

struct FramePattern {
    std::string before, after;  // the name around the field, each %% already made %
    int width = 0;              // at least this many digits, zero-padded (%05d: 5)

    std::string name(int frame) const;  // frame >= 0
};

// Accepts exactly one field, %d or %0Nd (N digits at least, 1 to 99), and %% for a percent sign;
// false with *error, one line, on none, two, or any other conversion.
bool parseFramePattern(const std::string& pattern, FramePattern* out, std::string* error);

}  // namespace mb
