#!/usr/bin/env bash
# Renders the pictures the documentation shows, with Marchbox itself.
# Usage: scripts/make-pictures.sh [MARCHBOX]   (default build/marchbox; build it first)
# Writes docs/images/front.png: scenes/default.txt at 640x360, as the README shows it.
set -euo pipefail
cd "$(dirname "$0")/.."
marchbox=${1:-build/marchbox}
if [[ ! -x $marchbox ]]; then
  echo "make-pictures: $marchbox is not built; run scripts/setup.sh first" >&2
  exit 1
fi
mkdir -p docs/images
"$marchbox" render scenes/default.txt -o docs/images/front.png --size 640x360
