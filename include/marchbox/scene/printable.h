// marchbox/scene/printable.h — text from a file or a command line, made fit for a one-line message.
#pragma once

#include <string>
#include <string_view>

namespace mb {

// `s` with each control byte (newline, CR, ESC, NUL, DEL) shown as '?': echoed raw they would
// split the message into lines or rewrite the terminal it is printed on. Every other byte,
// UTF-8 included, is kept, so a plain name reads as typed.
inline std::string printable(std::string_view s) {
    std::string out(s);
    for (char& c : out)
        if ((unsigned char)c < 0x20 || c == 0x7f) c = '?';
    return out;
}

}  // namespace mb
