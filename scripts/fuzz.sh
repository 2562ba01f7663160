#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (build-fuzz/) and runs each for SECONDS.
# Usage: scripts/fuzz.sh SECONDS [TARGET...]   (targets: fuzz_scene_parse fuzz_scene_roundtrip)
#
# Seeds: scenes/*.txt, tests/fuzz/seeds/ and tests/fuzz/regressions/; the growing corpus stays
# in build-fuzz/corpus/TARGET between runs. A crash, hang or leak is written to
# build-fuzz/findings/ and the script fails: copy the file into tests/fuzz/regressions/ so
# scene_tests replays it (tests/scene/test_fuzz_regressions.cpp), then fix the parser.
set -euo pipefail
cd "$(dirname "$0")/.."

seconds=${1:?usage: scripts/fuzz.sh SECONDS [TARGET...]}
shift
targets=("$@")
((${#targets[@]})) || targets=(fuzz_scene_parse fuzz_scene_roundtrip)

cmake -S . -B build-fuzz -DMARCHBOX_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ >/dev/null
cmake --build build-fuzz -j"$(nproc)" --target "${targets[@]}"

mkdir -p build-fuzz/findings
status=0
for t in "${targets[@]}"; do
  corpus=build-fuzz/corpus/$t
  mkdir -p "$corpus"
  echo "fuzz: $t for ${seconds}s"
  # 16 KiB holds every seed and several maximum-length (4096-byte) lines; the limit on a line
  # matters more to the parser than the size of a file. A run over 10 s is a hang.
  build-fuzz/"$t" "$corpus" scenes tests/fuzz/seeds tests/fuzz/regressions \
      -dict=tests/fuzz/scene.dict -max_len=16384 -timeout=10 -rss_limit_mb=2048 \
      -max_total_time="$seconds" -print_final_stats=1 \
      -artifact_prefix=build-fuzz/findings/"$t"- 2>&1 | tee build-fuzz/"$t".log |
      grep -E '^(#[0-9]+[[:space:]]+(INITED|DONE)|stat::|==[0-9]+==|SUMMARY|artifact_prefix|Test unit)' \
      || true
  [[ ${PIPESTATUS[0]} -eq 0 ]] || status=1
done
if ((status)); then
  echo "fuzz: findings in build-fuzz/findings/ (full logs in build-fuzz/*.log)" >&2
fi
exit "$status"
