// main.cpp — marchbox: the editor, or one of the subcommands of docs/cli.md.
#include "args.h"
#include "commands.h"

#include <cstring>
#include <filesystem>
#include <iostream>
#include <string_view>

static const char* kUsage =
    "usage: marchbox [SCENE]                      open the editor (default: an untitled copy of\n"
    "                                             scenes/default.txt; a new file: an empty scene)\n"
    "       marchbox render SCENE -o OUT.png [--size WxH] [--seconds T] [--uber] [--mode M] "
    "[--post P]\n"
    "                [--quality Q] [--threads N]\n"
    "       marchbox render SCENE -o PATTERN|OUT.mp4 --frames A-B [--fps F] [--size WxH] "
    "[--quality Q]\n"
    "                [--skip-existing]   (PATTERN: one frame-number field, out/frame_%05d.png)\n"
    "       marchbox simulate SCENE --seconds T [-o OUT.txt] [--threads N]\n"
    "       marchbox export SCENE -o OUT.stl|.obj|.ply|.glb [--voxel S] [--seconds T]\n"
    "       marchbox export SCENE -o OUT.glb --frames A-B [--fps F] [--voxel S]   (animated)\n"
    "       marchbox check SCENE...\n"
    "       marchbox shader SCENE [--uber]\n"
    "       marchbox bench SCENE [--uber] [--size WxH] [--frames N] [--quality Q]\n"
    "       marchbox report physics|render|export\n"
    "       marchbox --help | --version\n"
    "modes: shaded normals depth steps ao shadow id; post passes: none fxaa fxaa-edges "
    "fxaa-direction\n"
    "quality presets: draft normal (the scene as written) final\n"
    "threads: the simulator's, 1 (default) or 2; the same result either way\n";

// `marchbox rendr x.txt` is a typo of a command, not a scene to open: a first word that is no
// file and has no .txt ending. A missing scene.txt still reaches the editor, which says so.
static bool looksLikeCommand(const char* arg) {
    std::string_view s(arg);
    bool txt = s.size() >= 4 && s.substr(s.size() - 4) == ".txt";
    std::error_code error;  // e.g. a name too long: not a file either, and must not throw
    return !s.empty() && s[0] != '-' && !txt && !std::filesystem::exists(s, error);
}

int main(int argc, char** argv) {
    using namespace mb;
    if (argc > 1 && (!std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h"))) {
        std::cout << kUsage;
        return flushStdout();
    }
    if (argc > 1 && !std::strcmp(argv[1], "--version")) {
        std::cout << "marchbox " << MARCHBOX_VERSION << '\n';
        return flushStdout();
    }
    struct Command {
        const char* name;
        int (*run)(const Args&);
        const char* options;  // the options it takes (docs/cli.md's Options)
    };
    static const Command commands[] = {
        {"render", runRender,
         "-o --size --seconds --frames --fps --skip-existing --uber --mode --quality --post "
         "--backend --threads"},
        {"simulate", runSimulate, "-o --seconds --threads"},
        {"check", runCheck, ""},
        {"shader", runShader, "--uber"},
        {"bench", runBench, "--size --frames --uber --mode --quality --post --backend"},
        {"report", runReport, "--backend"},
        {"export", runExport, "-o --seconds --frames --fps --voxel --threads"}};
    const Command* command = nullptr;
    for (const Command& c : commands)
        if (argc > 1 && !std::strcmp(argv[1], c.name)) command = &c;
    if (!command && argc > 1 && looksLikeCommand(argv[1])) {
        std::cerr << "marchbox: unknown command " << quoteArg(argv[1])
                  << " (see marchbox --help)\n";
        return kExitUsage;
    }
    Args args;
    std::string error;
    if (!parseArgs(argc, argv, command ? 2 : 1, &args, &error)) {
        std::cerr << "marchbox: " << error << " (see marchbox --help)\n";
        return kExitUsage;
    }
    // An option the command does not take would be ignored: say so, as for an unknown one.
    if (const std::string stray = optionNotIn(args, command ? command->options : "");
        !stray.empty()) {
        std::cerr << "marchbox: " << (command ? command->name : "the editor") << " takes no option "
                  << quoteArg(stray) << " (see marchbox --help)\n";
        return kExitUsage;
    }
    return command ? command->run(args) : runEditor(args);
}
