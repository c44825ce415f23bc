#!/usr/bin/env python3
"""glint-mpi's speed-up on this machine: one render on 1, 2 and 4 ranks of one thread each, as
ratios against one rank, and against glint render on one thread (the job's own cost); an
animation's frames on 1 and 2 ranks (a frame to a rank); then the cost of sending a big scene's
files and of summing a 4K film, from glint-mpi's summary.

  python3 bench/cluster/run.py --repeat 3 [--mesh ../shared/data/meshes/bunny.ply]
"""

import argparse
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(__file__), ".."))
from timing import timed  # noqa: E402

ROOT = os.path.join(os.path.dirname(__file__), "..", "..")
BUILD = os.path.join(ROOT, "build", "release", "apps", "glint")
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")


def mpirun(ranks, args):
    return ["mpirun", "--oversubscribe", "--bind-to", "none", "-np", str(ranks),
            os.path.join(BUILD, "glint-mpi"), "render", "--threads", "1"] + args


def best(cmd, repeat):
    os.environ.update(ENV)
    walls = []
    for _ in range(repeat):
        status, wall, _, err = timed(cmd, 3600)
        if status != "ok":
            sys.exit("failed (%s): %s\n%s" % (status, " ".join(cmd), err))
        walls.append(wall)
    return min(walls)


def summary(cmd):
    p = subprocess.run(cmd, capture_output=True, text=True, env=ENV)
    if p.returncode != 0:
        sys.exit("failed: %s\n%s" % (" ".join(cmd), p.stderr))
    return p.stdout


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--mesh", help="a big mesh file, for the cost of sending a scene's files")
    args = ap.parse_args()
    out = tempfile.mkdtemp(prefix="glint-cluster-bench-")
    scene = os.path.join(ROOT, "scenes", "distributed-showcase.yaml")
    render = [scene, "--width", "480", "--height", "300", "--spp", "32", "-q",
              "-o", os.path.join(out, "x.exr")]
    one_thread = best([os.path.join(BUILD, "glint"), "render", "--threads", "1"] + render,
                      args.repeat)
    two_threads = best([os.path.join(BUILD, "glint"), "render", "--threads", "2"] + render,
                       args.repeat)
    ranks = {n: best(mpirun(n, render), args.repeat) for n in (1, 2, 4)}
    print("| run | wall s | speed-up against 1 rank |")
    print("|---|---:|---:|")
    print("| glint render, 1 thread | %.3f | %.2fx |" % (one_thread, ranks[1] / one_thread))
    print("| glint render, 2 threads | %.3f | %.2fx |" % (two_threads, ranks[1] / two_threads))
    for n, wall in ranks.items():
        print("| glint-mpi, %d rank%s of 1 thread | %.3f | %.2fx |" % (
            n, "s" if n > 1 else "", wall, ranks[1] / wall))

    # An animation of 8 frames: whole frames, a frame to a rank, against one rank.
    frames = [os.path.join(ROOT, "scenes", "features", "animation.yaml"), "--width", "320",
              "--height", "200", "--spp", "16", "--frames", "0..7", "-q",
              "-o", os.path.join(out, "f.####.png")]
    sequence = {n: best(mpirun(n, frames), args.repeat) for n in (1, 2)}
    sequence_two_threads = best([os.path.join(BUILD, "glint"), "render", "--threads", "2"] +
                                frames, args.repeat)
    print("\n| 8 frames of scenes/features/animation.yaml | wall s | speed-up against 1 rank |")
    print("|---|---:|---:|")
    print("| glint render, 2 threads | %.3f | %.2fx |" % (
        sequence_two_threads, sequence[1] / sequence_two_threads))
    for n, wall in sequence.items():
        print("| glint-mpi, %d rank%s of 1 thread | %.3f | %.2fx |" % (
            n, "s" if n > 1 else "", wall, sequence[1] / wall))

    line = re.compile(r"scene's files sent \(([\d.]+) MB\) in ([\d.]+) s; films summed (\d+) "
                      r"times in ([\d.]+) s")
    if args.mesh:
        yaml = os.path.join(out, "mesh.yaml")
        with open(yaml, "w") as f:
            f.write("camera: {from: [0, 0.1, 0.3], at: [0, 0.1, 0], fov: 40}\n"
                    "lights: [{type: point, position: [1, 1, 1]}]\n"
                    "objects: [{type: mesh, file: %s}]\n" % os.path.abspath(args.mesh))
        s = summary(mpirun(2, [yaml, "--width", "64", "--height", "48", "--allow-read",
                               os.path.dirname(os.path.abspath(args.mesh)),
                               "-o", os.path.join(out, "m.png")]))
        m = line.search(s)
        print("\nscene's files, 2 ranks: %s MB sent in %s s" % (m.group(1), m.group(2)))
    s = summary(mpirun(2, [scene, "--width", "3840", "--height", "2160", "--spp", "1",
                           "--filter", "gaussian", "--integrator", "distributed",
                           "--max-depth", "1", "-o", os.path.join(out, "big.exr")]))
    m = line.search(s)
    print("4K film (Gaussian, 531 MB a rank), 2 ranks: summed in %s s" % m.group(4))


if __name__ == "__main__":
    main()
