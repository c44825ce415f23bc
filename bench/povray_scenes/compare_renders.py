#!/usr/bin/env python3
"""glint against POV-Ray on POV-Ray's own sample scenes: image difference and time.

    bench/povray_scenes/compare_renders.py                 # every sample scene glint reads
    bench/povray_scenes/compare_renders.py advanced/glass/glass.pov ...   # under --scenes

Each scene is rendered by both, in its own folder (where its include files are), at the same
size without antialiasing, one after the other, on every core:

    povray +Iscene.pov +Op.png +W160 +H120 -A -D
    glint render scene.pov -o g.png --width 160 --height 120

Per scene: PSNR over the images' 8-bit sRGB values (dB, the issue's bar is 30), SSIM (Wang et
al. 2004: 11 x 11 Gaussian windows, sigma 1.5, on the mean of the channels) and each command's
wall time, with their ratio (POV-Ray's over glint's: above 1, glint is faster). Then the
summary: how many scenes render, how many match within 30 dB. Prints a Markdown table and
writes every measurement as a JSON line (results.jsonl in the work folder).
"""

import argparse
import json
import math
import os
import subprocess
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "spd_vs_povray"))
sys.path.insert(0, os.path.dirname(HERE))  # bench/, for timing
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
from compare import read_png  # noqa: E402
from timing import timed  # noqa: E402

MATCH_DB = 30


def image(path):
    width, height, data = read_png(path)
    return np.frombuffer(data, dtype=np.uint8).reshape(height, width, 3).astype(np.float64)


def psnr(a, b):
    mse = np.mean((a - b) ** 2)
    return math.inf if mse == 0 else 10 * math.log10(255 ** 2 / mse)


def gaussian_blur(x, sigma=1.5, radius=5):
    taps = np.exp(-0.5 * (np.arange(-radius, radius + 1) / sigma) ** 2)
    taps /= taps.sum()
    x = np.apply_along_axis(lambda r: np.convolve(r, taps, mode="valid"), 1, x)
    return np.apply_along_axis(lambda c: np.convolve(c, taps, mode="valid"), 0, x)


def ssim(a, b):
    x, y = a.mean(axis=2), b.mean(axis=2)
    c1, c2 = (0.01 * 255) ** 2, (0.03 * 255) ** 2
    mx, my = gaussian_blur(x), gaussian_blur(y)
    sxx = gaussian_blur(x * x) - mx * mx
    syy = gaussian_blur(y * y) - my * my
    sxy = gaussian_blur(x * y) - mx * my
    s = ((2 * mx * my + c1) * (2 * sxy + c2)) / ((mx * mx + my * my + c1) * (sxx + syy + c2))
    return float(s.mean())


def reads(glint, scene):
    run = subprocess.run([glint, "info", scene], cwd=os.path.dirname(scene),
                         capture_output=True, text=True, timeout=60)
    return run.returncode == 0


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("scenes", nargs="*", help="scene files, relative to --scenes")
    ap.add_argument("--glint", default="build/release/apps/glint/glint")
    ap.add_argument("--povray", default="povray")
    ap.add_argument("--scenes-dir", default="/usr/share/povray-3.7/scenes")
    ap.add_argument("--width", type=int, default=160)
    ap.add_argument("--height", type=int, default=120)
    ap.add_argument("--timeout", type=float, default=120)
    ap.add_argument("--work", default=os.path.join(tempfile.gettempdir(), "glint-povray-scenes"))
    args = ap.parse_args()
    glint = os.path.abspath(args.glint)
    root = os.path.realpath(args.scenes_dir)
    if args.scenes:
        scenes = [os.path.join(root, s) for s in args.scenes]
    else:
        every = sorted(os.path.join(d, f) for d, _, files in os.walk(root, followlinks=True)
                       for f in files if f.endswith(".pov"))
        scenes = [s for s in every if reads(glint, s)]
        print("glint reads %d of the %d scenes" % (len(scenes), len(every)), file=sys.stderr)
    os.makedirs(args.work, exist_ok=True)
    size = ["+W%d" % args.width, "+H%d" % args.height]
    rows = []
    with open(os.path.join(args.work, "results.jsonl"), "w") as log:
        for scene in scenes:
            name = os.path.relpath(scene, root)
            stem = os.path.join(args.work, name.replace("/", "_")[:-4])
            folder = os.path.dirname(scene)
            p_status, p_wall, _, _ = timed([args.povray, "+I" + scene, "+O" + stem + "-povray.png",
                                            *size, "-A", "-D", "-V", "-GA"],
                                           args.timeout, cwd=folder)
            g_status, g_wall, _, g_err = timed(
                [glint, "render", scene, "-o", stem + "-glint.png", "--width", str(args.width),
                 "--height", str(args.height), "--quiet"], args.timeout, cwd=folder)
            row = {"scene": name, "povray": p_status, "glint": g_status,
                   "povray_s": p_wall, "glint_s": g_wall}
            if p_status == "ok" and g_status == "ok":
                a, b = image(stem + "-glint.png"), image(stem + "-povray.png")
                row.update(psnr=psnr(a, b), ssim=ssim(a, b))
            elif g_status != "ok":
                row["error"] = next((l for l in g_err.splitlines() if "error" in l), g_err)[:120]
            log.write(json.dumps(row) + "\n")
            log.flush()
            rows.append(row)
            print("%-60s %s" % (name, " ".join("%s=%s" % kv for kv in row.items()
                                                   if kv[0] != "scene")), file=sys.stderr)
    print("| scene | PSNR (dB) | SSIM | POV-Ray (s) | glint (s) | ratio |")
    print("|---|---:|---:|---:|---:|---:|")
    for r in rows:
        if "psnr" in r:
            print("| %s | %.1f | %.3f | %.2f | %.2f | %.1f |" % (
                r["scene"], r["psnr"], r["ssim"], r["povray_s"], r["glint_s"],
                r["povray_s"] / r["glint_s"]))
        else:
            print("| %s | POV-Ray %s, glint %s | | | | |" % (r["scene"], r["povray"], r["glint"]))
    both = [r for r in rows if "psnr" in r]
    matched = [r for r in both if r["psnr"] >= MATCH_DB]
    ratios = [r["povray_s"] / r["glint_s"] for r in both]
    print("\n%d scenes: %d rendered by both, %d within %d dB of POV-Ray's image; time ratio "
          "(POV-Ray / glint) geometric mean %.2f" % (
              len(rows), len(both), len(matched), MATCH_DB,
              math.exp(sum(map(math.log, ratios)) / len(ratios)) if ratios else float("nan")))


if __name__ == "__main__":
    main()
