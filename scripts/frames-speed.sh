#!/usr/bin/env bash
# frames-speed.sh — what render --frames costs against renders of an already simulated scene,
# timed side by side in one run. Not a test: the figures move with the machine's load.
# Usage: scripts/frames-speed.sh [BUILD_DIR] [SCENE] [SIZE] [FRAMES]
#   (defaults: build scenes/pile.txt 160x90 300)
# Prints the wall time of
#   frames   one `render --frames 0-(FRAMES-1)` of SCENE, played from t = 0
#   settled  the same for SCENE simulated 10 s first: the same pipeline on still content
#   bench    `bench` of the simulated scene, FRAMES frames: drawing only (no readback, no PNG)
#   singles  FRAMES `render`s of the simulated scene, one process each
# and the time of frames over each of the others.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build} scene=${2:-scenes/pile.txt} size=${3:-160x90} frames=${4:-300}
mb=$PWD/$build/marchbox
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# seconds CMD...: runs CMD quietly and prints its wall time in seconds.
seconds() {
  local start end
  start=$(date +%s.%N)
  "$@" >/dev/null
  end=$(date +%s.%N)
  awk "BEGIN { print $end - $start }"
}

"$mb" simulate "$scene" --seconds 10 -o "$tmp/settled.txt"
last=$((frames - 1))
t_frames=$(seconds "$mb" render "$scene" -o "$tmp/f_%05d.png" --size "$size" --frames 0-$last)
t_settled=$(seconds "$mb" render "$tmp/settled.txt" -o "$tmp/s_%05d.png" --size "$size" --frames 0-$last)
t_bench=$(seconds "$mb" bench "$tmp/settled.txt" --size "$size" --frames "$frames")
singles() { for ((i = 0; i < frames; i++)); do "$mb" render "$tmp/settled.txt" -o "$tmp/one.png" --size "$size"; done; }
t_singles=$(seconds singles)
printf '%s, %d frames at %s\n' "$scene" "$frames" "$size"
for name in frames settled bench singles; do
  t=t_$name
  printf '%-8s %7.2f s   frames / %-8s %5.2fx\n' "$name" "${!t}" "$name" "$(awk "BEGIN { print $t_frames / ${!t} }")"
done
