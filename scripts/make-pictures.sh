#!/usr/bin/env bash
# Renders the pictures the documentation shows, with Marchbox itself.
# Usage: scripts/make-pictures.sh [MARCHBOX]   (default build/marchbox; build it first)
# Writes docs/images/front.png (scenes/default.txt at 640x360, as the README shows it), the
# getting-started guide's pictures and, where Debian's f3d viewer is installed (it is no
# dependency: `apt-get install f3d`), docs/export.md's picture of an export opened in it.
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
# docs/images/export-dominoes.png: an animated export opened in a real glTF viewer, from its
# own camera (f3d 1.3 draws the first frame).
if command -v f3d >/dev/null; then
  "$marchbox" export scenes/dominoes.txt -o build/export-dominoes.glb --frames 0-90
  xvfb-run -a -s "-screen 0 1280x800x24" f3d build/export-dominoes.glb \
      --output docs/images/export-dominoes.png --resolution 640,360 \
      --camera-index 0 --tone-mapping --fxaa --ssao --grid --bg-color 0.85,0.87,0.9
else
  echo "make-pictures: f3d is not installed; docs/images/export-dominoes.png left as it is"
fi
