// sequence_report.h — the render report's section on frame sequences.
#pragma once

#include <string>

namespace mb {

// What `render --frames` costs against drawing the same frames of an already simulated scene,
// each a whole process of this executable, timed side by side: a markdown table and a sentence
// with the target. `root`: the source tree, for scenes/pile.txt.
std::string sequenceSection(const std::string& root);

}  // namespace mb
