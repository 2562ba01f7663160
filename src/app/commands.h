// commands.h — the subcommands of ../shared/CLI.md. Each returns the process exit status.
#pragma once

#include "args.h"

namespace mb {

int runRender(const Args& a);
int runSimulate(const Args& a);
int runCheck(const Args& a);
int runShader(const Args& a);
int runBench(const Args& a);
int runReport(const Args& a);
int runEditor(const Args& a);

}  // namespace mb
