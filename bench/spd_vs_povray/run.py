#!/usr/bin/env python3
"""Whole renders of the SPD databases: glint against POV-Ray 3.7, same machine, same run.

    bench/spd_vs_povray/run.py                   # every SPD file up to ~1 million primitives
    bench/spd_vs_povray/run.py --quick           # five small files, under a minute
    bench/spd_vs_povray/run.py tetra teapot-s60  # names in the data folder, or NFF paths

Each NFF file is converted once by nff2pov.py (cached in the work folder) and then rendered on
every core, alternately, N times each (--repeat, 3; --repeat-large, 1, from 100,000 primitives):

    glint render FILE.nff -o g.png --width 512 --height 512 --spp 1 --max-depth 5
                          --threads 0 --quiet --stats g.json
    povray +IFILE.pov +Op.png +W512 +H512 -A -D +WT<cores>     (in the work folder)

A time is the whole command's wall time (read or parse, build, render, write the image), the
fastest of the N runs; a command that runs past --timeout is stopped and reported as "> T".
The table also gives the ratio of the two commands' CPU times (user + system), which other
jobs on the machine disturb less, and the renderers' own figures: glint's render time, POV-Ray's
parse and trace times. compare.py then checks that the two images agree. Prints a Markdown
table and writes every measurement as a JSON line (results.jsonl in the work folder).
"""

import argparse
import datetime
import glob
import json
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
import compare  # noqa: E402
import nff2pov  # noqa: E402
from timing import timed  # noqa: E402

# The shared data beside the repository, as ../shared/data is for the C++ benchmarks.
DATA = os.path.join(os.path.dirname(REPO), "shared", "data", "spd")
QUICK = ["jacks", "sombrero", "tetra", "teapot", "balls"]
LARGE = 100000  # primitives from which --repeat-large applies


def log(msg):
    print(msg, file=sys.stderr, flush=True)


def scene_name(path):
    base = os.path.basename(path)
    return base[:-len(".nff.gz")] if base.endswith(".nff.gz") else os.path.splitext(base)[0]


def find_scenes(names, data):
    if not names:
        return sorted(glob.glob(os.path.join(data, "*.nff")) +
                      glob.glob(os.path.join(data, "*.nff.gz")))
    paths = []
    for name in names:
        candidates = [name, os.path.join(data, name + ".nff"), os.path.join(data, name + ".nff.gz")]
        found = [p for p in candidates if os.path.isfile(p)]
        if not found:
            raise SystemExit("no NFF file %r (nor %s.nff[.gz] in %s)" % (name, name, data))
        paths.append(found[0])
    return paths


def convert(nff, work):
    """The POV-Ray scene of nff (converted when missing or older than its sources), and facts
    about it: primitive counts and the background."""
    pov = os.path.join(work, "pov", scene_name(nff) + ".pov")
    meta_path = pov + ".json"
    newest = max(os.path.getmtime(p) for p in (nff, nff2pov.__file__))
    if os.path.exists(meta_path) and os.path.getmtime(meta_path) >= newest:
        with open(meta_path) as f:
            return pov, json.load(f)
    log("converting %s" % nff)
    t0 = time.perf_counter()
    with open(pov, "w", encoding="ascii", buffering=1 << 20) as out:
        counts = nff2pov.convert(nff, out)
    background = [0.0, 0.0, 0.0]
    with nff2pov.open_nff(nff) as f:
        for line in f:
            if line.startswith("b "):
                background = [float(x) for x in line.split()[1:4]]
                break
            if line.startswith(("s ", "p ", "pp ", "c ")):
                break
    meta = {"nff": nff, "counts": counts, "background": background,
            "primitives": sum(v for k, v in counts.items() if k != "mesh2"),
            "convert_seconds": round(time.perf_counter() - t0, 2)}
    with open(meta_path, "w") as f:
        json.dump(meta, f)
    return pov, meta


def pov_statistics(stderr):
    """POV-Ray's own parse, bounding and trace seconds, from its closing statistics."""
    text = stderr.replace("\r", "\n")
    times = {}
    for key, label in (("parse", "Parse Time"), ("bounding", "Bounding Time"),
                       ("trace", "Trace Time")):
        m = re.search(label + r":.*?\(([\d.]+) seconds\)", text)
        if m:
            times[key] = float(m.group(1))
    return times


def best_of(runs):
    ok = [r for r in runs if r["status"] == "ok"]
    return min(ok, key=lambda r: r["wall"]) if ok else runs[-1]


def run_scene(nff, args, glint, cores):
    name = scene_name(nff)
    pov, meta = convert(nff, args.work)
    g_img, g_stats = os.path.join("img", name + "_glint.png"), os.path.join("img", name + "_glint.json")
    p_img = os.path.join("img", name + "_povray.png")
    size = str(args.size)
    glint_cmd = [glint, "render", os.path.abspath(nff), "-o", g_img, "--width", size,
                 "--height", size, "--spp", "1", "--max-depth", "5", "--threads", "0",
                 "--quiet", "--stats", g_stats]
    # POV-Ray may only read and write in its working folder: run it there, with relative paths.
    pov_cmd = [args.povray, "+I" + os.path.relpath(pov, args.work), "+O" + p_img, "+W" + size,
               "+H" + size, "-A", "-D", "+WT%d" % cores]
    runs = {"glint": [], "povray": []}
    load = os.getloadavg()[0]
    repeat = args.repeat if meta["primitives"] < LARGE else args.repeat_large
    for _ in range(repeat):  # alternating, so that a change in load touches both
        for renderer, cmd in (("glint", glint_cmd), ("povray", pov_cmd)):
            if runs[renderer] and runs[renderer][-1]["status"] != "ok":
                continue  # a failure or a timeout is not retried
            status, wall, cpu, stderr = timed(cmd, args.timeout, cwd=args.work)
            r = {"status": status, "wall": wall, "cpu": cpu}
            if status == "ok" and renderer == "glint":
                with open(os.path.join(args.work, g_stats)) as f:
                    stats = json.load(f)
                r.update(render=stats["seconds"], rays=stats["rays"]["total"])
            elif status == "ok":
                r.update(pov_statistics(stderr))
            elif status != "timeout":
                r["stderr"] = stderr[-1000:]
            runs[renderer].append(r)
            log("  %-12s %-6s %s %.2f s" % (name, renderer, status, wall))
    g, p = best_of(runs["glint"]), best_of(runs["povray"])
    row = {"scene": name, "primitives": meta["primitives"], "counts": meta["counts"],
           "glint": g, "povray": p, "runs": repeat, "threads": cores,
           "load_before": round(load, 2), "date": datetime.datetime.now().isoformat(timespec="seconds")}
    if g["status"] == "ok" and p["status"] == "ok":
        row["speedup"] = p["wall"] / g["wall"]
        row["images"] = compare.compare(os.path.join(args.work, g_img),
                                        os.path.join(args.work, p_img), meta["background"])
    elif g["status"] == "ok" and p["status"] == "timeout":
        row["speedup_at_least"] = p["wall"] / g["wall"]
    return row


def seconds(r):
    if r["status"] == "timeout":
        return "> %.0f (timeout)" % r["wall"]
    if r["status"] != "ok":
        return r["status"]
    return "%.2f" % r["wall"]


def markdown(rows, target):
    out = ["| scene | primitives | glint s | POV-Ray s | speed-up (POV/glint) | CPU-time ratio "
           "| glint render s | POV parse s | POV trace s | masks agree | pixels within 16/255 |",
           "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for row in rows:
        g, p = row["glint"], row["povray"]
        if "speedup" in row:
            s = "%.1f×" % row["speedup"]
            s = s if row["speedup"] >= target else s + " ✗"
        elif "speedup_at_least" in row:
            s = "> %.1f×" % row["speedup_at_least"]
        else:
            s = "—"
        img = row.get("images")
        cpu = "%.1f×" % (p["cpu"] / g["cpu"]) if "speedup" in row and g.get("cpu") else "—"
        out.append("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            row["scene"], "{:,}".format(row["primitives"]), seconds(g), seconds(p), s, cpu,
            "%.2f" % g["render"] if "render" in g else "—",
            "%.2f" % p["parse"] if "parse" in p else "—",
            "%.2f" % p["trace"] if "trace" in p else "—",
            "%.2f%%" % (100 * img["mask_agreement"]) if img else "—",
            "%.2f%%" % (100 * img["close_pixels"]) if img else "—"))
    return "\n".join(out)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog=__doc__.split("\n\n", 1)[1])
    ap.add_argument("scenes", nargs="*", help="NFF files, or names of files in --data "
                    "(default: all of them, up to --max-primitives)")
    ap.add_argument("--quick", action="store_true", help="only " + ", ".join(QUICK))
    ap.add_argument("--data", default=DATA, help="the SPD's NFF files (default: %(default)s)")
    ap.add_argument("--max-primitives", type=float, default=1.1e6,
                    help="skip larger files (default: %(default)g, which keeps tetra-s10)")
    ap.add_argument("--repeat", type=int, default=3,
                    help="runs of each renderer; the fastest counts (default: %(default)s)")
    ap.add_argument("--repeat-large", type=int, default=1,
                    help="the same for files of %d primitives or more (default: %%(default)s)" % LARGE)
    ap.add_argument("--timeout", type=float, default=600,
                    help="seconds a render may take (default: %(default)s)")
    ap.add_argument("--size", type=int, default=512, help="image width and height")
    ap.add_argument("--glint", default=os.path.join(REPO, "build/release/apps/glint/glint"))
    ap.add_argument("--povray", default=shutil.which("povray") or "/usr/bin/povray")
    ap.add_argument("--work", default="/tmp/spd_vs_povray",
                    help="converted scenes, images, results.jsonl (default: %(default)s)")
    ap.add_argument("--target", type=float, default=5, help="speed-up to reach (marked ✗ below)")
    args = ap.parse_args()

    args.work = os.path.abspath(args.work)
    for sub in ("pov", "img", "bin"):
        os.makedirs(os.path.join(args.work, sub), exist_ok=True)
    # One build for the whole run, whatever happens to the tree meanwhile.
    glint = os.path.join(args.work, "bin", "glint")
    shutil.copy2(args.glint, glint)
    cores = os.cpu_count()
    nffs = find_scenes(QUICK if args.quick and not args.scenes else args.scenes, args.data)

    rows = []
    with open(os.path.join(args.work, "results.jsonl"), "a") as results:
        for nff in nffs:
            pov, meta = convert(nff, args.work)
            if meta["primitives"] > args.max_primitives:
                log("skipping %s: %d primitives" % (nff, meta["primitives"]))
                continue
            row = run_scene(nff, args, glint, cores)
            results.write(json.dumps(row) + "\n")
            results.flush()
            rows.append(row)
    rows.sort(key=lambda r: (re.sub(r"-s\d+$", "", r["scene"]), r["primitives"]))
    print(markdown(rows, args.target))
    met = sum(1 for r in rows if r.get("speedup", r.get("speedup_at_least", 0)) >= args.target)
    print("\n%d of %d scenes at least %g× faster in glint; %d cores; the fastest of %d run(s) "
          "each, of %d from %d primitives." % (met, len(rows), args.target, cores, args.repeat,
                                                args.repeat_large, LARGE))


if __name__ == "__main__":
    main()
