// marchbox/gl/glsl_conditionals.h — resolving #if/#elif/#else/#endif before the driver sees
// the source, so a printed shader holds only the code its scene compiles.
#pragma once

#include "marchbox/gl/shader_lines.h"

#include <map>
#include <string>

namespace mb {

using Defines = std::map<std::string, long>;

// Keeps the lines of taken branches and drops the directives and the rest. Conditions are
// integer expressions over numbers and the names in `defines` (an unknown name is 0) with
// ( ) ! * / + - < <= > >= == != && ||. Other lines, #define and #version included, pass through.
// Returns false with *error on an unbalanced #endif or a malformed expression. `lines`, when
// given, holds the origin of each line of `source`: errors name it, and it is left with the
// origins of the lines kept. Without it errors name `line N` of `source`.
bool resolveConditionals(const std::string& source, const Defines& defines, std::string* out,
                         std::string* error, LineMap* lines = nullptr);

}  // namespace mb
