// marchbox/editor/events.h — a line on a stream for each thing the editor does, so that scripts
// and end-to-end tests can follow it ("select 4", "save /tmp/a.txt", "undo Simulation run").
//
// Off unless a stream is set; the editor window sets standard output when MARCHBOX_EVENT_LOG=1.
#pragma once

#include <iosfwd>
#include <string>

namespace mb {

void setEventStream(std::ostream* out);  // null turns the log off
bool eventsOn();
void emitEvent(const std::string& line);  // written and flushed at once

}  // namespace mb
