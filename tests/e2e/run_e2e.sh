#!/usr/bin/env bash
# run_e2e.sh CASE MARCHBOX WORKDIR — one end-to-end case in a fresh Xvfb screen.
# Exits 77 (CTest's skip) with a message only when no X server can be started here.
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
case_name=$1 marchbox=$2 workdir=$3
screen=(-s "-screen 0 1280x800x24")

for tool in xvfb-run xdotool python3; do
  if ! command -v "$tool" >/dev/null; then
    echo "SKIP: $tool is not installed (scripts/setup.sh installs it)"
    exit 77
  fi
done
if ! xvfb-run -a "${screen[@]}" true >/dev/null 2>&1; then
  echo "SKIP: Xvfb cannot start here"
  exit 77
fi
exec xvfb-run -a "${screen[@]}" python3 "$here/editor_e2e.py" "$case_name" "$marchbox" \
  "$here/e2e_scene.txt" "$workdir"
