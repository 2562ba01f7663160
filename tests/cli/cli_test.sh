#!/usr/bin/env bash
# cli_test.sh — absurd command lines get one line on standard error and the exit status of
# docs/cli.md (1 bad input, 2 usage, 3 OpenGL), never a crash, a hang or a stack trace.
# Usage: tests/cli/cli_test.sh MARCHBOX SOURCE_DIR GROUP   (GROUP: args, files or gl)
set -uo pipefail
mb=$1 src=$2 group=$3
scene=$src/scenes/primitives.txt
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0

# expect STATUS CMD...: runs CMD (60 s at most) and checks its exit status and that standard
# error is exactly one non-empty line. MB_ENV, when set, is passed to env for the command.
expect() {
  local want=$1
  shift
  timeout 60 env ${MB_ENV:-} "$@" >"$tmp/out" 2>"$tmp/err" </dev/null
  local got=$? lines
  lines=$(wc -l <"$tmp/err")
  if [[ $got -ne $want || $lines -ne 1 || ! -s $tmp/err ]]; then
    echo "FAIL: $* -> exit $got (want $want), $lines stderr lines:" >&2
    head -c 600 "$tmp/err" >&2
    failures=$((failures + 1))
  fi
}

# Like expect, and standard error must also contain TEXT.
expect_says() {
  local text=$1
  shift
  expect "$@"
  grep -qF -- "$text" "$tmp/err" || { echo "FAIL: $* does not say '$text'" >&2; failures=$((failures + 1)); }
}

args_cases() {
  local r=("$mb" render "$scene" -o "$tmp/x.png")
  for size in 0x0 100000x100000 junk 16384x16384 640x x360 -640x360 640x360x2 '' 0x10 \
              99999999999999999999x1 640X360; do
    expect 2 "${r[@]}" --size "$size"
  done
  for t in -1 nan NaN inf -inf 1e400 0x10 '' abc 3601 ' 5' 1,5; do
    expect 2 "${r[@]}" --seconds "$t"
    expect 2 "$mb" simulate "$scene" --seconds "$t"
  done
  for threads in 0 3 x ''; do expect 2 "$mb" simulate "$scene" --seconds 1 --threads "$threads"; done
  expect 2 "$mb" bench "$scene" --frames 0
  expect 2 "$mb" bench "$scene" --frames -5
  expect 2 "$mb" render "$scene" --mode bogus -o "$tmp/x.png"
  for q in bogus '' Draft fast 'draft ' 1; do
    expect_says "expected draft, normal or final" 2 "$mb" render "$scene" --quality "$q" -o "$tmp/x.png"
    expect_says "expected draft, normal or final" 2 "$mb" bench "$scene" --quality "$q"
  done
  expect 2 "$mb" render "$scene" -o "$tmp/x.png" --quality
  for opt in --seconds --size -o --frames --mode; do expect 2 "$mb" simulate "$scene" "$opt"; done
  # An option another command takes is refused, not ignored.
  expect_says "simulate takes no option '--size'" 2 "$mb" simulate "$scene" --seconds 1 --size 10x10
  expect_says "render takes no option '--voxel'" 2 "${r[@]}" --voxel 1
  expect_says "check takes no option '--seconds'" 2 "$mb" check "$scene" --seconds 1
  expect_says "export takes no option '--mode'" 2 "$mb" export "$scene" -o "$tmp/x.stl" --mode id
  expect_says "the editor takes no option '-o'" 2 "$mb" -o "$tmp/x.png"
  # One frame is a PNG: written to another name it would pass for what it is not.
  echo video > "$tmp/v.mp4"
  expect_says "a video takes --frames A-B" 2 "$mb" render "$scene" -o "$tmp/v.mp4" --size 16x10
  grep -qx video "$tmp/v.mp4" || { echo "FAIL: render wrote over v.mp4" >&2; failures=$((failures + 1)); }
  expect_says "-o must end in .png" 2 "$mb" render "$scene" -o "$tmp/x.stl" --size 16x10
  expect_says "unknown command 'foo'" 2 "$mb" foo
  expect_says "unknown command 'rendr'" 2 "$mb" rendr "$scene"
  expect 2 "$mb" "$(printf 'a%.0s' {1..5000})"         # too long for a file name
  expect 2 "$mb" "$(printf 'two\nlines')"               # one line even so
  expect 2 "$mb" --bogus
  expect 2 "$mb" render
  expect 2 "$mb" render "$scene"
  expect 2 "$mb" render "$scene" "$scene" -o "$tmp/x.png"
  expect 2 "$mb" simulate
  expect_says "simulate needs --seconds T" 2 "$mb" simulate "$scene"
  expect 2 "$mb" check
  expect 2 "$mb" shader
  expect 2 "$mb" report bogus
}

files_cases() {
  # A directory where a scene belongs, for each command that reads one.
  expect_says "is a directory" 1 "$mb" "$src/scenes"
  expect 1 "$mb" render "$src/scenes" -o "$tmp/x.png" --size 8x8
  expect 1 "$mb" simulate "$src/scenes" --seconds 0
  expect 1 "$mb" check "$src/scenes"
  expect 1 "$mb" check "$tmp/missing.txt"
  # A file name with a newline in it: each error still one line.
  printf 'world gravity:-1\n' >"$tmp/$(printf 'two\nlines').txt"
  expect_says "two?lines.txt:1: 'gravity' must be >= 0" 1 "$mb" check "$tmp/$(printf 'two\nlines').txt"
  # Two simulator threads give the same bytes as one, on a pile whose contacts are split
  # between them (PhysicsWorld.TheCliThreadsSceneSplitsItsContacts).
  local pile=$src/tests/scenes/split_pile.txt
  "$mb" simulate "$pile" --seconds 1.5 --threads 2 >"$tmp/two.txt" &&
    "$mb" simulate "$pile" --seconds 1.5 --threads 1 >"$tmp/one.txt" && cmp -s "$tmp/one.txt" "$tmp/two.txt" &&
    ! cmp -s "$tmp/one.txt" "$pile" ||
    { echo "FAIL: simulate --threads 2 differs from --threads 1, or did not run" >&2; failures=$((failures + 1)); }
  # 8 MB scenes: one line of 8 MB, and 8 MB of objects past the limit. Each is one error.
  head -c 8388608 /dev/zero | tr '\0' x >"$tmp/line.txt"
  expect_says "line longer than 4096 bytes" 1 "$mb" check "$tmp/line.txt"
  { echo "material r:1 g:1 b:1"
    yes "object type:sphere pos:0,1,0 radius:0.5" | head -n 205000; } >"$tmp/objects.txt"
  expect_says "more than 4096 objects" 1 "$mb" simulate "$tmp/objects.txt" --seconds 1
  # No display: the editor's scene as a PNG in the working folder, saying where, on stdout.
  mkdir "$tmp/run"
  (cd "$tmp/run" && timeout 60 env -u DISPLAY -u WAYLAND_DISPLAY "$mb" "$scene" >"$tmp/out" 2>"$tmp/err")
  local status=$?
  [[ $status -eq 0 && -s $tmp/run/primitives-preview.png && ! -s $tmp/err ]] &&
    grep -qF "to $tmp/run/primitives-preview.png" "$tmp/out" ||
    { echo "FAIL: no preview in the working folder (exit $status): $(cat "$tmp/out" "$tmp/err")" >&2
      failures=$((failures + 1)); }
  # Outputs that cannot be written; a device is refused, not replaced.
  expect 1 "$mb" render "$scene" -o "$tmp/missing/x.png" --size 8x8
  expect 1 "$mb" render "$scene" -o "$tmp" --size 8x8
  expect 1 "$mb" simulate "$scene" --seconds 0 -o "$tmp/missing/x.txt"
  # Refused before the work: with no shaders a render that got as far as drawing would exit 3.
  MB_ENV=MARCHBOX_SHADERS=/nonexistent expect_says "cannot write '$tmp/missing/x.png'" 1 "$mb" render "$scene" \
    -o "$tmp/missing/x.png" --size 8x8
  expect 1 "$mb" simulate "$scene" --seconds 0 -o "$tmp"
  expect_says "not a regular file" 1 "$mb" simulate "$scene" --seconds 0 -o /dev/null
  [[ -c /dev/null ]] || { echo "FAIL: /dev/null was replaced" >&2; failures=$((failures + 1)); }
  if [[ -w /dev/full ]]; then
    expect 1 sh -c '"$0" simulate "$1" --seconds 0 >/dev/full' "$mb" "$scene"
    expect 1 sh -c '"$0" shader "$1" >/dev/full' "$mb" "$scene"
    expect 1 sh -c '"$0" --help >/dev/full' "$mb"
    expect 1 sh -c '"$0" --version >/dev/full' "$mb"
  fi
}

gl_cases() {
  local r=("$mb" render "$scene" -o "$tmp/x.png" --size 8x8)
  MB_ENV=MARCHBOX_SHADERS=/nonexistent expect_says "/nonexistent" 3 "${r[@]}"
  MB_ENV=MARCHBOX_SHADERS=/nonexistent expect 3 "$mb" bench "$scene" --frames 1 --size 8x8
  if [[ -w /dev/full ]]; then expect 1 sh -c '"$0" bench "$1" --frames 1 --size 8x8 >/dev/full' "$mb" "$scene"; fi
  # Of an even count of frames the median is the mean of the middle two, not the upper one.
  "$mb" bench "$scene" --frames 2 --size 8x8 >"$tmp/bench" 2>/dev/null
  awk '/^frame/ {sum += $3} /^median_ms/ {got = $2} END {exit !(got != "" && (got - sum / 2) ^ 2 < 4e-6)}' \
    "$tmp/bench" || { echo "FAIL: bench's median of 2 frames: $(cat "$tmp/bench")" >&2; failures=$((failures + 1)); }
  MB_ENV=MARCHBOX_SHADERS=/nonexistent expect 3 "$mb" shader "$scene"
  # A syntax error in an included file, then in the vertex shader: the driver's first error
  # line, naming the file and line that hold it. sdf.glsl has #if blocks that the shader drops
  # before its last line; lighting.glsl comes after the code compiled for the scene.
  cp -r "$src/shaders" "$tmp/shaders"
  echo "float broken() { return ; }" >>"$tmp/shaders/sdf.glsl"
  MB_ENV=MARCHBOX_SHADERS=$tmp/shaders expect_says \
    "fragment shader: $tmp/shaders/sdf.glsl:$(wc -l <"$tmp/shaders/sdf.glsl")(" 3 "${r[@]}"
  grep -q "error" "$tmp/err" || { echo "FAIL: no error line: $(cat "$tmp/err")" >&2; failures=$((failures + 1)); }
  cp "$src/shaders/sdf.glsl" "$tmp/shaders/sdf.glsl"
  sed -i '4s/^/garbage /' "$tmp/shaders/lighting.glsl"
  MB_ENV=MARCHBOX_SHADERS=$tmp/shaders expect_says "$tmp/shaders/lighting.glsl:4(" 3 "${r[@]}"
  # Run from the folder that holds shaders/, the file is named as a person would type it.
  MB_ENV=MARCHBOX_SHADERS=$tmp/shaders expect_says ": shaders/lighting.glsl:4(" 3 \
    sh -c 'cd "$0" && exec "$@"' "$tmp" "${r[@]}"
  cp "$src/shaders/lighting.glsl" "$tmp/shaders/lighting.glsl"
  # Draft's fill pass: a broken one fails the render instead of writing an undrawn picture.
  echo "garbage" >>"$tmp/shaders/checkerboard.frag"
  MB_ENV=MARCHBOX_SHADERS=$tmp/shaders expect_says \
    "$tmp/shaders/checkerboard.frag:$(wc -l <"$tmp/shaders/checkerboard.frag")(" 3 "${r[@]}" --quality draft
  cp "$src/shaders/checkerboard.frag" "$tmp/shaders/checkerboard.frag"
  echo "garbage" >>"$tmp/shaders/fullscreen.vert"
  MB_ENV=MARCHBOX_SHADERS=$tmp/shaders expect_says \
    "vertex shader: $tmp/shaders/fullscreen.vert:$(wc -l <"$tmp/shaders/fullscreen.vert")(" 3 "${r[@]}"
}

"${group}_cases"
if ((failures)); then
  echo "$failures failure(s) in group $group" >&2
  exit 1
fi
echo "cli $group: all cases passed"
