#!/usr/bin/env bash
# Renders the pictures the documentation shows, with Marchbox itself.
# Usage: scripts/make-pictures.sh [MARCHBOX]   (default build/marchbox; build it first)
# Writes docs/images/front.png (scenes/default.txt at 640x360, as the README shows it) and the
# getting-started guide's pictures.
set -euo pipefail
cd "$(dirname "$0")/.."
marchbox=${1:-build/marchbox}
if [[ ! -x $marchbox ]]; then
  echo "make-pictures: $marchbox is not built; run scripts/setup.sh first" >&2
  exit 1
fi
mkdir -p docs/images
"$marchbox" render scenes/default.txt -o docs/images/front.png --size 640x360
# docs/images/guide-*.png: the steps of docs/getting-started.md, from the e2e case that takes
# them in a real window (Xvfb).
MARCHBOX_GUIDE_IMAGES="$PWD/docs/images" bash tests/e2e/run_e2e.sh guide "$marchbox" \
  build/test-output/e2e/guide-pictures
