#!/usr/bin/env bash
# Builds the unit tests that need no OpenGL with AddressSanitizer and UndefinedBehaviorSanitizer
# (MARCHBOX_SANITIZE, in build-asan/) and runs them; any report fails the run.
# Usage: scripts/test-sanitized.sh [gtest args...]
set -euo pipefail
cd "$(dirname "$0")/.."

# Debug (-O0): ASan+UBSan at -O2 makes g++ take minutes over a file that uses <regex>, which
# would dwarf the tests' own run time in CI; -O0 also keeps every assert.
cmake -S . -B build-asan -DMARCHBOX_SANITIZE=ON -DCMAKE_BUILD_TYPE=Debug >/dev/null
# Only the GL-free test binaries: the GL layer runs in llvmpipe, whose own code ASan would
# slow to a crawl and whose leaks are not ours (valgrind checks those; scripts/valgrind.sh).
targets=(scene_tests physics_tests reference_tests)
# grep without -q reads to the end: an early exit would kill cmake with SIGPIPE under pipefail.
if cmake --build build-asan --target help | grep -w editor_tests >/dev/null; then
  targets+=(editor_tests)
fi
cmake --build build-asan -j"$(nproc)" --target "${targets[@]}"

# Six rigid-body runs take 30 s optimised and many minutes at -O0 under ASan (the column and
# the large pyramid alone 82 s, the 400 thin bins 16 s); the same code runs in every other
# rigid-body test here.
slow=RigidWorld.PyramidSettlesAndSleeps:RigidWorld.MixedPileIsDeterministic
slow+=:RigidWorld.MixedPileAtALongStepRestsAboveTheGround:RigidWorld.ColumnOfThirtyStandsAMinuteAwake
slow+=:RigidWorld.PyramidOfFortyBaseSettlesAndSleeps:RigidWorld.ThinFastBodiesInABinGainNoEnergy
export GTEST_FILTER=${GTEST_FILTER:--$slow}
export ASAN_OPTIONS=detect_leaks=1:detect_stack_use_after_return=1:strict_string_checks=1
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
for t in "${targets[@]}"; do
  echo "sanitized: $t"
  build-asan/"$t" --gtest_brief=1 "$@"
done
