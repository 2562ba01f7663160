#!/usr/bin/env bash
# Sets up Marchbox and opens the editor on scenes/default.txt (or the scene given).
# With no display it says so and renders the scene to a PNG instead.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh build
exec build/marchbox "${1:-scenes/default.txt}"
