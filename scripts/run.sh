#!/usr/bin/env bash
# Sets up Marchbox and opens the editor on the scene given, or on an untitled copy of
# scenes/default.txt (Save asks where). With no display it says so and renders the scene to a
# PNG in the working folder instead.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh build
exec build/marchbox "$@"
