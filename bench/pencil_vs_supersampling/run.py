#!/usr/bin/env python3
"""Texture filtering over ray differentials (pencil tracing) against jittered supersampling, on
the same scene: each image's error against one converged reference, and the time supersampling
needs to reach the error a filtered lookup gives at one sample a pixel.

    bench/pencil_vs_supersampling/run.py           # texture-filtering.yaml at 480 x 270
    bench/pencil_vs_supersampling/run.py --quick   # fewer samples: a check

1. A reference: point (bilinear) lookups at --reference-spp jittered samples a pixel.
2. Supersampling: bilinear lookups at 1, 4, 16, 64 and 256 samples a pixel.
3. Pencils: trilinear and ewa lookups over each sample's footprint at 1 and 4 samples.
Each image's error is its RMSE in linear RGB against the reference; its time the whole
command's wall time on every core, the fastest of --repeat runs. The scene's variants are
written to the work folder, beside a copy of its texture.
"""

import argparse
import os
import shutil
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "distributed_vs_povray"))
sys.path.insert(0, os.path.dirname(HERE))  # bench/, for timing and equal_error
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
import images  # noqa: E402
from equal_error import time_to_reach  # noqa: E402
from timing import fastest  # noqa: E402

SCENE = os.path.join(REPO, "scenes", "features", "texture-filtering.yaml")


def log(msg):
    print(msg, file=sys.stderr, flush=True)


def variant(work, texture_filter):
    """The scene with its floor's filter replaced, in the work folder."""
    text = open(SCENE).read()
    assert "filter: ewa" in text
    path = os.path.join(work, "scene-%s.yaml" % texture_filter)
    with open(path, "w") as f:
        f.write(text.replace("filter: ewa", "filter: " + texture_filter))
    return path


def render(args, scene, spp, out):
    cmd = [args.glint, "render", scene, "-o", out, "--width", str(args.width), "--height",
           str(args.height), "--spp", str(spp), "--threads", "0", "--quiet"]
    return fastest(cmd, args.repeat, args.timeout)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--glint", default=os.path.join(REPO, "build", "release", "apps", "glint",
                                                   "glint"))
    p.add_argument("--work", default="/tmp/glint-pencil-bench")
    p.add_argument("--width", type=int, default=480)
    p.add_argument("--height", type=int, default=270)
    p.add_argument("--reference-spp", type=int, default=1024)
    p.add_argument("--repeat", type=int, default=2)
    p.add_argument("--timeout", type=float, default=600)
    p.add_argument("--quick", action="store_true")
    args = p.parse_args()
    if args.quick:
        args.reference_spp, args.repeat = 64, 1
    os.makedirs(os.path.join(args.work, "textures"), exist_ok=True)
    shutil.copy(os.path.join(os.path.dirname(SCENE), "textures", "tiles.png"),
                os.path.join(args.work, "textures", "tiles.png"))
    scenes = {f: variant(args.work, f) for f in ("bilinear", "trilinear", "ewa")}

    log("reference: %d samples a pixel" % args.reference_spp)
    reference_path = os.path.join(args.work, "reference.pfm")
    render(args, scenes["bilinear"], args.reference_spp, reference_path)
    reference = images.read_pfm(reference_path)

    rows = []
    sweep = []
    for method, spps in (("bilinear", (1, 4, 16, 64, 256)), ("trilinear", (1, 4)),
                         ("ewa", (1, 4))):
        for spp in spps:
            if args.quick and spp > 16:
                continue
            out = os.path.join(args.work, "%s-%d.pfm" % (method, spp))
            wall = render(args, scenes[method], spp, out)
            error = images.rmse(images.read_pfm(out), reference)
            log("%s %d spp: %.3f s, RMSE %.4f" % (method, spp, wall, error))
            rows.append((method, spp, wall, error))
            if method == "bilinear":
                sweep.append((wall, error))

    print("| lookup | spp | wall s | RMSE | supersampling's time to that error |")
    print("|---|---:|---:|---:|---:|")
    for method, spp, wall, error in rows:
        reach = "" if method == "bilinear" else time_to_reach(sweep, error)
        cell = "" if method == "bilinear" else (
            "beyond the sweep" if reach is None else "%.2f s (%.1f×)" % (reach, reach / wall))
        print("| %s | %d | %.3f | %.4f | %s |" % (method, spp, wall, error, cell))


if __name__ == "__main__":
    main()
