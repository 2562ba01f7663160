#!/usr/bin/env python3
"""simulate_test.py — `marchbox simulate` on a terminal and off it, and stopped by Ctrl-C.

On a terminal (a pseudo-terminal here) a run shows its progress on standard error; piped, it
shows nothing. Ctrl-C, typed on that terminal, ends a long run at once with a non-zero status
and leaves the output file as it was, with no temporary file beside it.

Usage: simulate_test.py MARCHBOX SOURCE_DIR
"""
import os
import subprocess
import sys
import tempfile

from terminal import read_until, spawn_on_terminal, wait_for_exit

# Generous bounds, not timings: they only turn a hang into a failure.
RUN_LIMIT_S = 120    # a run that should finish
STOP_LIMIT_S = 5     # from Ctrl-C to the process gone

failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        print("FAIL:", what, file=sys.stderr)


def progress_on_a_terminal(mb, scene, tmp):
    pid, master = spawn_on_terminal([mb, "simulate", scene, "--seconds", "5", "-o", os.path.join(tmp, "a.txt")])
    seen = read_until(master, b"simulating 100%", RUN_LIMIT_S)
    status = wait_for_exit(pid, RUN_LIMIT_S)
    os.close(master)
    check(status == 0, f"simulate on a terminal: wait status {status}")
    check(b"simulating   1%" in seen and b"simulating 100%" in seen, f"no progress on a terminal: {seen[-200:]!r}")


def no_progress_when_piped(mb, scene, tmp):
    run = subprocess.run([mb, "simulate", scene, "--seconds", "5", "-o", os.path.join(tmp, "b.txt")],
                         stdin=subprocess.DEVNULL, capture_output=True, timeout=RUN_LIMIT_S)
    check(run.returncode == 0, f"simulate piped: exit {run.returncode}")
    check(run.stderr == b"", f"piped standard error holds {run.stderr[:200]!r}")


def ctrl_c_stops_and_writes_nothing(mb, scene, tmp):
    folder = os.path.join(tmp, "ctrl-c")
    os.mkdir(folder)
    out = os.path.join(folder, "out.txt")
    before = b"# known content, not a simulated scene\n"
    with open(out, "wb") as f:
        f.write(before)
    # An hour of simulated time: seconds of steps even on a fast machine, so Ctrl-C lands in
    # the middle of them.
    pid, master = spawn_on_terminal([mb, "simulate", scene, "--seconds", "3600", "-o", out])
    started = b"simulating" in read_until(master, b"simulating", RUN_LIMIT_S)
    check(started, "no progress before Ctrl-C")
    os.write(master, b"\x03")  # Ctrl-C: the terminal sends SIGINT to the run
    status = wait_for_exit(pid, STOP_LIMIT_S)
    os.close(master)
    check(status is not None, f"still running {STOP_LIMIT_S} s after Ctrl-C")
    if status is not None:
        stopped = os.WIFSIGNALED(status) or os.WEXITSTATUS(status) != 0
        check(stopped, f"Ctrl-C: wait status {status}, a success")
    with open(out, "rb") as f:
        check(f.read() == before, "Ctrl-C changed the output file")
    check(os.listdir(folder) == ["out.txt"], f"Ctrl-C left {sorted(os.listdir(folder))}")


def main():
    mb, src = sys.argv[1], sys.argv[2]
    scene = os.path.join(src, "scenes", "pile.txt")
    with tempfile.TemporaryDirectory() as tmp:
        progress_on_a_terminal(mb, scene, tmp)
        no_progress_when_piped(mb, scene, tmp)
        ctrl_c_stops_and_writes_nothing(mb, scene, tmp)
    if failures:
        print(f"{len(failures)} failure(s)", file=sys.stderr)
        return 1
    print("simulate: all cases passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
