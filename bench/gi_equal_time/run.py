#!/usr/bin/env python3
"""Global illumination at equal time: glint's path, light and photon integrators on the same
scene, each image's error against one converged reference, the time each needs to reach the
same error, and the three images side by side at one time budget.

    bench/gi_equal_time/run.py                        # caustics.yaml at 240 x 160
    bench/gi_equal_time/run.py --quick                # 120 x 80, fewer renders: a check
    bench/gi_equal_time/run.py --scene scenes/features/cornell-box.yaml --width 200 --height 200

1. A reference: the photon integrator (consistent: its radius shrinks to nothing) with
   --reference-spp passes and another seed than the sweep's, so it shares none of its photons.
2. A sweep of each integrator over samples per pixel (passes, for photon). Each image's error is
   its RMSE in linear RGB against the reference, both clamped to [0, --clamp] first (1: what a
   display shows, so that a few fireflies of a hundred do not outweigh the whole image; 0: no
   clamp); its time the whole command's wall time on every core, the fastest of --repeat runs.
3. For target errors, the time each integrator needs to reach it, interpolated on log-log axes
   between its sweep's points, and the ratios to the photon integrator's.
4. With --image out.png: each integrator rendered for about --budget seconds (its sample count
   scaled from its sweep's slowest point), the three side by side: path, light, photon.

Prints Markdown tables and writes every measurement as a JSON line (results.jsonl in the work
folder), with the images.
"""

import argparse
import json
import math
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

INTEGRATORS = ("path", "light", "photon")
SEED, REFERENCE_SEED = 1, 2


def log(msg):
    print(msg, file=sys.stderr, flush=True)


def render(args, integrator, spp, seed, out):
    cmd = [args.glint, "render", args.scene, "-o", out, "--width", str(args.width), "--height",
           str(args.height), "--spp", str(spp), "--seed", str(seed), "--integrator", integrator,
           "--threads", "0", "--quiet"]
    return fastest(cmd, args.repeat, args.timeout)


def side_by_side(pictures, gap=4):
    width, height = pictures[0][0], pictures[0][1]
    total = len(pictures) * width + (len(pictures) - 1) * gap
    values = []
    for y in range(height):
        for i, (_, _, v) in enumerate(pictures):
            if i:
                values.extend([1.0] * (3 * gap))
            values.extend(v[3 * width * y:3 * width * (y + 1)])
    return total, height, values


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--glint", default=os.path.join(REPO, "build/release/apps/glint/glint"))
    parser.add_argument("--scene", default=os.path.join(REPO, "scenes/features/caustics.yaml"))
    parser.add_argument("--width", type=int, default=240)
    parser.add_argument("--height", type=int, default=160)
    parser.add_argument("--reference-spp", type=int, default=1024)
    for integrator, counts in (("path", "16,64,256,1024"), ("light", "16,64,256,1024"),
                               ("photon", "4,16,64,256")):
        parser.add_argument("--%s-spp" % integrator, default=counts,
                            help="the sweep's sample counts for %s" % integrator)
    parser.add_argument("--repeat", type=int, default=1)
    parser.add_argument("--timeout", type=float, default=3600)
    parser.add_argument("--budget", type=float, default=10, help="seconds for --image")
    parser.add_argument("--image", help="write the equal-time images side by side here")
    parser.add_argument("--clamp", type=float, default=1.0)
    parser.add_argument("--work", default="/tmp/glint-gi-equal-time")
    parser.add_argument("--quick", action="store_true")
    args = parser.parse_args()
    if args.quick:
        args.width, args.height, args.reference_spp = 120, 80, 64
        args.path_spp = args.light_spp = args.photon_spp = "2,4,8"
        args.budget = min(args.budget, 2)
    args.scene = os.path.abspath(args.scene)
    os.makedirs(args.work, exist_ok=True)
    results = open(os.path.join(args.work, "results.jsonl"), "a")

    reference_path = os.path.join(args.work, "reference.pfm")
    log("reference: photon, %d passes" % args.reference_spp)
    t = render(args, "photon", args.reference_spp, REFERENCE_SEED, reference_path)
    reference = images.read_pfm(reference_path)
    results.write(json.dumps({"reference": "photon", "spp": args.reference_spp, "wall": t}) + "\n")

    sweep = {k: [] for k in INTEGRATORS}  # (time, error, spp)
    for integrator in INTEGRATORS:
        for spp in [int(s) for s in getattr(args, integrator + "_spp").split(",")]:
            out = os.path.join(args.work, "%s-%d.pfm" % (integrator, spp))
            wall = render(args, integrator, spp, SEED, out)
            image = images.read_pfm(out)
            error = images.rmse(image, reference, clamp=args.clamp or None)
            sweep[integrator].append((wall, error, spp))
            results.write(json.dumps({"integrator": integrator, "spp": spp, "wall": wall,
                                      "rmse": images.rmse(image, reference),
                                      "rmse_clamped": error, "clamp": args.clamp}) + "\n")
            log("%-6s %4d spp: %7.2f s, RMSE %.5f" % (integrator, spp, wall, error))

    print("| integrator | spp | time (s) | RMSE |\n|---|---|---|---|")
    for integrator in INTEGRATORS:
        for wall, error, spp in sweep[integrator]:
            print("| %s | %d | %.2f | %.5f |" % (integrator, spp, wall, error))

    # Targets: errors the photon integrator reaches within its sweep.
    photon_errors = sorted(e for _, e, _ in sweep["photon"])
    targets = [photon_errors[-1], math.sqrt(photon_errors[0] * photon_errors[-1]),
               photon_errors[0]]
    print("\n| RMSE | " + " | ".join("%s (s)" % k for k in INTEGRATORS) +
          " | path / photon | light / photon |\n|---|---|---|---|---|---|")
    for target in targets:
        times = {k: time_to_reach([(t, e) for t, e, _ in sweep[k]], target) for k in INTEGRATORS}

        def cell(t):
            return "%.2f" % t if t else "beyond the sweep"

        def ratio(k):
            if not (times[k] and times["photon"]):
                return "—"
            return "%.1f×" % (times[k] / times["photon"])
        print("| %.5f | %s | %s | %s |" % (target, " | ".join(cell(times[k]) for k in INTEGRATORS),
                                           ratio("path"), ratio("light")))

    if args.image:
        pictures = []
        for integrator in INTEGRATORS:
            wall, _, spp = max(sweep[integrator])
            n = max(1, int(round(spp * args.budget / wall)))
            out = os.path.join(args.work, "budget-%s.pfm" % integrator)
            t = render(args, integrator, n, SEED, out)
            picture = images.read_pfm(out)
            error = images.rmse(picture, reference, clamp=args.clamp or None)
            print("\n%s: %d spp, %.2f s, RMSE %.5f" % (integrator, n, t, error))
            pictures.append(picture)
        images.write_png(side_by_side(pictures), args.image)
        log("wrote " + args.image)


if __name__ == "__main__":
    main()
