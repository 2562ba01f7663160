// commands.h — the subcommands of docs/cli.md. Each returns the process exit status.
#pragma once

#include "args.h"

#include "marchbox/gl/offscreen_context.h"

namespace mb {

int runRender(const Args& a);
int runSimulate(const Args& a);
int runCheck(const Args& a);
int runShader(const Args& a);
int runBench(const Args& a);
int runReport(const Args& a);
int runEditor(const Args& a);

bool offscreenBackend(const Args& a, OffscreenBackend* out);  // --backend, or a usage error
int glFailure(const char* doing, const std::string& error);   // one line on stderr, exit 3

}  // namespace mb
