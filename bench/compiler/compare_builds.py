#!/usr/bin/env python3
"""Two builds of glint side by side: each scene rendered by one and then the other, --repeat
times, and the fastest render and whole-process times (glint's --stats) of each compared as a
ratio. For link-time and profile-guided optimisation against the release build (README.md)."""

import argparse
import json
import os
import subprocess
import sys
import tempfile

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
DATA = os.path.join(ROOT, "..", "shared", "data")

# Whitted, distributed and path tracing, SPD databases of spheres, cones and polygons, a mesh.
CASES = [
    ("showcase", ["scenes/showcase.yaml"]),
    ("distributed, 16 spp", ["scenes/distributed-showcase.yaml", "--spp", "16"]),
    ("Cornell box, path, 64 spp", ["scenes/features/cornell-box.yaml", "--spp", "64",
                                   "--width", "256", "--height", "256"]),
    ("balls 512²", [DATA + "/spd/balls.nff", "--width", "512", "--height", "512"]),
    ("rings 512²", [DATA + "/spd/rings.nff", "--width", "512", "--height", "512"]),
    ("gears 512²", [DATA + "/spd/gears.nff", "--width", "512", "--height", "512"]),
    ("bunny 512²", [DATA + "/meshes/stanford-bunny.obj", "--width", "512", "--height", "512"]),
]


def times(glint, args, work):
    out, stats = os.path.join(work, "image.pfm"), os.path.join(work, "stats.json")
    subprocess.run([glint, "render", *args, "-o", out, "--stats", stats, "--quiet"], cwd=ROOT,
                   check=True, stdout=subprocess.DEVNULL)
    with open(stats) as f:
        return json.load(f)["times"]


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("reference", help="the reference build's glint")
    parser.add_argument("candidate", help="the build measured against it")
    parser.add_argument("--repeat", type=int, default=5)
    a = parser.parse_args()
    print("| scene | render: reference, candidate, ratio | process: reference, candidate, ratio |")
    print("|---|---|---|")
    with tempfile.TemporaryDirectory() as work:
        for name, args in CASES:
            if not os.path.exists(os.path.join(ROOT, args[0])):
                print("| %s | not found: %s | |" % (name, args[0]), file=sys.stderr)
                continue
            runs = {a.reference: [], a.candidate: []}
            for _ in range(a.repeat):  # alternating, so that a change of load touches both
                for glint in runs:
                    runs[glint].append(times(glint, args, work))
            cells = []
            for key in ("render", "process"):
                ref = min(t[key] for t in runs[a.reference])
                can = min(t[key] for t in runs[a.candidate])
                cells.append("%.3f s, %.3f s, %.3f" % (ref, can, ref / can))
            print("| %s | %s | %s |" % (name, cells[0], cells[1]), flush=True)


if __name__ == "__main__":
    main()
