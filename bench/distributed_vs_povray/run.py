#!/usr/bin/env python3
"""Distributed ray tracing, glint against POV-Ray 3.7: the time each needs to reach the same
error against a high-sample reference.

    bench/distributed_vs_povray/run.py                  # 480 x 270, the full sweep
    bench/distributed_vs_povray/run.py --quick          # 200 x 112, a few renders: a check
    bench/distributed_vs_povray/run.py --repeat 3 --width 640 --height 360

The scene is scene.yaml for glint and scene.pov, the same scene, for POV-Ray (soft shadows from
an area light with jitter, focal blur). Both render on every core, in the work folder:

    glint render scene.yaml -o g.pfm --width W --height H --spp N --seed S --threads 0
                 --quiet --stats g.json
    povray +Iscene.pov +Op.exr +FE +WW +HH -A -D +WT<cores> Declare=BlurSamples=B
           Declare=AreaN=N [Declare=BlurVariance=V] [Declare=Adaptive=A] [Declare=Mirror=1]

1. A reference for each renderer, at many samples: its own converged image. Each is drawn
   independently of the sweep's images (glint: another seed; POV-Ray, whose samples follow
   from the pixel's coordinates: rendered mirrored and flipped back). The two references are
   compared with each other, to show that the two files describe the same scene.
2. A sweep: glint over samples per pixel; POV-Ray over (blur_samples, area light N x N) pairs,
   and over its adaptive focal blur (--pov-variance). Each image's error is its RMSE in linear
   RGB against its own renderer's reference; its time is the whole command's wall time, the
   fastest of --repeat runs.
3. For target errors (those glint reaches at --target-spp), the time each renderer needs to
   reach it, interpolated on log-log axes between the sweep's points (on the Pareto front of
   each renderer's settings: the fastest time at each error), and their ratio, POV-Ray / glint.

Prints Markdown tables and writes every measurement as a JSON line (results.jsonl in the work
folder), with the images.
"""

import argparse
import datetime
import json
import math
import os
import re
import shutil
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.dirname(HERE))  # bench/, for timing
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
import images  # noqa: E402
from timing import timed  # noqa: E402

GLINT_SEED = 1
GLINT_REFERENCE_SEED = 2  # another seed: the reference shares no samples with the sweep


def log(msg):
    print(msg, file=sys.stderr, flush=True)


def int_list(text):
    return [int(x) for x in text.split(",") if x]


def cpu_idle_share(seconds):
    """The share of the machine's CPU time spent idle over the next `seconds` (/proc/stat)."""
    def sample():
        with open("/proc/stat") as f:
            t = [int(x) for x in f.readline().split()[1:]]
        return t[3] + t[4], sum(t)  # idle + iowait, all
    idle0, total0 = sample()
    time.sleep(seconds)
    idle1, total1 = sample()
    return (idle1 - idle0) / max(1, total1 - total0)


def wait_for_idle(min_idle, patience):
    """Waits, up to patience seconds, until other jobs leave the cores (at least min_idle of
    the CPU time idle over half a second); returns the last share measured. The cores are
    shared: a render timed beside a compiler takes twice as long."""
    waited, idle = 0.0, cpu_idle_share(0.5)
    while idle < min_idle and waited < patience:
        time.sleep(2)
        waited += 2.5
        idle = cpu_idle_share(0.5)
    return idle


class Renders:
    """Builds and runs the two renderers' commands in the work folder."""

    def __init__(self, args, glint, cores):
        self.args, self.glint, self.cores = args, glint, cores

    def glint_job(self, spp, seed, name):
        a = self.args
        out = os.path.join("img", name + ".pfm")
        stats = os.path.join("img", name + ".json")
        cmd = [self.glint, "render", "scene.yaml", "-o", out, "--width", str(a.width),
               "--height", str(a.height), "--spp", str(spp), "--seed", str(seed),
               "--threads", "0", "--quiet", "--stats", stats]
        return {"renderer": "glint", "spp": spp, "seed": seed, "cmd": cmd, "image": out,
                "stats": stats, "label": "%d spp" % spp}

    def povray_job(self, blur, area, name, adaptive=None, variance=0, mirror=False):
        a = self.args
        out = os.path.join("img", name + ".exr")
        cmd = [a.povray, "+Iscene.pov", "+O" + out, "+FE", "+W%d" % a.width, "+H%d" % a.height,
               "-A", "-D", "+WT%d" % self.cores, "Declare=BlurSamples=%d" % blur,
               "Declare=AreaN=%d" % area]
        label = "blur %d, %d×%d" % (blur, area, area)
        if variance:
            cmd.append("Declare=BlurVariance=%.10g" % variance)
            label = "blur ≤ %d, variance 1/%g, %d×%d" % (blur, 1 / variance, area, area)
        if adaptive is not None:
            cmd.append("Declare=Adaptive=%d" % adaptive)
            label += ", adaptive %d" % adaptive
        if not a.area_illumination:
            cmd.append("Declare=AreaIllumination=0")
        if mirror:
            cmd.append("Declare=Mirror=1")
        return {"renderer": "povray", "blur": blur, "area": area, "adaptive": adaptive,
                "variance": variance, "mirror": mirror, "cmd": cmd, "image": out,
                "label": label}

    def run(self, job):
        idle = wait_for_idle(self.args.min_idle, self.args.patience) if self.args.min_idle else None
        status, wall, cpu, stderr = timed(job["cmd"], self.args.timeout, self.args.work)
        r = {"status": status, "wall": wall, "cpu": cpu, "idle_before": idle}
        if status == "ok" and job["renderer"] == "glint":
            with open(os.path.join(self.args.work, job["stats"])) as f:
                stats = json.load(f)
            r.update(render=stats["seconds"], rays=stats["rays"])
        elif status == "ok":
            r.update(pov_statistics(stderr))
        elif status != "timeout":
            r["stderr"] = stderr[-1000:]
        return r

    def image(self, job):
        image = images.read_image(os.path.join(self.args.work, job["image"]))
        return images.mirrored(image) if job.get("mirror") else image


def pov_statistics(stderr):
    """POV-Ray's own trace seconds and ray counts, from its closing statistics."""
    text = stderr.replace("\r", "\n")
    out = {}
    m = re.search(r"Trace Time:.*?\(([\d.]+) seconds\)", text)
    if m:
        out["trace"] = float(m.group(1))
    for key, label in (("rays", r"Rays:"), ("shadow_tests", r"Shadow Ray Tests:")):
        m = re.search(label + r"\s+([\d,]+)", text)
        if m:
            out[key] = int(m.group(1).replace(",", ""))
    return out


def pareto_front(points, key="wall"):
    """The points no other point beats on both time (key: wall or cpu seconds) and error,
    fastest first: for each error, the least time any setting needed to reach it."""
    front = []
    for p in sorted(points, key=lambda p: (p[key], p["error"])):
        if not front or p["error"] < front[-1]["error"]:
            front.append(p)
    return front


def time_to_reach(front, target, key="wall"):
    """Seconds to reach the target error, interpolated linearly in log(time) against
    log(error) between the two points of the front around it. Outside the front, extrapolated
    by Monte Carlo's error ~ time^(-1/2) from the point of the front that buys error cheapest
    (least time x error^2); the flag says so."""
    for a, b in zip(front, front[1:]):
        if a["error"] >= target >= b["error"]:
            la, lb = math.log(a["error"]), math.log(b["error"])
            s = (math.log(target) - la) / (lb - la)
            return math.exp((1 - s) * math.log(a[key]) + s * math.log(b[key])), False
    if len(front) == 1 and front[0]["error"] == target:
        return front[0][key], False
    cost = min(p[key] * p["error"] ** 2 for p in front)
    return cost / target ** 2, True


def reference(renders, job, args, results):
    """Renders a reference unless one with the same command is in the work folder already
    (with --reuse-references): a reference takes minutes."""
    meta_path = os.path.join(args.work, job["image"] + ".json")
    sources = [os.path.join(args.work, f) for f in ("scene.yaml", "scene.pov")]
    if args.reuse_references and os.path.exists(meta_path):
        with open(meta_path) as f:
            meta = json.load(f)
        fresh = os.path.getmtime(meta_path) >= max(os.path.getmtime(p) for p in sources)
        if meta["cmd"][1:] == job["cmd"][1:] and fresh:
            log("reusing the %s reference (%s)" % (job["renderer"], job["label"]))
            return meta
    log("rendering the %s reference (%s)" % (job["renderer"], job["label"]))
    r = renders.run(job)
    if r["status"] != "ok":
        raise SystemExit("the %s reference failed: %s %s" % (job["renderer"], r["status"],
                                                             r.get("stderr", "")))
    meta = {"cmd": job["cmd"], "label": job["label"], "run": r}
    with open(meta_path, "w") as f:
        json.dump(meta, f)
    results.write(json.dumps({"kind": "reference", "renderer": job["renderer"],
                              "label": job["label"], **r}) + "\n")
    log("  %.1f s" % r["wall"])
    return meta


def sweep_jobs(renders, args):
    glint = [renders.glint_job(spp, GLINT_SEED, "glint_%d" % spp) for spp in args.glint_spp]
    pov = []
    for blur in args.pov_blur:
        for area in args.pov_area:
            if blur * area * area > args.pov_budget:
                continue  # shadow rays that cost much and buy little: the noise is the lens's
            for adaptive in args.pov_adaptive:
                a = None if adaptive < 0 else adaptive
                name = "pov_b%d_n%d%s" % (blur, area, "" if a is None else "_a%d" % a)
                pov.append(renders.povray_job(blur, area, name, adaptive=a))
    # POV-Ray's adaptive focal blur: up to --pov-variance-blur rays a pixel, fewer where the
    # samples agree. It pays at the larger errors.
    for variance in args.pov_variance:
        pov.append(renders.povray_job(args.pov_variance_blur, 2, "pov_v%g" % (1 / variance),
                                      variance=variance))
    return glint, pov


def run_sweep(renders, jobs, args, results, refs):
    """Runs every job --repeat times, glint and POV-Ray interleaved (so that a change of load
    touches both), and measures each image's error against its renderer's reference."""
    order = []
    glint, pov = jobs
    for i in range(max(len(glint), len(pov))):
        order += glint[i:i + 1] + pov[i:i + 1]
    runs = {id(job): [] for job in order}
    for rep in range(args.repeat):
        for job in order:
            if runs[id(job)] and runs[id(job)][-1]["status"] != "ok":
                continue  # a failure or a timeout is not retried
            r = renders.run(job)
            runs[id(job)].append(r)
            idle = "" if r["idle_before"] is None else " (idle before: %.0f%%)" % (
                100 * r["idle_before"])
            log("  [%d/%d] %-6s %-26s %s %.2f s%s" % (rep + 1, args.repeat, job["renderer"],
                                                      job["label"], r["status"], r["wall"], idle))
    rows = []
    for job in order:
        ok = [r for r in runs[id(job)] if r["status"] == "ok"]
        best = min(ok, key=lambda r: r["wall"]) if ok else runs[id(job)][-1]
        row = {k: v for k, v in job.items() if k not in ("cmd",)}
        row.update(best=best, walls=[r["wall"] for r in runs[id(job)]])
        if ok:
            # The last run's image; repeated runs give the same image (POV-Ray's within 1e-4).
            row["error"] = images.rmse(renders.image(job), refs[job["renderer"]])
            row["wall"] = best["wall"]
            row["cpu"] = min(r["cpu"] for r in ok)
        rows.append(row)
        results.write(json.dumps({"kind": "sweep", **row}) + "\n")
        results.flush()
    return rows


def markdown_sweep(rows, front):
    on_front = {id(p) for p in front}
    out = ["| renderer | setting | wall s (best) | runs | CPU s | error (RMSE) | on front |",
           "|---|---|---:|---|---:|---:|---|"]
    for row in sorted(rows, key=lambda r: r["renderer"] != "glint"):  # glint's rows first
        runs = ", ".join("%.2f" % w for w in row["walls"])
        if "error" not in row:
            out.append("| %s | %s | — | %s | — | %s | |" % (
                row["renderer"], row["label"], runs, row["best"]["status"]))
            continue
        out.append("| %s | %s | %.2f | %s | %.2f | %.5f | %s |" % (
            "glint" if row["renderer"] == "glint" else "POV-Ray", row["label"], row["wall"],
            runs, row["cpu"], row["error"], "yes" if id(row) in on_front else ""))
    return "\n".join(out)


def parse_args():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog=__doc__.split("\n\n", 1)[1])
    ap.add_argument("--quick", action="store_true",
                    help="200 x 112, a short sweep and small references: checks that it works")
    ap.add_argument("--width", type=int, help="image width (default 480; --quick 200)")
    ap.add_argument("--height", type=int, help="image height (default 270; --quick 112)")
    ap.add_argument("--repeat", type=int, default=2,
                    help="runs of each sweep render; the fastest counts (default: %(default)s)")
    ap.add_argument("--glint-spp", type=int_list,
                    help="glint's sweep (default 4,8,16,32,64,128; --quick 4,16,64)")
    ap.add_argument("--pov-blur", type=int_list, help="POV-Ray's blur_samples "
                    "(default 4,8,16,32,64,128,256; --quick 4,16,64,128)")
    ap.add_argument("--pov-area", type=int_list,
                    help="POV-Ray's area light N, N x N points (default 2,4,8; --quick 2). "
                    "Powers of 2: POV-Ray's recursive average weighs other grids' points "
                    "unevenly")
    ap.add_argument("--pov-adaptive", type=int_list, default=[-1],
                    help="POV-Ray's area light adaptive levels to sweep as well, -1 for none "
                    "(every point tested; default: %(default)s)")
    ap.add_argument("--pov-budget", type=int, default=2048,
                    help="skip POV-Ray pairs with blur x N x N above this: shadow rays a "
                    "pixel (default: %(default)s)")
    ap.add_argument("--pov-variance", type=int_list,
                    help="POV-Ray's adaptive focal blur as well: each V here is a render with "
                    "variance 1/V (default 128,1024,8192; --quick 1024; 0 for none)")
    ap.add_argument("--pov-variance-blur", type=int, default=1024,
                    help="the most blur_samples of those renders (default: %(default)s)")
    ap.add_argument("--ref-spp", type=int, help="glint's reference (default 2048; --quick 512)")
    ap.add_argument("--ref-blur", type=int, help="POV-Ray's reference blur_samples "
                    "(default 2048; --quick 512)")
    ap.add_argument("--ref-area", type=int, default=2,
                    help="POV-Ray's reference area light N (default 2: at thousands of blur "
                    "samples a pixel, the light's noise is long gone)")
    ap.add_argument("--target-spp", type=int_list, default=[16, 64],
                    help="the target errors: those of glint at these spp (default 16,64)")
    ap.add_argument("--goal", type=float, default=5, help="speed-up to reach (✗ below)")
    ap.add_argument("--no-area-illumination", dest="area_illumination", action="store_false",
                    help="POV-Ray shades towards the area light's centre only (faster, and "
                    "further from glint's image)")
    ap.add_argument("--reuse-references", action="store_true",
                    help="keep reference images of the same commands from an earlier run")
    ap.add_argument("--min-idle", type=float, default=0.9,
                    help="before each render, wait until this share of the CPU time is idle "
                    "(0: do not wait; default: %(default)s)")
    ap.add_argument("--patience", type=float, default=300,
                    help="the longest wait for idle cores, seconds (default: %(default)s)")
    ap.add_argument("--timeout", type=float, default=3600, help="seconds a render may take")
    ap.add_argument("--glint", default=os.path.join(REPO, "build/release/apps/glint/glint"))
    ap.add_argument("--povray", default=shutil.which("povray") or "/usr/bin/povray")
    ap.add_argument("--work", default="/tmp/distributed_vs_povray",
                    help="images, results.jsonl (default: %(default)s)")
    args = ap.parse_args()

    quick = args.quick
    args.width = args.width or (200 if quick else 480)
    args.height = args.height or (112 if quick else 270)
    args.glint_spp = args.glint_spp or ([4, 16, 64] if quick else [4, 8, 16, 32, 64, 128])
    args.pov_blur = args.pov_blur or ([4, 16, 64, 128] if quick else [4, 8, 16, 32, 64, 128, 256])
    args.pov_area = args.pov_area or ([2] if quick else [2, 4, 8])
    if args.pov_variance is None:
        args.pov_variance = [1024] if quick else [128, 1024, 8192]
    args.pov_variance = [1 / v for v in args.pov_variance if v > 0]
    args.ref_spp = args.ref_spp or (512 if quick else 2048)
    args.ref_blur = args.ref_blur or (512 if quick else 2048)
    for spp in args.target_spp:
        if spp not in args.glint_spp:
            args.glint_spp = sorted(args.glint_spp + [spp])
    return args


def measure(args, results):
    """Renders the references and the sweep; returns everything the report needs."""
    glint = os.path.join(args.work, "bin", "glint")
    renders = Renders(args, glint, os.cpu_count())
    g_ref_job = renders.glint_job(args.ref_spp, GLINT_REFERENCE_SEED, "ref_glint")
    p_ref_job = renders.povray_job(args.ref_blur, args.ref_area, "ref_povray", mirror=True)
    m = {"references": {"glint": reference(renders, g_ref_job, args, results),
                        "povray": reference(renders, p_ref_job, args, results)}}
    refs = {"glint": renders.image(g_ref_job), "povray": renders.image(p_ref_job)}
    m["agreement"] = {"rmse": images.rmse(refs["glint"], refs["povray"]),
                      "rmse_clamped": images.rmse(refs["glint"], refs["povray"], clamp=1.0),
                      "mean_glint": images.mean(refs["glint"]),
                      "mean_povray": images.mean(refs["povray"])}
    results.write(json.dumps({"kind": "agreement", **m["agreement"]}) + "\n")
    images.write_difference_png(refs["glint"], refs["povray"],
                                os.path.join(args.work, "img", "ref_difference.png"))
    for name in ("glint", "povray"):
        images.write_png(refs[name], os.path.join(args.work, "img", "ref_%s.png" % name))

    m["rows"] = rows = run_sweep(renders, sweep_jobs(renders, args), args, results, refs)
    points = {name: [r for r in rows if r["renderer"] == name and "error" in r]
              for name in ("glint", "povray")}
    m["fronts"] = fronts = {(name, key): pareto_front(p, key) for name, p in points.items()
                            for key in ("wall", "cpu")}
    m["targets"] = []
    for spp in args.target_spp:
        g = next((r for r in points["glint"] if r["spp"] == spp), None)
        if g is None or not points["povray"]:
            continue
        t = {"spp": spp, "error": g["error"]}
        for key in ("wall", "cpu"):
            tg, g_extra = time_to_reach(fronts["glint", key], g["error"], key)
            tp, p_extra = time_to_reach(fronts["povray", key], g["error"], key)
            t[key] = {"glint": tg, "povray": tp, "ratio": tp / tg,
                      "extrapolated": g_extra or p_extra}
        m["targets"].append(t)
        results.write(json.dumps({"kind": "target", **t}) + "\n")

    # The references' own noise, from each sweep's most-sampled point: against a reference of
    # N samples drawn independently, an image of n samples has error^2 = s/n + s/N, s the
    # variance of one sample, and the reference's own share is s/N.
    m["noise"] = noise = {}
    if points["glint"]:
        g = max(points["glint"], key=lambda r: r["spp"])
        noise["glint"] = g["error"] * math.sqrt(g["spp"] / (g["spp"] + args.ref_spp))
    same_n = [r for r in points["povray"] if r["area"] == args.ref_area
              and r["adaptive"] is None and not r["variance"]]
    if same_n:
        p = max(same_n, key=lambda r: r["blur"])
        noise["povray"] = p["error"] * math.sqrt(p["blur"] / (p["blur"] + args.ref_blur))
    # Independent noise adds in squares; what it leaves is the renderers' difference.
    m["systematic"] = None
    if len(noise) == 2:
        rest = m["agreement"]["rmse"] ** 2 - noise["glint"] ** 2 - noise["povray"] ** 2
        m["systematic"] = math.sqrt(max(rest, 0))
    results.write(json.dumps({"kind": "summary", "reference_noise": noise,
                              "systematic_difference": m["systematic"]}) + "\n")
    return m


def report(args, m, load, elapsed):
    print("## References (%d × %d)\n" % (args.width, args.height))
    print("| renderer | setting | wall s | estimated own noise (RMSE) |")
    print("|---|---|---:|---:|")
    noise = m["noise"]
    for name, title in (("glint", "glint"), ("povray", "POV-Ray")):
        ref = m["references"][name]
        print("| %s | %s | %.1f | %s |" % (title, ref["label"], ref["run"]["wall"],
                                         "%.5f" % noise[name] if name in noise else "—"))
    a = m["agreement"]
    print("\nThe two references differ by an RMSE of %.5f in linear RGB (%.5f clamped to "
          "[0, 1]); mean values %.5f (glint) and %.5f (POV-Ray)."
          % (a["rmse"], a["rmse_clamped"], a["mean_glint"], a["mean_povray"]))
    if m["systematic"] is not None:
        print("Their own noise accounts for %.5f of it; the systematic difference is about "
              "%.5f." % (math.hypot(noise["glint"], noise["povray"]), m["systematic"]))
    print("\n## Sweep (best of %d; error against the renderer's own reference)\n" % args.repeat)
    print(markdown_sweep(m["rows"], m["fronts"]["glint", "wall"] + m["fronts"]["povray", "wall"]))
    print("\n## Time to equal error\n")
    print("| target error | = glint at | glint s | POV-Ray s | POV-Ray / glint | "
          "CPU-time ratio |")
    print("|---:|---:|---:|---:|---:|---:|")
    for t in m["targets"]:
        w, c = t["wall"], t["cpu"]
        print("| %.5f | %d spp | %.2f | %.2f%s | %.1f×%s | %.1f× |" % (
            t["error"], t["spp"], w["glint"], w["povray"],
            " (extrapolated)" if w["extrapolated"] else "", w["ratio"],
            "" if w["ratio"] >= args.goal else " ✗", c["ratio"]))
    print("\n%d × %d, %d cores, load %.2f before the run; the whole run took %.0f s. "
          "Results in %s." % (args.width, args.height, os.cpu_count(), load, elapsed,
                              os.path.join(args.work, "results.jsonl")))


def main():
    args = parse_args()
    args.work = os.path.abspath(args.work)
    for sub in ("img", "bin"):
        os.makedirs(os.path.join(args.work, sub), exist_ok=True)
    # One build for the whole run, whatever happens to the tree meanwhile; POV-Ray may only
    # read and write in its working folder, so the scenes go there too.
    shutil.copy2(args.glint, os.path.join(args.work, "bin", "glint"))
    for f in ("scene.yaml", "scene.pov"):
        shutil.copy2(os.path.join(HERE, f), os.path.join(args.work, f))
    started = time.perf_counter()
    load = os.getloadavg()[0]
    with open(os.path.join(args.work, "results.jsonl"), "a") as results:
        results.write(json.dumps({
            "kind": "run", "date": datetime.datetime.now().isoformat(timespec="seconds"),
            "argv": sys.argv[1:], "width": args.width, "height": args.height,
            "cores": os.cpu_count(), "load_before": round(load, 2)}) + "\n")
        m = measure(args, results)
    report(args, m, load, time.perf_counter() - started)


if __name__ == "__main__":
    main()
