#!/usr/bin/env python3
"""Beam tracing against stochastic supersampling, on the same scenes of polygons: each image's
error against one converged reference, and the time supersampling needs to reach the error of
the beam tracer's one pass.

    bench/beam_vs_supersampling/run.py           # three scenes at 480 x 300
    bench/beam_vs_supersampling/run.py --quick   # fewer samples: a check

For each scene (bench/beam_vs_supersampling/mirrors.yaml: polygons, boxes and two mirrors at
an angle; scenes/features/beam-tracing.yaml: the same with a glass slab, which the beam tracer
refracts by the paraxial approximation; bench/beam_vs_supersampling/meshes.yaml: 6,400 mesh
triangles and a mirror, for the cost of many polygons):
1. A reference: Whitted's integrator at --reference-spp jittered samples a pixel, the filter a
   one-pixel box (a pixel's mean, what the beam tracer draws).
2. Supersampling: the same at 1, 4, 16, 64 and 256 samples a pixel.
3. Beams: the beam integrator, once.
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


def render(args, scene, integrator, spp, out):
    cmd = [args.glint, "render", scene, "-o", out, "--width", str(args.width), "--height",
           str(args.height), "--spp", str(spp), "--integrator", integrator, "--filter", "box",
           "--threads", "0", "--quiet", "--allow-read", os.path.join(REPO, "scenes")]
    if integrator == "whitted":
        cmd += ["--sampler", "jittered"]
    return fastest(cmd, args.repeat, args.timeout)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--glint", default=os.path.join(REPO, "build", "release", "apps", "glint",
                                                   "glint"))
    p.add_argument("--scenes", nargs="+",
                   default=[os.path.join(HERE, "mirrors.yaml"),
                            os.path.join(REPO, "scenes", "features", "beam-tracing.yaml"),
                            os.path.join(HERE, "meshes.yaml")])
    p.add_argument("--work", default="/tmp/glint-beam-bench")
    p.add_argument("--width", type=int, default=480)
    p.add_argument("--height", type=int, default=300)
    p.add_argument("--reference-spp", type=int, default=1024)
    p.add_argument("--repeat", type=int, default=2)
    p.add_argument("--timeout", type=float, default=900)
    p.add_argument("--quick", action="store_true")
    args = p.parse_args()
    if args.quick:
        args.reference_spp, args.repeat = 64, 1
    os.makedirs(args.work, exist_ok=True)

    print("| scene | integrator | spp | wall s | RMSE | supersampling's time to that error |")
    print("|---|---|---:|---:|---:|---:|")
    for scene in args.scenes:
        name = os.path.basename(scene)
        log("%s: reference, %d samples a pixel" % (name, args.reference_spp))
        reference_path = os.path.join(args.work, "reference-%s.pfm" % name)
        render(args, scene, "whitted", args.reference_spp, reference_path)
        reference = images.read_pfm(reference_path)
        rows, sweep = [], []
        for integrator, spps in (("whitted", (1, 4, 16, 64, 256)), ("beam", (1,))):
            for spp in spps:
                if args.quick and spp > 16:
                    continue
                out = os.path.join(args.work, "%s-%s-%d.pfm" % (name, integrator, spp))
                wall = render(args, scene, integrator, spp, out)
                error = images.rmse(images.read_pfm(out), reference)
                log("%s %s %d spp: %.3f s, RMSE %.5f" % (name, integrator, spp, wall, error))
                rows.append((integrator, spp, wall, error))
                if integrator == "whitted":
                    sweep.append((wall, error))
        for integrator, spp, wall, error in rows:
            cell = ""
            if integrator == "beam":
                reach = time_to_reach(sweep, error)
                cell = ("beyond the sweep" if reach is None
                        else "%.2f s (%.2f×)" % (reach, reach / wall))
            print("| %s | %s | %d | %.3f | %.5f | %s |" % (name, integrator, spp, wall, error,
                                                            cell))


if __name__ == "__main__":
    main()
