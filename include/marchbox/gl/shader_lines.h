// marchbox/gl/shader_lines.h — where each line of an assembled shader came from, so the
// driver's log names the file a person edits, not a line of the whole.
//
// GLSL's #line takes numbers only, so the shader is sent as it is and its log is mapped back:
// `0:123(4): error: ...` becomes `/path/shaders/lighting.glsl:42(4): error: ...`. Lines with
// no file of their own are named for what made them: `<defines>`, `<scene code>`.
#pragma once

#include <string>
#include <vector>

namespace mb {

struct LineOrigin {
    std::string file;
    int line = 0;  // 1-based, in `file`

    bool operator==(const LineOrigin&) const = default;
};

// Entry i is the origin of line i + 1 of the assembled source.
using LineMap = std::vector<LineOrigin>;

// Each line of `text` as line 1, 2, ... of `file`.
LineMap linesOf(const std::string& file, const std::string& text);

// The map of `prefix` + a body mapped by `body`: the prefix's lines are `<defines>` 1, 2, ...
LineMap withPrefix(const std::string& prefix, const LineMap& body);

// Rewrites each log line that starts with a location in source string 0, as Mesa
// (`0:L(C):`), AMD and Intel (`ERROR: 0:L:`) and NVIDIA (`0(L) :`) write it, to `file:line`.
// Locations past the map and other lines are left as they are.
std::string rewriteShaderLog(const std::string& log, const LineMap& lines);

}  // namespace mb
