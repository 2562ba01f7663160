#!/usr/bin/env bash
# Runs an off-screen render and a simulate under valgrind --leak-check=full and fails on any
# memory error or definite leak not allocated by the OpenGL driver (tests/valgrind/mesa.supp).
# Slow (a render takes about 1.5 minutes under valgrind): CI runs it last (.ci/run). The two
# runs go side by side, one a core: valgrind runs a program on one thread at a time.
# Usage: scripts/valgrind.sh [BUILD_DIR]   (default build; builds marchbox there if needed)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
[[ -f $build/CMakeCache.txt ]] || cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$build" -j"$(nproc)" --target marchbox >/dev/null

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# check NAME ARGS...: one marchbox run under memcheck; its log goes to BUILD/valgrind-NAME.log,
# its summary to standard output in one piece (the runs go side by side); fails on a report.
check() {
  local name=$1 log=$build/valgrind-$1.log status=0 said
  shift
  local start=$SECONDS
  # Mesa's disk shader cache serialises shaders with padding it never writes, and checks and
  # compresses those bytes on its own thread: three reports inside libOSMesa and libzstd for
  # each new program. The cache is off here; it stores nothing of Marchbox's.
  if MESA_SHADER_CACHE_DISABLE=true valgrind --leak-check=full --show-leak-kinds=definite,indirect \
       --errors-for-leak-kinds=definite,indirect --suppressions=tests/valgrind/mesa.supp \
       --num-callers=40 --error-exitcode=99 --log-file="$log" "$build/marchbox" "$@" >/dev/null; then
    said="valgrind $name: clean ($((SECONDS - start)) s)"
  else
    said="valgrind $name: FAILED, see $log"
    status=1
  fi
  said+=$'\n'$(grep -E "definitely lost|indirectly lost|possibly lost|suppressed:|no leaks are possible|ERROR SUMMARY" "$log" |
    sed 's/^==[0-9]*== */  /')
  echo "$said"
  return "$status"
}
check render render scenes/primitives.txt -o "$tmp/x.png" --size 64x36 &
render=$!
check simulate simulate scenes/pile.txt --seconds 2 -o "$tmp/after.txt" &
simulate=$!
status=0
wait "$render" || status=1
wait "$simulate" || status=1
exit "$status"
