// interrupt.h — Ctrl-C (and SIGTERM, SIGHUP) during a command that must clean up first: the
// signal is only noted; the command polls interrupted() between steps, removes what it left
// half done, then endInterrupted() ends the process as the signal would have.
#pragma once

namespace mb {

void catchInterrupts();              // from now on the three signals only set the flag
bool interrupted();                  // one of them has come
[[noreturn]] void endInterrupted();  // the default action again, and the signal raised

}  // namespace mb
