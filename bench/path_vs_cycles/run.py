#!/usr/bin/env python3
"""Path tracing, glint against Blender's Cycles on the CPU: the time each needs to reach the same
error on the Cornell box, each against its own converged image.

    bench/path_vs_cycles/run.py              # 200 x 200, the full sweep
    bench/path_vs_cycles/run.py --quick      # 64 x 64, a few renders: a check

The scene is scenes/features/cornell-box.yaml for glint and, built from the same file inside
Blender by cornell_cycles.py, for Cycles (Debian's blender, run headless). Both render on every
core with no adaptive sampling and no denoising, paths of at most 8 surfaces, and a box filter
one pixel wide (a wider filter lowers a pixel's noise by blurring: both use the same).

1. A reference for each, at --reference-spp samples and another seed than the sweep's; the two
   references are compared with each other (RMSE and means), to show that the two renderers
   compute the same image.
2. A sweep of each over samples per pixel. Each image's error is its RMSE in linear RGB against
   its own renderer's reference; its times are the whole command's wall time and the render's
   alone (glint's --stats seconds; Cycles' render call, Blender's start-up and scene building
   left out), the fastest of --repeat runs.
3. For target errors (those glint reaches in its sweep), the time each needs to reach it,
   interpolated on log-log axes, and the ratio Cycles / glint, for both times; and each one's
   samples a second (and glint's rays a second) at its largest sweep point.

Prints Markdown tables and writes every measurement as a JSON line (results.jsonl in the work
folder), with the images.
"""

import argparse
import json
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "distributed_vs_povray"))
sys.path.insert(0, os.path.dirname(HERE))  # bench/, for timing and equal_error
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
import images  # noqa: E402
import yaml  # noqa: E402  (Debian's python3-yaml, which blender depends on)
from equal_error import time_to_reach  # noqa: E402
from timing import timed  # noqa: E402

SEED, REFERENCE_SEED = 1, 2
SCENE = os.path.join(REPO, "scenes/features/cornell-box.yaml")


def log(msg):
    print(msg, file=sys.stderr, flush=True)


def fastest(args, cmd, render_seconds):
    """(wall, render) of the fastest of --repeat runs of cmd."""
    best = None
    for _ in range(args.repeat):
        status, wall, _, stderr = timed(cmd, args.timeout)
        if status != "ok":
            sys.exit("failed (%s): %s\n%s" % (status, " ".join(cmd), stderr[-2000:]))
        run = (wall, render_seconds())
        best = run if best is None or run[0] < best[0] else best
    return best


def glint(args, spp, seed, out):
    stats = out + ".json"
    cmd = [args.glint, "render", SCENE, "-o", out, "--width", str(args.width), "--height",
           str(args.height), "--spp", str(spp), "--seed", str(seed), "--filter", "box",
           "--threads", "0", "--quiet", "--stats", stats]

    def seconds():
        with open(stats) as f:
            s = json.load(f)
        glint.rays = s["rays"]["total"]
        return s["seconds"]
    return fastest(args, cmd, seconds)


def cycles(args, spp, seed, out):
    log_file = out + ".log"
    script = os.path.join(HERE, "cornell_cycles.py")
    inner = [args.blender, "-b", "--factory-startup", "-noaudio", "--python-exit-code", "1",
             "-P", script, "--", "--scene", args.scene_json, "--out", out,
             "--width", str(args.width), "--height", str(args.height), "--spp", str(spp), "--seed", str(seed)]
    # Blender prints the render time on standard output; keep it in a file beside the image.
    cmd = ["sh", "-c", '"$@" > "%s" 2>&1' % log_file, "sh"] + inner

    def seconds():
        with open(log_file) as f:
            m = re.search(r"render seconds: ([0-9.]+)", f.read())
        if not m:
            sys.exit("no render time in " + log_file)
        return float(m.group(1))
    return fastest(args, cmd, seconds)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--glint", default=os.path.join(REPO, "build/release/apps/glint/glint"))
    parser.add_argument("--blender", default="blender")
    parser.add_argument("--width", type=int, default=200)
    parser.add_argument("--height", type=int, default=200)
    parser.add_argument("--reference-spp", type=int, default=4096)
    parser.add_argument("--spp", default="16,32,64,128,256,512")
    parser.add_argument("--repeat", type=int, default=1)
    parser.add_argument("--timeout", type=float, default=3600)
    parser.add_argument("--work", default="/tmp/glint-path-vs-cycles")
    parser.add_argument("--quick", action="store_true")
    args = parser.parse_args()
    if args.quick:
        args.width = args.height = 64
        args.reference_spp, args.spp = 256, "8,16,32"
    os.makedirs(args.work, exist_ok=True)
    args.scene_json = os.path.join(args.work, "cornell-box.json")
    with open(SCENE) as f, open(args.scene_json, "w") as out:
        json.dump(yaml.safe_load(f), out)
    results = open(os.path.join(args.work, "results.jsonl"), "a")
    renderers = {"glint": (glint, ".pfm"), "cycles": (cycles, ".exr")}

    references = {}
    for name, (render, extension) in renderers.items():
        out = os.path.join(args.work, "reference-%s%s" % (name, extension))
        log("%s reference: %d spp" % (name, args.reference_spp))
        wall, seconds = render(args, args.reference_spp, REFERENCE_SEED, out)
        references[name] = images.read_image(out)
        results.write(json.dumps({"renderer": name, "reference": True, "spp": args.reference_spp,
                                  "wall": wall, "render": seconds}) + "\n")
    agreement = images.rmse(references["glint"], references["cycles"])
    print("The references differ by an RMSE of %.5f; their means are %.5f (glint) and %.5f "
          "(Cycles).\n" % (agreement, images.mean(references["glint"]),
                           images.mean(references["cycles"])))

    sweep = {name: [] for name in renderers}  # (wall, render, error, spp, rays)
    for name, (render, extension) in renderers.items():
        for spp in [int(s) for s in args.spp.split(",")]:
            out = os.path.join(args.work, "%s-%d%s" % (name, spp, extension))
            wall, seconds = render(args, spp, SEED, out)
            error = images.rmse(images.read_image(out), references[name])
            rays = glint.rays if name == "glint" else None
            sweep[name].append((wall, seconds, error, spp, rays))
            results.write(json.dumps({"renderer": name, "spp": spp, "wall": wall,
                                      "render": seconds, "rmse": error, "rays": rays}) + "\n")
            log("%-6s %4d spp: %7.2f s wall, %7.2f s render, RMSE %.5f" %
                (name, spp, wall, seconds, error))

    print("| renderer | spp | wall (s) | render (s) | RMSE |\n|---|---|---|---|---|")
    for name in renderers:
        for wall, seconds, error, spp, _ in sweep[name]:
            print("| %s | %d | %.2f | %.2f | %.5f |" % (name, spp, wall, seconds, error))

    print("\n| RMSE | glint wall (s) | Cycles wall (s) | ratio | glint render (s) | "
          "Cycles render (s) | ratio |\n|---|---|---|---|---|---|---|")
    for target in sorted({e for _, _, e, _, _ in sweep["glint"]}, reverse=True):
        row = []
        for column in (0, 1):
            times = [time_to_reach([(p[column], p[2]) for p in sweep[name]], target)
                     for name in ("glint", "cycles")]
            ratio = "%.2f×" % (times[1] / times[0]) if all(times) else "—"
            row += ["%.2f" % t if t else "beyond the sweep" for t in times] + [ratio]
        print("| %.5f | %s |" % (target, " | ".join(row)))

    pixels = args.width * args.height
    for name in renderers:
        wall, seconds, _, spp, rays = max(sweep[name], key=lambda p: p[3])
        text = "%s at %d spp: %.2f M samples a second" % (name, spp, pixels * spp / seconds / 1e6)
        if rays:
            text += ", %.2f M rays a second" % (rays / seconds / 1e6)
        print("\n" + text)


if __name__ == "__main__":
    main()
