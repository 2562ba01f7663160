// interrupt.cpp — a flag set by the signal handler, the only thing a handler may safely do.
#include "interrupt.h"

#include <csignal>
#include <cstdlib>

namespace mb {

static volatile std::sig_atomic_t caught = 0;  // the signal's number, 0 while none came
static constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};

void catchInterrupts() {
    struct sigaction note {};
    note.sa_handler = [](int sig) {
        if (!caught) caught = sig;
    };
    sigemptyset(&note.sa_mask);
    for (int sig : kSignals) sigaction(sig, &note, nullptr);
}

bool interrupted() { return caught != 0; }

// Dying of the signal, not exiting with a status, tells a shell or GNU parallel that the user
// stopped the run, so a script around it stops too.
void endInterrupted() {
    const int sig = caught ? int(caught) : SIGINT;
    std::signal(sig, SIG_DFL);
    std::raise(sig);
    std::_Exit(128 + sig);  // only if the signal was blocked
}

}  // namespace mb
