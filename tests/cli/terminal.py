"""terminal.py — running the executable on a pseudo-terminal, for the CLI tests that check what
it shows there (progress) and what Ctrl-C does."""
import os
import pty
import select
import signal
import time


def spawn_on_terminal(argv):
    """Starts argv with a new pseudo-terminal as its controlling terminal; (pid, master fd)."""
    pid, master = pty.fork()
    if pid == 0:
        try:
            os.execv(argv[0], argv)
        finally:
            os._exit(127)
    return pid, master


def read_until(master, want, limit_s):
    """Reads the terminal until `want` shows or the output ends; returns what was read."""
    seen, deadline = b"", time.monotonic() + limit_s
    while want not in seen and time.monotonic() < deadline:
        ready, _, _ = select.select([master], [], [], 0.1)
        if not ready:
            continue
        try:
            chunk = os.read(master, 4096)
        except OSError:  # EIO: the other end closed
            break
        if not chunk:
            break
        seen += chunk
    return seen


def wait_for_exit(pid, limit_s):
    """The process's wait status, or None if it is still running after limit_s (then killed)."""
    deadline = time.monotonic() + limit_s
    while time.monotonic() < deadline:
        done, status = os.waitpid(pid, os.WNOHANG)
        if done:
            return status
        time.sleep(0.02)
    os.kill(pid, signal.SIGKILL)
    os.waitpid(pid, 0)
    return None
