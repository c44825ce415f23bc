#!/usr/bin/env python3
"""glint's BVH against Embree on the same rays: `glint bench --json` run several times in a row on
each scene, alternating the two structures, and the median of the per-run throughput ratios.

A ratio within one run cancels the machine's speed; the median over runs, and the range printed
beside it, show how far the machine's other jobs moved it. Prints a Markdown table (the one in
bench/README.md) and, with --json, the raw rows.

    bench/embree_ratios.py --glint build/release/apps/glint/glint --runs 5 \\
        ../shared/data/meshes/stanford-bunny.obj ../shared/data/spd/balls.nff
"""

import argparse
import json
import os
import statistics
import subprocess
import sys


def bench(glint, scene, accel, rays, threads):
    """One `glint bench` run of one structure: {(ray set, threads): row}."""
    out = subprocess.run(
        [glint, "bench", scene, "--json", "--accel", accel, "--rays", str(rays),
         "--threads", str(threads)],
        check=True, capture_output=True, text=True).stdout
    rows = [json.loads(line) for line in out.splitlines() if line.startswith("{")]
    return {(r["rays"], r["threads"]): r for r in rows}


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("scenes", nargs="+")
    parser.add_argument("--glint", default="build/release/apps/glint/glint")
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--rays", type=int, default=262144)
    parser.add_argument("--threads", type=int, default=0, help="the 'all threads' count")
    parser.add_argument("--json", action="store_true", help="print the raw rows too")
    args = parser.parse_args()

    print("| scene | primitives | rays | threads | glint BVH Mrays/s | Embree Mrays/s | "
          "ratio (median) | range | glint B/prim | Embree B/prim | build glint / Embree |")
    print("|---|---:|---|---:|---:|---:|---:|---|---:|---:|---:|")
    for scene in args.scenes:
        runs = []  # [(glint rows, embree rows)]
        for _ in range(args.runs):
            g = bench(args.glint, scene, "bvh", args.rays, args.threads)
            e = bench(args.glint, scene, "embree", args.rays, args.threads)
            runs.append((g, e))
            if args.json:
                for row in list(g.values()) + list(e.values()):
                    print(json.dumps(row), file=sys.stderr)
        name = os.path.basename(scene)
        for key in runs[0][0]:
            ratios = [g[key]["mrays_per_s"] / e[key]["mrays_per_s"] for g, e in runs]
            builds = [g[key]["build_s"] / e[key]["build_s"] for g, e in runs]
            g0, e0 = runs[0]
            print(f"| {name} | {g0[key]['primitives']:,} | {key[0]} | {key[1]} | "
                  f"{statistics.median(g[key]['mrays_per_s'] for g, _ in runs):.2f} | "
                  f"{statistics.median(e[key]['mrays_per_s'] for _, e in runs):.2f} | "
                  f"{statistics.median(ratios):.2f}× | {min(ratios):.2f}–{max(ratios):.2f} | "
                  f"{g0[key]['bytes_per_prim']:.1f} | {e0[key]['bytes_per_prim']:.1f} | "
                  f"{statistics.median(builds):.2f}× |")
            sys.stdout.flush()


if __name__ == "__main__":
    main()
