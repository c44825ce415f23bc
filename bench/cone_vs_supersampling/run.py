#!/usr/bin/env python3
"""Cone tracing against stochastic supersampling, on the same scene: each image's error against
one converged reference, and the time supersampling needs to reach the error a cone a pixel
gives.

    bench/cone_vs_supersampling/run.py           # cone-tracing.yaml at 480 x 270
    bench/cone_vs_supersampling/run.py --quick   # fewer samples: a check

1. A reference: the distributed integrator (soft shadows and glossy reflection by sampling)
   at --reference-spp jittered samples a pixel, every filter a one-pixel box (a pixel's mean,
   what a cone stands for).
2. Supersampling: the distributed integrator at 1, 4, 16, 64 and 256 samples a pixel.
3. Cones: the cone integrator at 1 and 4 cones a pixel.
Each image's error is its RMSE in linear RGB against the reference; its time the whole
command's wall time on every core, the fastest of --repeat runs.
"""

import argparse
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "distributed_vs_povray"))
sys.path.insert(0, os.path.dirname(HERE))  # bench/, for timing and equal_error
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
import images  # noqa: E402
from equal_error import time_to_reach  # noqa: E402
from timing import fastest  # noqa: E402


def log(msg):
    print(msg, file=sys.stderr, flush=True)


def render(args, integrator, spp, out):
    cmd = [args.glint, "render", args.scene, "-o", out, "--width", str(args.width), "--height",
           str(args.height), "--spp", str(spp), "--integrator", integrator, "--filter", "box",
           "--threads", "0", "--quiet"]
    if integrator == "distributed":
        cmd += ["--sampler", "jittered"]
    return fastest(cmd, args.repeat, args.timeout)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--glint", default=os.path.join(REPO, "build", "release", "apps", "glint",
                                                   "glint"))
    p.add_argument("--scene", default=os.path.join(REPO, "scenes", "features",
                                                   "cone-tracing.yaml"))
    p.add_argument("--work", default="/tmp/glint-cone-bench")
    p.add_argument("--width", type=int, default=480)
    p.add_argument("--height", type=int, default=270)
    p.add_argument("--reference-spp", type=int, default=1024)
    p.add_argument("--repeat", type=int, default=2)
    p.add_argument("--timeout", type=float, default=900)
    p.add_argument("--quick", action="store_true")
    args = p.parse_args()
    if args.quick:
        args.reference_spp, args.repeat = 64, 1
    os.makedirs(args.work, exist_ok=True)

    log("reference: %d samples a pixel" % args.reference_spp)
    reference_path = os.path.join(args.work, "reference.pfm")
    render(args, "distributed", args.reference_spp, reference_path)
    reference = images.read_pfm(reference_path)

    rows, sweep = [], []
    for integrator, spps in (("distributed", (1, 4, 16, 64, 256)), ("cone", (1, 4))):
        for spp in spps:
            if args.quick and spp > 16:
                continue
            out = os.path.join(args.work, "%s-%d.pfm" % (integrator, spp))
            wall = render(args, integrator, spp, out)
            error = images.rmse(images.read_pfm(out), reference)
            log("%s %d spp: %.3f s, RMSE %.4f" % (integrator, spp, wall, error))
            rows.append((integrator, spp, wall, error))
            if integrator == "distributed":
                sweep.append((wall, error))

    print("| integrator | spp | wall s | RMSE | supersampling's time to that error |")
    print("|---|---:|---:|---:|---:|")
    for integrator, spp, wall, error in rows:
        cell = ""
        if integrator == "cone":
            reach = time_to_reach(sweep, error)
            cell = "beyond the sweep" if reach is None else "%.2f s (%.2f×)" % (reach, reach / wall)
        print("| %s | %d | %.3f | %.4f | %s |" % (integrator, spp, wall, error, cell))


if __name__ == "__main__":
    main()
