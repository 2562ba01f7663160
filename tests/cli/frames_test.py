#!/usr/bin/env python3
"""frames_test.py — `marchbox render --frames A-B`: frame sequences and video.

Groups, each its own CTest test (cli.frames_GROUP), each a few seconds at 64x36:
  sequence  frames equal `render --seconds k/fps` byte for byte; at a key's time the view is
            the key's; --skip-existing; no output on standard error when it is not a terminal,
            a progress line when it is
  errors    bad patterns, ranges and outputs, and writes that fail midway: one line on
            standard error and the exit status, no partial or temporary file
  video     an MP4 that ffprobe reads as H.264 with the frames and rate asked for, its first
            frame the right way up; without ffmpeg on PATH, one line saying how to install it
  parallel  four ranges rendered at once by GNU parallel equal one process's frames
  interrupt Ctrl-C (SIGINT) mid-run leaves only whole frames, and no video or temporary file

A group whose program (ffmpeg, parallel) is missing exits 77, which CTest reports as skipped.
Usage: frames_test.py MARCHBOX SOURCE_DIR GROUP
"""
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time

from terminal import read_until, spawn_on_terminal, wait_for_exit

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "e2e"))
from png import read_png  # noqa: E402

# Generous bounds, not timings: they only turn a hang into a failure.
RUN_LIMIT_S = 120
STOP_LIMIT_S = 5
SIZE = "64x36"
SKIP = 77

failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        print("FAIL:", what, file=sys.stderr)
    return ok


def run(argv, env=None):
    return subprocess.run(argv, stdin=subprocess.DEVNULL, capture_output=True, env=env,
                          timeout=RUN_LIMIT_S)


def render_frames(mb, scene, out, frames, *more):
    r = run([mb, "render", scene, "-o", out, "--frames", frames, "--size", SIZE, *more])
    check(r.returncode == 0, f"--frames {frames} -o {out}: exit {r.returncode}: {r.stderr[-300:]!r}")
    check(r.stderr == b"", f"--frames {frames}: standard error, not a terminal, holds {r.stderr[:200]!r}")
    return r


def read(path):
    with open(path, "rb") as f:
        return f.read()


def sequence(mb, scene, tmp):
    """Frames 0-9 at 30 fps against single renders at t = k/30, and --skip-existing."""
    pattern = os.path.join(tmp, "f_%03d.png")
    render_frames(mb, scene, pattern, "0-9", "--fps", "30")
    names = sorted(os.listdir(tmp))
    check(names == [f"f_{k:03d}.png" for k in range(10)], f"frames written: {names}")
    singles = {}
    for k in (0, 1, 5, 9):
        single = os.path.join(tmp, f"single_{k}.png")
        # repr: the shortest decimal that reads back as the double k / 30
        r = run([mb, "render", scene, "-o", single, "--size", SIZE, "--seconds", repr(k / 30)])
        check(r.returncode == 0, f"render --seconds {k}/30: exit {r.returncode}")
        singles[k] = read(single)
        check(read(pattern % k) == singles[k], f"frame {k} differs from render --seconds {k}/30")
    # The test means something only if the scene moves: first and last frames differ.
    check(singles[0] != singles[9], "frames 0 and 9 are the same picture")
    # --skip-existing renders only the missing frame 3, and leaves frame 4's file alone, yet
    # simulates through both: frame 3 comes back as it was.
    frame3 = read(pattern % 3)
    os.remove(pattern % 3)
    with open(pattern % 4, "wb") as f:
        f.write(b"left alone")
    render_frames(mb, scene, pattern, "0-9", "--skip-existing")
    check(os.path.exists(pattern % 3) and read(pattern % 3) == frame3,
          "--skip-existing did not render the missing frame 3 as it was")
    check(read(pattern % 4) == b"left alone", "--skip-existing rendered an existing frame")
    check(read(pattern % 5) == singles[5], "--skip-existing changed frame 5")
    progress_on_a_terminal(mb, scene, tmp)
    follows_the_keys(mb, scene, tmp)


def follows_the_keys(mb, scene, tmp):
    """At a key's time the view is that key's: the scene with its camera record set to the key
    and no keyframes renders the same bytes. Off the key it differs."""
    text = read(scene).decode()
    key = "keyframe t:0.25 "
    line = next(l for l in text.splitlines() if l.startswith(key))
    still = os.path.join(tmp, "still.txt")
    with open(still, "w") as f:
        f.write("".join(("camera " + line[len(key):] if l.startswith("camera ") else l) + "\n"
                        for l in text.splitlines() if not l.startswith("keyframe ")))
    views = {}
    for name, path, t in (("key", scene, "0.25"), ("still", still, "0.25"), ("off", scene, "0.2")):
        out = os.path.join(tmp, f"view_{name}.png")
        r = run([mb, "render", path, "-o", out, "--size", SIZE, "--seconds", t])
        check(r.returncode == 0, f"render {path} --seconds {t}: exit {r.returncode}")
        views[name] = read(out)
    check(views["key"] == views["still"], "at t = 0.25 the view is not the 0.25 keyframe's")
    check(views["key"] != views["off"], "the view at t = 0.2 is the one at 0.25")


def progress_on_a_terminal(mb, scene, tmp):
    out = os.path.join(tmp, "tty_%d.png")
    pid, master = spawn_on_terminal([mb, "render", scene, "-o", out, "--frames", "0-2", "--size", SIZE])
    seen = read_until(master, b"3 of 3", RUN_LIMIT_S)
    status = wait_for_exit(pid, RUN_LIMIT_S)
    os.close(master)
    check(status == 0, f"--frames on a terminal: wait status {status}")
    check(b"frame 2 (3 of 3)" in seen and b"frames/s" in seen, f"no progress line: {seen[-200:]!r}")


def expect(status, argv, says, env=None, tmp=None):
    """argv exits with `status`, one line on standard error that contains `says`, and writes
    nothing into tmp."""
    before = sorted(os.listdir(tmp)) if tmp else None
    r = run(argv, env)
    err = r.stderr.decode(errors="replace")
    ok = r.returncode == status and err.count("\n") == 1 and err.endswith("\n") and says in err
    check(ok, f"{argv[1:]} -> exit {r.returncode} (want {status}), stderr {err!r} (want one line with {says!r})")
    if tmp:
        check(sorted(os.listdir(tmp)) == before, f"{argv[1:]} wrote {sorted(os.listdir(tmp))}")


def errors(mb, scene, tmp):
    def frames(out, rng="0-2", *more):
        return [mb, "render", scene, "-o", out, "--frames", rng, "--size", SIZE, *more]
    at = lambda name: os.path.join(tmp, name)  # noqa: E731
    expect(2, frames(at("f.png")), "needs one frame-number field", tmp=tmp)
    expect(2, frames(at("f_%d_%d.png")), "two frame-number fields", tmp=tmp)
    expect(2, frames(at("f_%s.png")), "not %d, %05d or %%", tmp=tmp)
    expect(2, frames(at("f_%5d.png")), "not %d, %05d or %%", tmp=tmp)
    expect(2, frames(at("f_%05d.jpg")), "PATTERN must end in .png", tmp=tmp)  # PNG bytes in .jpg
    expect(2, frames(at("f_%05d.png"), "5-3"), "the last frame comes before the first", tmp=tmp)
    expect(2, frames(at("f_%05d.png"), "5"), "render --frames takes a range A-B", tmp=tmp)
    expect(2, frames(at("f_%05d.png"), "0-2", "--fps", "0"), "--fps", tmp=tmp)
    expect(2, frames(at("f_%05d.png"), "0-2", "--seconds", "1"), "--seconds does not go", tmp=tmp)
    expect(2, [mb, "render", scene, "-o", at("x.png"), "--fps", "24"], "go with --frames A-B", tmp=tmp)
    expect(2, [mb, "bench", scene, "--frames", "0-3"], "bench --frames takes a count N", tmp=tmp)
    # Outputs that cannot be written, refused before the work. (As root no folder is
    # read-only, so: a folder that does not exist, and a file where a folder belongs.)
    expect(1, frames(at("missing/f_%05d.png")), f"cannot write '{at('missing/f_00000.png')}'", tmp=tmp)
    with open(at("file"), "w") as f:
        f.write("a file, not a folder\n")
    expect(1, frames(at("file/f_%05d.png")), "Not a directory", tmp=tmp)
    if shutil.which("ffmpeg"):
        expect(1, frames(at("missing/clip.mp4")), f"cannot write '{at('missing/clip.mp4')}'", tmp=tmp)
        # .MP4 is a video too, not a pattern without a frame-number field.
        expect(1, frames(at("missing/clip.MP4")), f"cannot write '{at('missing/clip.MP4')}'", tmp=tmp)
    fails_midway(mb, scene, tmp)


def fails_midway(mb, scene, tmp):
    """A write that fails after frames have gone out: one line, exit 1, the frames before it
    whole, and no temporary file. For PNGs a folder holds frame 5's name (a full disk fails
    the same way, one frame in); for a video ffmpeg is killed, as when it fails."""
    folder = os.path.join(tmp, "out")

    def png_fails(p):  # the folder is there before the run starts
        return "f_00005.png': is a directory", [f"f_{k:05d}.png" for k in range(5)]

    def ffmpeg_fails(p):
        children = f"/proc/{p.pid}/task/{p.pid}/children"
        while p.poll() is None and not read(children).split():
            time.sleep(0.02)
        time.sleep(0.5)  # some frames on their way
        for child in read(children).split():
            os.kill(int(child), signal.SIGKILL)
        return "ffmpeg could not write", []

    cases = [("f_%05d.png", png_fails)] + ([("clip.mp4", ffmpeg_fails)] if shutil.which("ffmpeg") else [])
    for out, fail in cases:
        os.mkdir(folder)
        os.mkdir(os.path.join(folder, "f_00005.png"))
        p = subprocess.Popen([mb, "render", scene, "-o", os.path.join(folder, out), "--frames", "0-100000",
                              "--size", SIZE], stdin=subprocess.DEVNULL, stderr=subprocess.PIPE)
        says, want = fail(p)
        try:
            err = p.communicate(timeout=RUN_LIMIT_S)[1].decode(errors="replace")
        except subprocess.TimeoutExpired:
            p.kill()
            err = p.communicate()[1].decode(errors="replace")
        check(p.returncode == 1 and err.count("\n") == 1 and says in err,
              f"-o {out}, failing midway: exit {p.returncode}, {err!r}")
        os.rmdir(os.path.join(folder, "f_00005.png"))
        left = sorted(os.listdir(folder))
        check(left == want, f"-o {out}, failing midway, left {left}, want {want}")
        shutil.rmtree(folder)


def probe(path):
    r = run(["ffprobe", "-v", "error", "-select_streams", "v:0", "-count_frames", "-show_entries",
             "stream=codec_name,width,height,r_frame_rate,nb_read_frames", "-of", "default=nw=1", path])
    return dict(line.split("=", 1) for line in r.stdout.decode().split())


def rgb(path):
    """The first picture of an image or video file as raw RGB bytes, decoded by ffmpeg."""
    r = run(["ffmpeg", "-v", "error", "-i", path, "-frames:v", "1", "-f", "rawvideo", "-pix_fmt", "rgb24", "-"])
    return r.stdout


def mean_abs(a, b):
    return sum(abs(x - y) for x, y in zip(a, b)) / max(1, len(a))


def flipped(raw, width, height):
    row = width * 3
    return b"".join(raw[y * row:(y + 1) * row] for y in reversed(range(height)))


def video(mb, scene, tmp):
    if not shutil.which("ffmpeg") or not shutil.which("ffprobe"):
        print("ffmpeg is not installed (apt-get install ffmpeg): video group skipped")
        return SKIP
    clip = os.path.join(tmp, "clip.mp4")
    render_frames(mb, scene, clip, "0-11", "--fps", "24")
    check(sorted(os.listdir(tmp)) == ["clip.mp4"], f"beside the video: {sorted(os.listdir(tmp))}")
    info = probe(clip)
    want = {"codec_name": "h264", "width": "64", "height": "36", "r_frame_rate": "24/1", "nb_read_frames": "12"}
    check(info == want, f"ffprobe: {info}, want {want}")
    # Row 0 is the top: the video's first frame is near the PNG of t = 0 (H.264 at crf 18 with
    # half-resolution colour, at 64x36: a mean of 4.4 levels) and far from it upside down (sky
    # over floor: 70 levels).
    still = os.path.join(tmp, "still.png")
    run([mb, "render", scene, "-o", still, "--size", SIZE])
    picture, decoded = rgb(still), rgb(clip)
    near, upside_down = mean_abs(decoded, picture), mean_abs(decoded, flipped(picture, 64, 36))
    check(len(decoded) == 64 * 36 * 3 and near < 8 and upside_down > 4 * near + 8,
          f"first frame vs PNG: mean {near:.2f}, upside down {upside_down:.2f}")
    os.remove(still)
    # No ffmpeg: one line saying how to install it, before any work, and nothing written.
    os.remove(clip)
    no_ffmpeg = dict(os.environ, PATH="/nonexistent")
    expect(1, [mb, "render", scene, "-o", clip, "--frames", "0-2", "--size", SIZE],
           "apt-get install ffmpeg", env=no_ffmpeg, tmp=tmp)
    expect(2, [mb, "render", scene, "-o", clip, "--frames", "0-2", "--size", "63x36"],
           "even width and height", tmp=tmp)


def parallel(mb, scene, tmp):
    if not shutil.which("parallel"):
        print("GNU parallel is not installed (apt-get install parallel): parallel group skipped")
        return SKIP
    one, four = os.path.join(tmp, "one"), os.path.join(tmp, "four")
    os.mkdir(one)
    os.mkdir(four)
    render_frames(mb, scene, os.path.join(one, "f_%03d.png"), "0-11")
    r = subprocess.run(["parallel", "--will-cite", "--halt", "now,fail=1", mb, "render", scene, "-o",
                        os.path.join(four, "f_%03d.png"), "--size", SIZE, "--frames", "{}",
                        ":::", "0-2", "3-5", "6-8", "9-11"],
                       stdin=subprocess.DEVNULL, capture_output=True, timeout=RUN_LIMIT_S)
    check(r.returncode == 0, f"parallel: exit {r.returncode}: {r.stderr[-300:]!r}")
    names = sorted(os.listdir(one))
    check(len(names) == 12 and names == sorted(os.listdir(four)), f"frames: {names} and {sorted(os.listdir(four))}")
    for name in names:
        check(read(os.path.join(one, name)) == read(os.path.join(four, name)), f"{name} differs between one process and four")


def interrupt(mb, scene, tmp):
    """SIGINT once a few frames are written: the run ends within seconds, by the signal, and
    leaves whole PNGs and nothing else; a video run leaves nothing at all."""
    pattern = os.path.join(tmp, "f_%05d.png")
    # Frames for an hour of play: far more than get written before the signal.
    argv = [mb, "render", scene, "-o", pattern, "--frames", "0-100000", "--size", SIZE]
    stop_midway(argv, lambda: len([n for n in os.listdir(tmp) if n.endswith(".png")]) >= 3)
    names = sorted(os.listdir(tmp))
    check(names and all(n.startswith("f_") and n.endswith(".png") for n in names), f"left: {names}")
    for name in names:
        data = read(os.path.join(tmp, name))
        try:
            image = read_png(os.path.join(tmp, name))
            whole = data.endswith(b"IEND\xaeB`\x82") and (image.width, image.height) == (64, 36)
        except Exception as e:  # noqa: BLE001 - any decoding error is a partial file
            whole = False
            print(name, e, file=sys.stderr)
        check(whole, f"{name} is not a whole 64x36 PNG")
    if not shutil.which("ffmpeg"):
        print("ffmpeg is not installed: the video half skipped")
        return
    folder = os.path.join(tmp, "video")
    os.mkdir(folder)
    argv = [mb, "render", scene, "-o", os.path.join(folder, "clip.mp4"), "--frames", "0-100000", "--size", SIZE]
    started = time.monotonic()
    stop_midway(argv, lambda: time.monotonic() - started > 2)
    check(os.listdir(folder) == [], f"an interrupted video left {os.listdir(folder)}")


def stop_midway(argv, ready):
    p = subprocess.Popen(argv, stdin=subprocess.DEVNULL, stderr=subprocess.PIPE)
    deadline = time.monotonic() + RUN_LIMIT_S
    while not ready() and p.poll() is None and time.monotonic() < deadline:
        time.sleep(0.02)
    check(p.poll() is None, f"{argv[1:4]} ended before the signal: {p.returncode}")
    p.send_signal(signal.SIGINT)
    try:
        p.wait(STOP_LIMIT_S)
    except subprocess.TimeoutExpired:
        p.kill()
        p.wait()
        check(False, f"still running {STOP_LIMIT_S} s after SIGINT")
    check(p.returncode == -signal.SIGINT, f"after SIGINT: exit {p.returncode}, {p.stderr.read()[-200:]!r}")


def main():
    mb, src, group = sys.argv[1], sys.argv[2], sys.argv[3]
    scene = os.path.join(src, "tests", "scenes", "motion.txt")
    with tempfile.TemporaryDirectory() as tmp:
        status = globals()[group](mb, scene, tmp)
    if failures:
        print(f"{len(failures)} failure(s) in group {group}", file=sys.stderr)
        return 1
    if status == SKIP:
        return SKIP
    print(f"frames {group}: all cases passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
