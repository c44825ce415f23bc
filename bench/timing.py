"""Timing a command as the renderer comparisons do: the whole process, wall and CPU time."""

import resource
import subprocess
import sys
import time


def timed(cmd, timeout, cwd=None):
    """Runs cmd; returns its status, wall seconds, CPU seconds (user + system) and stderr. The
    CPU time says less about speed but more about work done when other jobs share the cores."""
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    try:
        p = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, errors="replace",
                           timeout=timeout)
        status, stderr = ("ok" if p.returncode == 0 else "exit %d" % p.returncode), p.stderr
    except subprocess.TimeoutExpired:
        status, stderr = "timeout", ""
    wall = time.perf_counter() - t0
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime)
    return status, wall, cpu, stderr


def fastest(cmd, repeat, timeout):
    """The fastest wall time of `repeat` runs of cmd; exits with its error if any run fails."""
    best = None
    for _ in range(repeat):
        status, wall, _, stderr = timed(cmd, timeout)
        if status != "ok":
            sys.exit("glint failed (%s): %s\n%s" % (status, " ".join(cmd), stderr))
        best = wall if best is None else min(best, wall)
    return best
