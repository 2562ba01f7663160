#!/usr/bin/env python3
"""export_test.py — `marchbox export`: mesh files in each format, an animated glb, errors, Ctrl-C.

Groups, each its own CTest test (cli.export_GROUP):
  formats   STL, OBJ + MTL and PLY of tests/cli/export_scene.txt, each read back: the STL's
            triangle count matches its header and size, and its mesh is closed and wound one
            way (each edge once in each direction); the PLY's header, sizes and the materials'
            colours; the OBJ's faces name vertices that exist and materials its MTL defines;
            --seconds moves the falling ball; piped, standard error stays empty
  gltf      a still and an animated .glb pass the Khronos glTF validator (npm's gltf-validator,
            installed into BUILD/gltf-validator on first use; where npm cannot fetch it, skipped)
  assimp    each format, and an animated .glb, read by another program's importers (Open Asset
            Import Library's `assimp info`, Debian's assimp-utils; where it is missing, skipped):
            exit 0, and the meshes, vertices and faces it counts are those the file says it holds
  animated  --frames A-B: one node per dynamic body, the static solids in one more, a camera,
            and every animation channel keyed at each of the B−A+1 frames, at t = k / fps;
            the ball's keys fall as `simulate --seconds` says
  errors    a bad extension, --voxel, --frames or path, an unreadable scene, a voxel too small
            for the memory: one line on standard error, exit 2 (usage) or 1 (input), nothing
            written and an existing file left as it was
  interrupt progress on a terminal; Ctrl-C mid-run ends it by the signal, writes nothing and
            leaves the old file whole
Usage: export_test.py MARCHBOX SOURCE_DIR BUILD_DIR GROUP
"""
import fcntl
import json
import os
import shutil
import signal
import struct
import subprocess
import sys
import tempfile
import time

from terminal import read_until, spawn_on_terminal, wait_for_exit

RUN_LIMIT_S = 120  # generous bounds, not timings: they only turn a hang into a failure
STOP_LIMIT_S = 10  # the run polls Ctrl-C every leaf of voxels: milliseconds, but the machine
                  # may be shared with builds
SKIP = 77
VALIDATOR = "gltf-validator@2.0.0-dev.3.10"
VOXEL = "0.04"  # coarse: a few thousand triangles, quick to read back in Python

failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        print("FAIL:", what, file=sys.stderr)
    return ok


def run(argv):
    return subprocess.run(argv, stdin=subprocess.DEVNULL, capture_output=True, timeout=RUN_LIMIT_S)


def export(mb, scene, out, *more):
    r = run([mb, "export", scene, "-o", out, *more])
    check(r.returncode == 0, f"export -o {out} {more}: exit {r.returncode}: {r.stderr[-300:]!r}")
    check(r.stderr == b"", f"export -o {out}: standard error, not a terminal, holds {r.stderr[:200]!r}")
    return r


def read(path):
    with open(path, "rb") as f:
        return f.read()


def stl_triangles(path):
    """The triangles of a binary STL, each three (x, y, z) tuples; checks count against size."""
    data = read(path)
    count = struct.unpack_from("<I", data, 80)[0]
    check(len(data) == 84 + 50 * count, f"{path}: {len(data)} bytes for {count} triangles")
    check(not data.startswith(b"solid"), f"{path}: a binary STL's header must not start 'solid'")
    tris = []
    for t in range(count):
        v = struct.unpack_from("<12f", data, 84 + 50 * t)
        tris.append((v[3:6], v[6:9], v[9:12]))
    return tris


def closed_and_one_way(tris):
    """Corners welded by their exact floats: each directed edge once, its reverse once."""
    edges = {}
    for tri in tris:
        for i in range(3):
            e = (tri[i], tri[(i + 1) % 3])
            edges[e] = edges.get(e, 0) + 1
    bad = [e for e, n in edges.items() if n != 1 or edges.get((e[1], e[0])) != 1]
    return not bad, len(bad)


def signed_volume(tris):
    return sum(a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
               + a[2] * (b[0] * c[1] - b[1] * c[0]) for a, b, c in tris) / 6


def ply(path):
    """(header lines, vertices as (x, y, z, r, g, b), faces as index triples) of a binary PLY."""
    data = read(path)
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode().splitlines()
    nv = int(next(l for l in header if l.startswith("element vertex")).split()[2])
    nf = int(next(l for l in header if l.startswith("element face")).split()[2])
    check(len(data) == end + 15 * nv + 13 * nf, f"{path}: {len(data)} bytes for {nv} vertices, {nf} faces")
    verts = [struct.unpack_from("<3f3B", data, end + 15 * i) for i in range(nv)]
    faces = []
    for i in range(nf):
        n, a, b, c = struct.unpack_from("<B3I", data, end + 15 * nv + 13 * i)
        check(n == 3, f"{path}: face {i} has {n} corners")
        faces.append((a, b, c))
    return header, verts, faces


def glb_json(path):
    data = read(path)
    magic, version, length = struct.unpack_from("<4sII", data, 0)
    check(magic == b"glTF" and version == 2 and length == len(data), f"{path}: GLB header {magic}, {version}, {length}")
    size, kind = struct.unpack_from("<I4s", data, 12)
    check(kind == b"JSON", f"{path}: first chunk {kind}")
    return json.loads(data[20:20 + size])


def formats(mb, src, build, scene, tmp):
    at = lambda name: os.path.join(tmp, name)  # noqa: E731
    export(mb, scene, at("a.stl"), "--voxel", VOXEL)
    tris = stl_triangles(at("a.stl"))
    check(len(tris) > 1000, f"STL: only {len(tris)} triangles")
    ok, bad = closed_and_one_way(tris)
    check(ok, f"STL: {bad} edges not shared by exactly two triangles in opposite directions")
    check(signed_volume(tris) > 0, "STL: the triangles wind inward")

    export(mb, scene, at("a.ply"), "--voxel", VOXEL)
    header, verts, faces = ply(at("a.ply"))
    check(header[:2] == ["ply", "format binary_little_endian 1.0"], f"PLY header {header[:2]}")
    for prop in ("property float x", "property uchar red", "property list uchar uint vertex_indices"):
        check(prop in header, f"PLY header lacks {prop!r}")
    check(len(faces) == len(tris), f"PLY has {len(faces)} faces, the STL {len(tris)}")
    check(all(max(f) < len(verts) for f in faces), "PLY: a face names a vertex that is not there")
    # The scene's two materials, 0.9,0.15,0.1 and 0.2,0.4,0.9, as bytes; nothing else.
    colours = {v[3:] for v in verts}
    check(colours == {(230, 38, 26), (51, 102, 230)}, f"PLY colours {sorted(colours)[:6]}")

    export(mb, scene, at("a.obj"), "--voxel", VOXEL)
    obj = read(at("a.obj")).decode().splitlines()
    mtl = read(at("a.mtl")).decode().splitlines()
    check("mtllib a.mtl" in obj, "the OBJ does not name a.mtl")
    nv = sum(1 for l in obj if l.startswith("v "))
    faces = [l.split()[1:] for l in obj if l.startswith("f ")]
    check(len(faces) == len(tris), f"OBJ has {len(faces)} faces, the STL {len(tris)}")
    check(all(len(f) == 3 and all(1 <= int(i) <= nv for i in f) for f in faces), "OBJ: a face names a missing vertex")
    defined = {l.split()[1] for l in mtl if l.startswith("newmtl ")}
    used = {l.split()[1] for l in obj if l.startswith("usemtl ")}
    check(defined == {"red", "blue"} and used == defined, f"MTL defines {defined}, the OBJ uses {used}")
    check(sorted(os.listdir(tmp)) == ["a.mtl", "a.obj", "a.ply", "a.stl"], f"left: {sorted(os.listdir(tmp))}")

    # Upper case is the same format; --seconds meshes the scene as it then stands: the ball
    # (radius 0.4, at y = 2) has fallen onto the box (top at y = 0.6), so nothing is left above 2.
    export(mb, scene, at("later.STL"), "--voxel", VOXEL, "--seconds", "1.5")
    top = lambda ts: max(p[1] for t in ts for p in t)  # noqa: E731
    check(top(tris) > 2.3 and top(stl_triangles(at("later.STL"))) < 2.0,
          f"tops before and after 1.5 s: {top(tris):.2f}, {top(stl_triangles(at('later.STL'))):.2f}")


def ensure_validator(build):
    """NODE_PATH for gltf-validator, installed into BUILD/gltf-validator once; None if npm cannot."""
    folder = os.path.join(build, "gltf-validator")
    modules = os.path.join(folder, "node_modules")
    if not shutil.which("node"):
        print("node is not installed: the glTF validator cannot run")
        return None
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, ".lock"), "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)  # two tests at once install it once
        if not os.path.isdir(os.path.join(modules, "gltf-validator")):
            if not shutil.which("npm"):
                print("npm is not installed: the glTF validator cannot be fetched")
                return None
            try:
                # Bounded well inside CTest's limit, so an unreachable registry skips, not fails.
                r = subprocess.run(["npm", "install", "--prefix", folder, "--no-audit", "--no-fund",
                                    "--no-save", "--fetch-retries", "1", "--fetch-timeout", "30000",
                                    VALIDATOR], stdin=subprocess.DEVNULL,
                                   capture_output=True, timeout=150)
                ok = r.returncode == 0
            except subprocess.TimeoutExpired:
                ok = False
            if not ok or not os.path.isdir(os.path.join(modules, "gltf-validator")):
                print(f"npm could not install {VALIDATOR}: the glTF validator is skipped")
                return None
    return modules


def validate(src, modules, *files):
    r = subprocess.run(["node", os.path.join(src, "tests", "cli", "validate_gltf.js"), *files],
                       stdin=subprocess.DEVNULL, capture_output=True, timeout=RUN_LIMIT_S,
                       env=dict(os.environ, NODE_PATH=modules))
    print(r.stdout.decode(errors="replace"), end="")
    check(r.returncode == 0, f"the glTF validator finds errors: {r.stdout[-600:]!r} {r.stderr[-300:]!r}")


def gltf(mb, src, build, scene, tmp):
    modules = ensure_validator(build)
    if not modules:
        return SKIP
    still, moving = os.path.join(tmp, "still.glb"), os.path.join(tmp, "moving.glb")
    export(mb, scene, still, "--voxel", VOXEL)
    export(mb, scene, moving, "--voxel", VOXEL, "--frames", "0-5")
    validate(src, modules, still, moving)
    # A file that breaks the rules must fail, or the check above proves nothing: an index past
    # the end of its accessor.
    broken = os.path.join(tmp, "broken.glb")
    doc = glb_json(still)
    data = read(still)
    size = struct.unpack_from("<I", data, 12)[0]
    doc["accessors"][0]["count"] += 1000000
    text = json.dumps(doc).encode()
    text += b" " * (-len(text) % 4)
    rest = data[20 + size:]
    with open(broken, "wb") as f:
        f.write(struct.pack("<4sII", b"glTF", 2, 20 + len(text) + len(rest)))
        f.write(struct.pack("<I4s", len(text), b"JSON") + text + rest)
    r = subprocess.run(["node", os.path.join(src, "tests", "cli", "validate_gltf.js"), broken],
                       stdin=subprocess.DEVNULL, capture_output=True, timeout=RUN_LIMIT_S,
                       env=dict(os.environ, NODE_PATH=modules))
    check(r.returncode == 1, f"the validator passes a broken file: {r.stdout[-300:]!r}")


def assimp_counts(path):
    """`assimp info --raw PATH` (no joining or splitting of vertices): its summary as a dict
    ("Meshes", "Vertices", "Faces", ...) of whole numbers; None, after a failure, if it fails."""
    r = subprocess.run(["assimp", "info", path, "--raw"], stdin=subprocess.DEVNULL,
                       capture_output=True, timeout=RUN_LIMIT_S)
    out = r.stdout.decode(errors="replace")
    if not check(r.returncode == 0, f"assimp info {os.path.basename(path)}: exit {r.returncode}: "
                 f"{(out + r.stderr.decode(errors='replace'))[-300:]!r}"):
        return None
    counts = {}
    for line in out.splitlines():
        key, _, value = line.partition(":")
        if value.strip().isdigit():
            counts[key.strip()] = int(value)
    return counts


def assimp_agrees(path, want):
    """Checks that assimp counts what WANT says the file holds, and prints its counts."""
    got = assimp_counts(path)
    if got is not None:
        seen = {k: got.get(k) for k in want}
        check(seen == want, f"assimp reads {os.path.basename(path)} as {seen}, the file holds {want}")
        print(f"assimp {os.path.basename(path)}: {seen}")


def glb_counts(path):
    """What a .glb holds by its own JSON: primitives, vertices, triangles, animations, ..."""
    doc = glb_json(path)
    prims = [p for m in doc["meshes"] for p in m["primitives"]]
    count = lambda name: doc["accessors"][name]["count"]  # noqa: E731
    anims = doc.get("animations", [])
    return {"Meshes": len(prims),
            "Vertices": sum(count(p["attributes"]["POSITION"]) for p in prims),
            "Faces": sum(count(p["indices"]) // 3 for p in prims),
            "Cameras": len(doc.get("cameras", [])),
            "Lights": len(doc.get("extensions", {}).get("KHR_lights_punctual", {}).get("lights", [])),
            "Animations": len(anims),
            "Animation Channels": len({c["target"]["node"] for a in anims for c in a["channels"]})}


def assimp(mb, src, build, scene, tmp):
    if not shutil.which("assimp"):
        print("the assimp program is not installed (Debian: apt-get install assimp-utils): skipped")
        return SKIP
    at = lambda name: os.path.join(tmp, name)  # noqa: E731
    for ext in ("stl", "obj", "ply", "glb"):
        export(mb, scene, at("a." + ext), "--voxel", VOXEL)
    export(mb, scene, at("run.glb"), "--voxel", VOXEL, "--frames", "0-5")
    # A raw import keeps each file's vertices as they are: STL has three per triangle, and
    # assimp's OBJ importer gives every face's corners vertices of their own, so both count 3F.
    triangles = struct.unpack_from("<I", read(at("a.stl")), 80)[0]
    assimp_agrees(at("a.stl"), {"Meshes": 1, "Vertices": 3 * triangles, "Faces": triangles})
    obj = read(at("a.obj")).decode().splitlines()
    faces = sum(1 for l in obj if l.startswith("f "))
    used = len({l.split()[1] for l in obj if l.startswith("usemtl ")})
    assimp_agrees(at("a.obj"), {"Meshes": used, "Vertices": 3 * faces, "Faces": faces})
    # The PLY's counts from its header alone, so that a short file reaches assimp. assimp finds
    # a PLY cut among its vertices ("File corrupted") but not one cut among its faces: it
    # counts the header's faces. `formats` checks the PLY's size against its header.
    header = read(at("a.ply")).split(b"end_header\n")[0].decode().splitlines()
    nv, nf = (int(next(l for l in header if l.startswith("element " + e)).split()[2])
              for e in ("vertex", "face"))
    assimp_agrees(at("a.ply"), {"Meshes": 1, "Vertices": nv, "Faces": nf})
    for name in ("a.glb", "run.glb"):
        assimp_agrees(at(name), glb_counts(at(name)))
    # The counts above come from each file itself; tie them to one another and to the scene.
    check(triangles == nf == faces == glb_counts(at("a.glb"))["Faces"] > 1000,
          f"triangles: STL {triangles}, PLY {nf}, OBJ {faces}, glb {glb_counts(at('a.glb'))['Faces']}")
    check(glb_counts(at("run.glb"))["Animation Channels"] == 3, "the animated glb moves not 3 nodes")


def animated(mb, src, build, scene, tmp):
    out = os.path.join(tmp, "run.glb")
    first, last, fps = 3, 15, 24
    export(mb, scene, out, "--voxel", VOXEL, "--frames", f"{first}-{last}", "--fps", str(fps))
    doc = glb_json(out)
    nodes = doc["nodes"]
    names = [n.get("name") for n in nodes]
    check(names[:3] == ["static solids", "sphere 1", "cup"], f"nodes {names}")
    check(all("mesh" in nodes[i] for i in range(3)), "a part without its mesh")
    check(sum(1 for n in nodes if "camera" in n) == 1, "not one camera node")
    check(sum(1 for n in nodes if "KHR_lights_punctual" in n.get("extensions", {})) == 2, "not two light nodes")
    anims = doc.get("animations", [])
    check(len(anims) == 1, f"{len(anims)} animations")
    channels = anims[0]["channels"] if anims else []
    camera = next(i for i, n in enumerate(nodes) if "camera" in n)
    targets = sorted((c["target"]["node"], c["target"]["path"]) for c in channels)
    want = sorted((n, p) for n in (1, 2, camera) for p in ("translation", "rotation"))
    check(targets == want, f"channels {targets}, want {want}")
    keys = last - first + 1
    blob = read(out)
    json_size = struct.unpack_from("<I", blob, 12)[0]
    bin_at = 20 + json_size + 8

    def floats(accessor):
        a = doc["accessors"][accessor]
        view = doc["bufferViews"][a["bufferView"]]
        width = {"SCALAR": 1, "VEC3": 3, "VEC4": 4}[a["type"]]
        start = bin_at + view.get("byteOffset", 0) + a.get("byteOffset", 0)
        return struct.unpack_from(f"<{a['count'] * width}f", blob, start)

    for c in channels:
        s = anims[0]["samplers"][c["sampler"]]
        check(doc["accessors"][s["input"]]["count"] == keys and doc["accessors"][s["output"]]["count"] == keys,
              f"channel {c['target']} has {doc['accessors'][s['input']]['count']} keys, want {keys}")
    times = floats(anims[0]["samplers"][0]["input"])
    check(all(abs(t - k / fps) < 1e-6 for t, k in zip(times, range(first, last + 1))), f"key times {times}")
    # The ball's last key is where `simulate --seconds last/fps` puts it.
    move = next(c for c in channels if c["target"] == {"node": 1, "path": "translation"})
    ball = floats(anims[0]["samplers"][move["sampler"]]["output"])
    r = run([mb, "simulate", scene, "--seconds", repr(last / fps)])
    line = next(l for l in r.stdout.decode().splitlines() if l.startswith("object type:sphere"))
    pos = [float(x) for x in next(f for f in line.split() if f.startswith("pos:"))[4:].split(",")]
    check(all(abs(a - b) < 1e-5 for a, b in zip(ball[-3:], pos)), f"ball at {ball[-3:]}, simulate says {pos}")
    check(ball[1] > ball[-2] + 0.1, f"the ball does not fall: y {ball[1]:.3f} then {ball[-2]:.3f}")


def blender(mb, src, build, scene, tmp):
    """Debian's Blender imports an animated glb headlessly: the three parts as meshes, the
    camera, the two lights, and an action for each of the three nodes that move. Blender is no dependency of
    Marchbox (67 packages, 77 MB to download, 16 s to install here, and python3-numpy for its
    glTF importer): without it this skips."""
    if not shutil.which("blender"):
        print("Blender is not installed (Debian: apt-get install blender): skipped")
        return SKIP
    out = os.path.join(tmp, "run.glb")
    export(mb, scene, out, "--voxel", VOXEL, "--frames", "0-5")
    # What the import adds to Blender's start-up scene (a cube, a camera, a light). Debian's
    # Blender 3.4 importer still names numpy's `np.bool`, which Debian's numpy 1.24 dropped: the
    # alias is put back first, or every import fails in Blender's own code.
    expr = ("import numpy; numpy.bool = bool; "
            "import bpy, sys; before = set(bpy.data.objects); "
            "bpy.ops.import_scene.gltf(filepath=sys.argv[-1]); "
            "new = [o.type for o in bpy.data.objects if o not in before]; "
            "print('IMPORTED', new.count('MESH'), new.count('CAMERA'), new.count('LIGHT'), "
            "len(bpy.data.actions))")
    # Debian's Blender embeds Debian's Python, which finds its library through the first python3
    # on PATH: a pyenv or venv one ahead of it hides Debian's numpy, which the importer needs.
    system = dict(os.environ, PATH="/usr/bin:/bin")
    r = subprocess.run([shutil.which("blender"), "-b", "--factory-startup", "--python-expr", expr,
                        "--", out], capture_output=True, timeout=240, env=system)
    said = [l for l in r.stdout.decode(errors="replace").splitlines() if l.startswith("IMPORTED")]
    check(r.returncode == 0 and said, f"Blender did not import {out}: {r.stderr.decode()[-300:]}")
    if said:
        meshes, cameras, lights, actions = map(int, said[0].split()[1:])
        check((meshes, cameras, lights, actions) == (3, 1, 2, 3),
              f"Blender made {meshes} meshes, {cameras} cameras, {lights} lights, {actions} actions")


def expect(status, argv, says, tmp):
    """argv exits with `status` and one line on standard error containing `says`; tmp unchanged."""
    def snapshot():
        return {n: read(p) if os.path.isfile(p) else sorted(os.listdir(p))
                for n in os.listdir(tmp) for p in [os.path.join(tmp, n)]}
    before = snapshot()
    r = run(argv)
    err = r.stderr.decode(errors="replace")
    check(r.returncode == status and err.count("\n") == 1 and err.endswith("\n") and says in err,
          f"{argv[1:]} -> exit {r.returncode} (want {status}), stderr {err!r} (want one line with {says!r})")
    after = snapshot()
    check(after == before, f"{argv[1:]} changed the folder: {sorted(after)} (was {sorted(before)})")


def errors(mb, src, build, scene, tmp):
    at = lambda name: os.path.join(tmp, name)  # noqa: E731
    old = at("old.stl")
    with open(old, "wb") as f:
        f.write(b"the bytes of an older export\n")
    ex = lambda out, *more: [mb, "export", scene, "-o", out, *more]  # noqa: E731
    expect(2, ex(at("a.step")), "cannot tell the format of", tmp)
    expect(2, ex(at("noextension")), "-o takes a .stl, .obj, .ply or .glb file", tmp)
    expect(2, [mb, "export", scene], "export needs -o", tmp)
    expect(2, [mb, "export", "-o", old], "usage: marchbox export", tmp)
    for bad in ("0", "-1", "abc", "nan", "inf", "1e999"):
        expect(2, ex(old, "--voxel", bad), "bad value", tmp)
    expect(2, ex(old, "--frames", "0-10"), "export --frames writes an animated .glb", tmp)
    expect(2, ex(at("a.glb"), "--frames", "10"), "takes a range A-B", tmp)
    expect(2, ex(at("a.glb"), "--frames", "0-10", "--seconds", "1"), "--seconds does not go", tmp)
    expect(2, ex(old, "--fps", "24"), "--fps goes with --frames", tmp)
    expect(2, ex(at("a.glb"), "--frames", "0-200000", "--fps", "1"), "past 3600 s", tmp)
    expect(1, [mb, "export", at("missing.txt"), "-o", old], "missing.txt", tmp)
    expect(1, ex(at("missing/a.stl")), f"cannot write '{at('missing/a.stl')}'", tmp)
    os.mkdir(at("folder.stl"))
    expect(1, ex(at("folder.stl")), "is a directory", tmp)
    # A millionth of a millimetre: a grid of ~10²⁰ voxels; refused at once, the old file kept.
    started = time.monotonic()
    expect(1, ex(old, "--voxel", "1e-9"), "too small for this scene", tmp)
    check(time.monotonic() - started < 30, f"the refusal took {time.monotonic() - started:.1f} s")
    empty = at("empty.txt")
    with open(empty, "w") as f:
        f.write("scene version:3\nlight pos:0,5,0\n")
    expect(1, [mb, "export", empty, "-o", old], "no solids to export", tmp)
    expect(1, ex(old, "--voxel", "100"), "thinner than a voxel", tmp)


def interrupt(mb, src, build, scene, tmp):
    out = os.path.join(tmp, "a.stl")
    pid, master = spawn_on_terminal([mb, "export", scene, "-o", out, "--voxel", "0.05"])
    seen = read_until(master, b"meshing 100%", RUN_LIMIT_S)
    status = wait_for_exit(pid, RUN_LIMIT_S)
    os.close(master)
    check(status == 0, f"export on a terminal: wait status {status}")
    check(b"meshing " in seen and b"100%" in seen, f"no progress on a terminal: {seen[-200:]!r}")
    before = b"an older export, to be left whole\n"
    with open(out, "wb") as f:
        f.write(before)
    # A voxel fine enough for seconds of work (8 s on two cores, 0.7 GB): Ctrl-C lands in it.
    pid, master = spawn_on_terminal([mb, "export", scene, "-o", out, "--voxel", "0.003"])
    check(b"meshing" in read_until(master, b"meshing", RUN_LIMIT_S), "no progress before Ctrl-C")
    started = time.monotonic()
    os.write(master, b"\x03")  # Ctrl-C: the terminal sends SIGINT to the run
    status = wait_for_exit(pid, STOP_LIMIT_S)
    os.close(master)
    check(status is not None and os.WIFSIGNALED(status) and os.WTERMSIG(status) == signal.SIGINT,
          f"after Ctrl-C: wait status {status}, {time.monotonic() - started:.1f} s")
    check(read(out) == before, "Ctrl-C changed the old file")
    check(os.listdir(tmp) == ["a.stl"], f"Ctrl-C left {os.listdir(tmp)}")


def main():
    mb, src, build, group = sys.argv[1:5]
    scene = os.path.join(src, "tests", "cli", "export_scene.txt")
    with tempfile.TemporaryDirectory() as tmp:
        status = globals()[group](mb, src, build, scene, tmp)
    if failures:
        print(f"{len(failures)} failure(s) in group {group}", file=sys.stderr)
        return 1
    if status == SKIP:
        return SKIP
    print(f"export {group}: all cases passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
