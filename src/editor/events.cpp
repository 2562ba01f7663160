// events.cpp — the event log's one stream.
#include "marchbox/editor/events.h"

#include <ostream>

namespace mb {

static std::ostream* gEvents = nullptr;

void setEventStream(std::ostream* out) { gEvents = out; }
bool eventsOn() { return gEvents != nullptr; }

void emitEvent(const std::string& line) {
    if (!gEvents) return;
    // Flushed per line: a test reads the log while the editor is still running.
    *gEvents << line << std::endl;
}

}  // namespace mb
