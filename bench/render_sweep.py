#!/usr/bin/env python3
"""Whole-render measurements of glint on Haines' Standard Procedural Databases.

Three tables, each a set of `glint render` runs made in one go, so that ratios compare runs on
the same machine under the same load:

  sizes    render time against scene size over the SPD size factors, for each structure, with
           the log-log slope of time against primitives (1 would be brute force, 0 ideal);
  shadows  the light buffer's gain: --shadow-accel none / light-buffer / light-buffer+cache;
  threads  thread scaling: one thread against all cores.

Renders are the SPD's own (512x512, one sample a pixel, depth 5). The time is glint's own
`seconds` figure (--stats): the render alone, without parsing and building, so that it measures
the cost of tracing; each figure is the best of --repeat runs.

    bench/render_sweep.py sizes --glint build/release/apps/glint/glint --spd ../shared/data/spd
"""

import argparse
import gzip
import json
import math
import os
import re
import subprocess
import sys
import tempfile

FAMILIES = ["balls", "gears", "lattice", "mount", "rings", "teapot", "tetra", "tree"]
# NFF entities that make one primitive each (a polygon, patch, sphere, cone or cylinder).
PRIMITIVE_ENTITIES = ("p", "pp", "s", "c")


def spd_files(spd, family):
    """The family's files, smallest first: the default size, then the -sN factors."""
    files = [f for f in os.listdir(spd) if re.fullmatch(family + r"(-s\d+)?\.nff(\.gz)?", f)]
    return [os.path.join(spd, f) for f in files]


def count_primitives(path):
    opener = gzip.open if path.endswith(".gz") else open
    with opener(path, "rt", errors="replace") as f:
        return sum(1 for line in f if line.split(" ", 1)[0].strip() in PRIMITIVE_ENTITIES)


def render_seconds(glint, path, repeat, extra):
    """The best render time of `repeat` runs, from glint's --stats."""
    best = None
    with tempfile.TemporaryDirectory() as tmp:
        stats = os.path.join(tmp, "stats.json")
        for _ in range(repeat):
            cmd = [glint, "render", path, "-o", os.path.join(tmp, "out.png"), "--width", "512",
                   "--height", "512", "--spp", "1", "--max-depth", "5", "--quiet", "--stats",
                   stats] + extra
            subprocess.run(cmd, check=True)
            with open(stats) as f:
                seconds = json.load(f)["seconds"]
            best = seconds if best is None else min(best, seconds)
    return best


def slope(points):
    """Least-squares slope of log(time) against log(primitives)."""
    xs = [math.log(n) for n, _ in points]
    ys = [math.log(t) for _, t in points]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    sxx = sum((x - mx) ** 2 for x in xs)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx if sxx > 0 else float("nan")


def sizes(args):
    accels = args.accel.split(",")
    print("| database | primitives | " + " | ".join(f"{a} s" for a in accels) + " |")
    print("|---|---:|" + "---:|" * len(accels))
    slopes = {}
    for family in args.family.split(","):
        runs = sorted((count_primitives(p), p) for p in spd_files(args.spd, family))
        per_accel = {a: [] for a in accels}
        for n, path in runs:
            cells = []
            for a in accels:
                if a == "grid" and n > args.grid_limit:
                    cells.append("—")
                    continue
                t = render_seconds(args.glint, path, args.repeat,
                                   ["--accel", a, "--threads", str(args.threads)])
                per_accel[a].append((n, t))
                cells.append(f"{t:.3f}")
            print(f"| {os.path.basename(path)} | {n:,} | " + " | ".join(cells) + " |", flush=True)
        slopes[family] = {a: slope(p) if len(p) > 1 else float("nan")
                          for a, p in per_accel.items()}
    print()
    print("| database | " + " | ".join(f"{a} slope" for a in accels) + " |")
    print("|---|" + "---:|" * len(accels))
    for family, by_accel in slopes.items():
        print(f"| {family} | " + " | ".join(f"{by_accel[a]:.2f}" for a in accels) + " |")


def shadows(args):
    modes = ["none", "light-buffer", "light-buffer+cache"]
    print("| database | none s | light-buffer s | +cache s | gain (none / light-buffer) |"
          " gain (none / +cache) |")
    print("|---|---:|---:|---:|---:|---:|")
    for family in args.family.split(","):
        path = os.path.join(args.spd, family + ".nff")
        t = {m: render_seconds(args.glint, path, args.repeat,
                               ["--shadow-accel", m, "--threads", str(args.threads)])
             for m in modes}
        print(f"| {family} | {t['none']:.3f} | {t['light-buffer']:.3f} |"
              f" {t['light-buffer+cache']:.3f} | {t['none'] / t['light-buffer']:.2f}× |"
              f" {t['none'] / t['light-buffer+cache']:.2f}× |", flush=True)


def threads(args):
    cores = os.cpu_count() or 1
    print(f"| database | 1 thread s | {cores} threads s | speed-up |")
    print("|---|---:|---:|---:|")
    for family in args.family.split(","):
        path = os.path.join(args.spd, family + ".nff")
        one = render_seconds(args.glint, path, args.repeat, ["--threads", "1"])
        all_ = render_seconds(args.glint, path, args.repeat, ["--threads", str(cores)])
        print(f"| {family} | {one:.3f} | {all_:.3f} | {one / all_:.2f}× |", flush=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("table", choices=["sizes", "shadows", "threads"])
    parser.add_argument("--glint", default="build/release/apps/glint/glint")
    parser.add_argument("--spd", default="../shared/data/spd")
    parser.add_argument("--family", default=",".join(FAMILIES))
    parser.add_argument("--accel", default="bvh,kdtree,grid")
    parser.add_argument("--threads", type=int, default=1, help="threads for sizes and shadows")
    parser.add_argument("--repeat", type=int, default=2)
    parser.add_argument("--grid-limit", type=int, default=10**7,
                        help="skip the grid above this many primitives")
    args = parser.parse_args()
    if not os.path.isdir(args.spd):
        sys.exit(f"render_sweep: no SPD directory at {args.spd}")
    {"sizes": sizes, "shadows": shadows, "threads": threads}[args.table](args)


if __name__ == "__main__":
    main()
