#!/usr/bin/env bash
# Two marchbox builds side by side on the example scenes: median frame time of each, their
# ratio, and the mean difference of their pictures. Runs alternate A B A B so that a machine
# whose speed drifts slows both alike; each figure is the median over the rounds.
# Usage: src/report/bench/compare_renderers.sh OLD_MARCHBOX NEW_MARCHBOX [WxH] [ROUNDS] [SCENE...]
# Prints a markdown table (docs/render-report.md, "Compiled against the general program").
set -euo pipefail
cd "$(dirname "$0")/.."
old=$1 new=$2 size=${3:-640x360} rounds=${4:-5}
shift $(($# < 4 ? $# : 4))
scenes=("$@")
((${#scenes[@]})) || scenes=(default csg primitives pile reflections fog)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

frame_ms() { "$1" bench "scenes/$2.txt" --size "$size" --frames 3 | awk '/median_ms/ {print $2}'; }

echo "| scene | old ms | new ms | speed-up | mean diff /255 |"
echo "| --- | ---: | ---: | ---: | ---: |"
logsum=0
for s in "${scenes[@]}"; do
  : >"$tmp/old" && : >"$tmp/new"
  for ((r = 0; r < rounds; ++r)); do
    frame_ms "$old" "$s" >>"$tmp/old"
    frame_ms "$new" "$s" >>"$tmp/new"
  done
  o=$(sort -g "$tmp/old" | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}')
  n=$(sort -g "$tmp/new" | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}')
  "$old" render "scenes/$s.txt" -o "$tmp/a.png" --size "$size" >/dev/null
  "$new" render "scenes/$s.txt" -o "$tmp/b.png" --size "$size" >/dev/null
  diff=$(python3 src/report/bench/png_mean_diff.py "$tmp/a.png" "$tmp/b.png")
  echo "| $s | $o | $n | $(awk -v o="$o" -v n="$n" 'BEGIN {printf "%.1fx", o / n}') | $diff |"
  logsum=$(awk -v l="$logsum" -v o="$o" -v n="$n" 'BEGIN {print l + log(o / n)}')
done
awk -v l="$logsum" -v k="${#scenes[@]}" 'BEGIN {printf "\nGeometric-mean speed-up: %.1fx\n", exp(l / k)}'
