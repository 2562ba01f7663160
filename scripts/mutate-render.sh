#!/usr/bin/env bash
# mutate-render.sh — the render tests' mutation score: plant each bug of the table below, one at
# a time, run the tests that should see it, and say whether they did.
#
#   scripts/mutate-render.sh [BUILD_DIR]      BUILD_DIR holds a built gl_tests (default: build)
#
# Shader mutations edit a copy of shaders/ in a temporary folder, which gl_tests reads through
# $MARCHBOX_SHADERS: no build. They run every gl_tests suite but AsyncCompile (an exclude list,
# so new render suites count as they are added; AsyncCompile sets and clears MARCHBOX_SHADERS
# itself and renders nothing to compare).
# Mirror mutations (src/scene/sdf.cpp, the C++ twin of the SDFs) edit a copy of the tracked
# source tree in BUILD_DIR/mutate-mirror/src, build gl_tests there in BUILD_DIR/mutate-mirror/
# build (incrementally, through ccache when it is installed) and run the agreement tests.
#
# Prints CAUGHT or SURVIVED per mutation, with the first failing test, then the score and the
# elapsed time. Exit status: 0 every mutation caught, 1 one or more survived, 2 an error: a
# pattern that does not occur exactly once in its file (update the table when the code changes),
# a mirror that does not build, or tests that fail with no mutation at all. Golden failures leave
# their .actual.png and .diff.png in BUILD_DIR/test-output/, as they always do.
#
# Measured on the 2-core machine (llvmpipe): 56 of 56 caught in 4 minutes 19 s with the mirror
# already built, each in 0-40 s; a survivor costs a whole run (about 40 s), the mirror's first
# build some 10 minutes more without ccache. Too slow for every CI run: run it after changing shaders/,
# src/scene/sdf.cpp or the render tests. JOBS=N sets the mirror build's parallelism (default 2).
set -uo pipefail

#-----------------------------------------------------------------------------
# [SECTION] Mutations, one per line: file | exact text, which must occur once | replacement |
# what a user would see. Text is matched literally (no regex); it may not contain " | ".
#-----------------------------------------------------------------------------
MUTATIONS=$(cat <<'TABLE'
shaders/lighting.glsl | s.k.z * spec)                                     | 0.5 * s.k.z * spec)                               | specular term halved
shaders/lighting.glsl | -rd), 0.0), s.k.w)                                | -rd), 0.0), 0.5 * s.k.w)                          | specular exponent halved: wider highlights
shaders/lighting.glsl | vec4(0.1, 0.8, 0.1, 16.0)                         | vec4(0.1, 0.8, 0.0, 16.0)                         | floor loses its highlight
shaders/lighting.glsl | skyGradient(rd) + sunGlow(rd, 4.0)                | skyGradient(rd) + sunGlow(rd, 0.0)                | sun disc removed from the sky
shaders/lighting.glsl | smoothstep(0.9995, 0.9997, c)                     | smoothstep(0.9990, 0.9997, c)                     | sun disc twice as wide
shaders/lighting.glsl | 0.25 * pow(c, 64.0)                               | 0.25 * pow(c, 16.0)                               | sun glow four times as wide
shaders/lighting.glsl | mix(vec3(1.0), uSkyTint, 0.35)                    | mix(vec3(1.0), uSkyTint, 0.0)                     | sky no longer tinted by the brightest light
shaders/lighting.glsl | mix(horizon, zenith, sqrt(rd.y))                  | mix(horizon, zenith, rd.y)                        | sky gradient linear instead of sqrt
shaders/raymarch.glsl | return res * res * (3.0 - 2.0 * res);             | return res;                                       | soft-shadow smoothstep dropped: linear penumbra
shaders/raymarch.glsl | float k = uSoftness, res = 1.0;                   | float k = 2.0 * uSoftness, res = 1.0;             | soft shadows twice as hard
shaders/lighting.glsl | shadow(p + n * 4.0 * normalStep(p), l, maxT)      | shadow(p, l, maxT)                                | shadow rays start on the surface: acne
shaders/lighting.glsl | uLights[i].color.rgb, dist,                       | uLights[i].color.rgb, uMaxDist,                   | objects beyond a point light shadow it
shaders/sdf.glsl      | h * h * k * 0.25                                  | h * h * k * 0.2                                   | smooth-union constant 0.25 -> 0.2: thinner blends
shaders/sdf.glsl      | vec2(length(p.xz) - major, p.y)                   | vec2(length(p.xz) - 0.9 * major, p.y)             | torus major radius 0.9x in the shader
shaders/lighting.glsl | mod(floor(p.x) + floor(p.z), 2.0)                 | mod(floor(2.0 * p.x) + floor(2.0 * p.z), 2.0)     | floor checkers 0.5 m instead of 1 m
shaders/lighting.glsl | exp(-(uFog * t) * (uFog * t))                     | exp(-(uFog * t))                                  | fog exp instead of exp^2
shaders/lighting.glsl | return skyGradient(level) + sunGlow(rd, 0.0);     | return skyGradient(level);                        | fog loses the sun's glow
shaders/raymarch.glsl | clamp(1.0 - 3.0 * occ, 0.0, 1.0)                  | clamp(1.0 - 1.5 * occ, 0.0, 1.0)                  | ambient occlusion half as strong
shaders/raymarch.glsl | 0.01 + 0.12 * float(i) / 4.0                      | 0.01 + 0.06 * float(i) / 4.0                      | occlusion samples half as far out
shaders/lighting.glsl | direct * (0.5 + 0.5 * ao)                         | direct                                            | occlusion no longer dims direct light
shaders/lighting.glsl | return s.k.x * s.albedo * ao                      | return s.k.x * ao                                 | ambient term loses the surface colour
shaders/march.frag    | weight *= s.kr;                                   | weight *= 0.5 * s.kr;                             | reflections half as bright
shaders/march.frag    | acc += weight * (1.0 - s.kr) * col;               | acc += weight * col;                              | mirrors keep their full own colour
shaders/raymarch.glsl | return len > 1e-20 ? n / len                      | return len > 1e-20 ? -n / len                     | normals point inwards
shaders/lighting.glsl | phong(s, p, n, rd, L.vec.xyz,                     | phong(s, p, n, rd, -L.vec.xyz,                    | directional lights shine from the wrong side
shaders/lighting.glsl | rd, toLight / max(dist, 1e-6),                    | rd, toLight,                                      | point-light direction not normalised
shaders/raymarch.glsl | return uEpsilon;                                  | return 20.0 * uEpsilon;                           | hit epsilon 20x: surfaces swell
shaders/march.frag    | / uResolution.y;                                  | / uResolution.x;                                  | camera rays squashed: wrong aspect
shaders/intersect.glsl | max(-b - s, 0.0)                                 | max(-b + s, 0.0)                                  | ray-sphere takes the far root: spheres hollow
shaders/intersect.glsl | vec3 near = (-b - ro) * inv                      | vec3 near = (b - ro) * inv                        | ray-box slab of the wrong sign: boxes flat
shaders/intersect.glsl | kNoSpan : (vec2(-b, -b) + vec2(-1.0, 1.0) * sqrt(h)) / a; | kNoSpan : (vec2(-b, -b) + vec2(1.0, -1.0) * sqrt(h)) / a; | ray-cylinder side roots swapped
shaders/intersect.glsl | float s = (r2 - r1) / height                     | float s = (r1 - r2) / height                      | ray-cone slant leaning the wrong way
shaders/intersect.glsl | ? before : after;                                | ? after : before;                                 | ray-cone takes the nappe beyond its apex
shaders/intersect.glsl | h = sqrt(h / dd);                                | h = sqrt(h);                                      | ray-ellipsoid span left unscaled
shaders/sdf.glsl      | vec2 k1 = vec2(r2, h)                             | vec2 k1 = vec2(r1, h)                             | cone's top as wide as its base
shaders/sdf.glsl      | float k0 = length(p / r), k1                      | float k0 = length(p / r.zxy), k1                  | ellipsoid's semi-axes permuted
shaders/sdf.glsl      | return abs(d + 0.5 * t) - 0.5 * t;                | return abs(d + t) - 0.5 * t;                      | shell walls moved inward by half
shaders/intersect.glsl | ballSpan(ro, rd, vec3(0.0, -h, 0.0), r)          | ballSpan(ro, rd, vec3(0.0, h, 0.0), r)            | capsule loses its lower cap
shaders/intersect.glsl | 0.5 * p + m + e, n, best);                       | 0.5 * p + m - e, n, best);                        | torus quartic factored with a wrong sign
shaders/intersect.glsl | w.cell += move * w.stepDir;                      | w.cell += 2 * move * w.stepDir;                   | plain-member grid walk misses every other cell
shaders/penumbra.glsl | / e) - b) / c, 1.0 / far);                        | / e) + b) / c, 1.0 / far);                        | plain balls' penumbrae taken at the wrong angle
shaders/penumbra.glsl | if (f1 < f2) {                                    | if (f1 > f2) {                                    | grid penumbra search climbs away from the shadow
shaders/raymarch.glsl | h < 2.0 * ph ? h * h / (2.0 * ph) : 0.0           | h * h / (2.0 * ph)                                | grid soft shadows black past an empty cell
shaders/outline.glsl  | kOutlinePixels = 2.0;                             | kOutlinePixels = 0.5;                             | editor's selection outline a quarter as wide
shaders/outline.glsl  | ? kOutlineColor : col;                            | ? col : col;                                      | editor's selection outline gone
shaders/post.frag     | lB < lMin || lB > lMax ? a : b                    | lB < lMin || lB > lMax ? b : a                    | FXAA keeps the wrong blend
shaders/checkerboard.frag | across < along ? h : along < across ? v    | across > along ? h : along > across ? v         | draft's fill blurs across edges
shaders/checkerboard.frag | uSize.x == 1 ? kNone                       | uSize.x == 0 ? kNone                            | draft's fill takes a pixel past the border into a one-pixel-wide picture
shaders/checkerboard.frag | 1) == 0 ? here : filled                    | 1) == 0 ? filled : here                         | draft's fill swaps shaded and filled-in pixels
src/scene/sdf.cpp      | vec2(r, 0.5f * height)                            | vec2(r, 0.25f * height)                           | mirror: cylinder of half its height
src/scene/sdf.cpp      | vec2(p.x, p.z)) - major                           | vec2(p.x, p.z)) - 0.9f * major                    | mirror: torus major radius 0.9x
src/scene/sdf.cpp      | glm::abs(p) - b;                                  | glm::abs(p) - 0.9f * b;                           | mirror: box 0.9x its size
src/scene/sdf.cpp      | p.y -= std::clamp(p.y, -h, h);                    | p.y -= std::clamp(p.y, -0.8f * h, 0.8f * h);      | mirror: capsule segment 0.8x
src/scene/sdf.cpp      | return sdObjectLocal(o, o.toLocal * (p - o.pos)); | return sdObjectLocal(o, (p - o.pos) * o.toLocal); | mirror: objects turned the other way
src/scene/sdf.cpp      | const vec2 k1(r2, h), k2(r2 - r1, 2.0f * h);      | const vec2 k1(r1, h), k2(r2 - r1, 2.0f * h);      | mirror: cone's top as wide as its base
src/scene/sdf.cpp      | const float k0 = glm::length(p / r), k1           | const float k0 = glm::length(p / vec3(r.z, r.x, r.y)), k1 | mirror: ellipsoid's semi-axes permuted
TABLE
)

RENDER_FILTER='-AsyncCompile.*'  # shader mutations: every gl_tests suite but AsyncCompile
MIRROR_FILTER='*Agreement*:VocabularyPicture.*'  # mirror mutations: CPU/GPU agreement
TEST_TIMEOUT=600                 # seconds per gl_tests run; a hang counts as caught

#-----------------------------------------------------------------------------
# [SECTION] Setup
#-----------------------------------------------------------------------------
cd "$(dirname "$0")/.."
root=$PWD
build=$(cd "${1:-build}" 2>/dev/null && pwd) || { echo "mutate-render: no build folder '${1:-build}'" >&2; exit 2; }
[[ -x $build/gl_tests ]] || { echo "mutate-render: $build/gl_tests is not built (cmake --build $build --target gl_tests)" >&2; exit 2; }
jobs=${JOBS:-2}
start=$SECONDS
scratch=$(mktemp -d "${TMPDIR:-/tmp}/mutate-render.XXXXXX")
trap 'rm -rf "$scratch"' EXIT

trim() { local s=$1; s=${s#"${s%%[![:space:]]*}"}; s=${s%"${s##*[![:space:]]}"}; printf '%s' "$s"; }

# Occurrences of the literal text $2 in file $1.
count() { PAT=$2 perl -0ne '$n = () = /\Q$ENV{PAT}\E/g; print $n + 0' "$1"; }

# Replaces the one occurrence of $2 in file $1 by $3.
mutate() { PAT=$2 REP=$3 perl -0pi -e 's/\Q$ENV{PAT}\E/$ENV{REP}/' "$1"; }

# Runs gl_tests ($1) with filter $2 and MARCHBOX_SHADERS=$3 (empty: unset). Sets `failed` to the
# first failing test's name, or a short reason when it failed without naming one; empty if all
# passed.
failed=""
run_tests() {
    local out rc
    if [[ -n $3 ]]; then
        out=$(MARCHBOX_SHADERS=$3 timeout "$TEST_TIMEOUT" "$1" --gtest_filter="$2" --gtest_brief=1 --gtest_fail_fast 2>&1)
    else
        out=$(env -u MARCHBOX_SHADERS timeout "$TEST_TIMEOUT" "$1" --gtest_filter="$2" --gtest_brief=1 --gtest_fail_fast 2>&1)
    fi
    rc=$?
    failed=$(grep -m1 '^\[  FAILED  \] [A-Za-z]' <<<"$out" | sed -E 's/^\[  FAILED  \] //; s/, where GetParam.*//; s/ \([0-9]+ ms\)$//')
    if [[ $rc -eq 124 ]]; then failed="(timed out after ${TEST_TIMEOUT} s)"
    elif [[ $rc -ne 0 && -z $failed ]]; then failed="(exit status $rc: $(tail -n1 <<<"$out"))"
    elif [[ $rc -eq 0 ]]; then failed=""
    fi
}

# The mirror: tracked files (as they are in the work tree) copied into BUILD/mutate-mirror/src.
# A file whose content changed is copied with a new mtime so make rebuilds it; others are left
# alone so the build stays incremental.
mirror=$build/mutate-mirror
sync_mirror() {
    local f
    mkdir -p "$mirror/src"
    while IFS= read -r -d '' f; do
        [[ -f $f ]] || continue
        if ! cmp -s "$f" "$mirror/src/$f"; then
            mkdir -p "$mirror/src/$(dirname "$f")"
            cp "$f" "$mirror/src/$f"
        fi
    done < <(git ls-files -z)
    # Files no longer tracked would still be globbed into the build: remove them.
    comm -13 <(git ls-files | sort) <(cd "$mirror/src" && find . -type f | sed 's|^\./||' | sort) |
        while IFS= read -r f; do rm -f "$mirror/src/$f"; done
}

build_mirror() {
    local type launcher=()
    if [[ ! -f $mirror/build/CMakeCache.txt ]]; then
        type=$(sed -n 's/^CMAKE_BUILD_TYPE:[A-Z]*=//p' "$build/CMakeCache.txt" 2>/dev/null)
        command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
        cmake -S "$mirror/src" -B "$mirror/build" -DCMAKE_BUILD_TYPE="${type:-RelWithDebInfo}" "${launcher[@]}" \
            >"$mirror/configure.log" 2>&1 || return 1
    fi
    CCACHE_BASEDIR=$mirror CCACHE_NOHASHDIR=1 cmake --build "$mirror/build" -j"$jobs" --target gl_tests \
        >"$mirror/build.log" 2>&1
}

#-----------------------------------------------------------------------------
# [SECTION] Check the table, then run with no mutation: every test must pass as it is
#-----------------------------------------------------------------------------
files=() pats=() reps=() descs=() errors=0
while IFS=$'\x1f' read -r f p r d; do
    [[ -z $(trim "$f") ]] && continue
    f=$(trim "$f") p=$(trim "$p") r=$(trim "$r") d=$(trim "$d")
    if [[ ! -f $f ]]; then
        echo "ERROR     $d: no file $f; update the table"
        errors=$((errors + 1))
        continue
    fi
    n=$(count "$f" "$p")
    if [[ $n != 1 ]]; then
        echo "ERROR     $d: '$p' occurs $n times in $f, not once; update the table"
        errors=$((errors + 1))
        continue
    fi
    files+=("$f") pats+=("$p") reps+=("$r") descs+=("$d")
done < <(sed 's/ | /\x1f/g' <<<"$MUTATIONS")

cp -r shaders "$scratch/clean"
run_tests "$build/gl_tests" "$RENDER_FILTER" "$scratch/clean"
if [[ -n $failed ]]; then
    echo "ERROR     the render tests fail with no mutation: $failed" >&2
    exit 2
fi

#-----------------------------------------------------------------------------
# [SECTION] Mutate
#-----------------------------------------------------------------------------
caught=0 survived=() mirrorState=""
for i in "${!files[@]}"; do
    f=${files[$i]} p=${pats[$i]} r=${reps[$i]} d=${descs[$i]}
    t0=$SECONDS
    if [[ $f == shaders/* ]]; then
        rm -rf "$scratch/mutant" && cp -r shaders "$scratch/mutant"
        mutate "$scratch/mutant/${f#shaders/}" "$p" "$r"
        run_tests "$build/gl_tests" "$RENDER_FILTER" "$scratch/mutant"
    else
        if [[ -z $mirrorState ]]; then  # once: the mirror as it is must build and agree
            sync_mirror
            mirrorState=ok
            if ! build_mirror; then
                mirrorState="the unmutated copy does not build; see $mirror/build.log"
            else
                run_tests "$mirror/build/gl_tests" "$MIRROR_FILTER" ""
                [[ -n $failed ]] && mirrorState="$MIRROR_FILTER fails with no mutation: $failed"
            fi
        fi
        if [[ $mirrorState != ok ]]; then
            echo "ERROR     $d: $mirrorState"
            errors=$((errors + 1))
            continue
        fi
        cp "$f" "$scratch/original"
        mutate "$mirror/src/$f" "$p" "$r"
        if build_mirror; then
            run_tests "$mirror/build/gl_tests" "$MIRROR_FILTER" ""
        else
            failed="(the mutant does not compile; see $mirror/build.log)"
        fi
        cp "$scratch/original" "$mirror/src/$f"  # a new mtime: the next build recompiles it
    fi
    if [[ -n $failed ]]; then
        caught=$((caught + 1))
        printf 'CAUGHT    %-50s %4ss  %s\n' "$d" $((SECONDS - t0)) "$failed"
    else
        survived+=("$d")
        printf 'SURVIVED  %-50s %4ss\n' "$d" $((SECONDS - t0))
    fi
done

#-----------------------------------------------------------------------------
# [SECTION] Score
#-----------------------------------------------------------------------------
total=${#files[@]}
echo "mutation score: $caught/$total caught$( ((errors)) && echo ", $errors error(s)")"
for s in "${survived[@]}"; do echo "  survived: $s"; done
echo "elapsed: $(( (SECONDS - start) / 60 ))m $(( (SECONDS - start) % 60 ))s"
((errors)) && exit 2
((${#survived[@]})) && exit 1
exit 0
