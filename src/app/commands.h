// commands.h — the subcommands of docs/cli.md. Each returns the process exit status.
#pragma once

#include "args.h"

#include "marchbox/gl/offscreen_context.h"
#include "marchbox/gl/quality_preset.h"
#include "marchbox/gl/renderer.h"
#include "marchbox/physics/physics.h"

namespace mb {

int runRender(const Args& a);
int runRenderFrames(const Args& a);  // render --frames A-B (render_frames.cpp)
int runSimulate(const Args& a);
int runCheck(const Args& a);
int runShader(const Args& a);
int runBench(const Args& a);
int runReport(const Args& a);
int runExport(const Args& a);  // export SCENE -o OUT: a mesh file (marchbox/export/export.h)
int runEditor(const Args& a);

// What the commands share. Each reports its own error, one line on standard error.
bool loadOrReport(const std::string& path, Scene* scene);
bool needOne(const Args& a, const char* usage);  // exactly one SCENE, or the usage line
bool needOutput(const Args& a, const char* command, const char* what);  // -o
bool offscreenBackend(const Args& a, OffscreenBackend* out);  // --backend, or a usage error
bool renderOptions(const Args& a, RenderOptions* o);          // --mode, --post, --uber
bool qualityPreset(const Args& a, QualityPreset* out);        // --quality
PhysicsSettings physicsSettings(const Args& a);               // --threads
int glFailure(const char* doing, const std::string& error);   // one line on stderr, exit 3
int flushStdout();  // 0, or one line on stderr and exit 1 where standard output took no more

}  // namespace mb
