#!/usr/bin/env python3
"""Census of POV-Ray's sample scenes (Debian's povray-examples) as glint reads them.

Reads every .pov file under the scenes folder with `glint info` and sorts them into those glint
reads and those it refuses, tallying what each refusal names first (the feature not read yet,
or the error). Prints a markdown table for bench/README.md.

    bench/povray_scenes/census.py [--glint build/release/apps/glint/glint]
        [--scenes /usr/share/povray-3.7/scenes] [--jobs 2]
"""
import argparse
import collections
import concurrent.futures
import pathlib
import re
import subprocess

NOT_READ = [
    re.compile(r'POV-Ray\'s (\w+) is not supported'),
    re.compile(r'"(\w+)" is not supported'),
    re.compile(r'(#\w+) is not supported'),
]


def read(glint, scene):
    """('reads', '') or ('refused', what), from `glint info` on the scene."""
    try:
        run = subprocess.run([glint, 'info', str(scene)], capture_output=True, text=True,
                             timeout=60, cwd=scene.parent)
    except subprocess.TimeoutExpired:
        return 'refused', 'took over 60 s'
    if run.returncode == 0:
        return 'reads', ''
    message = next((line for line in run.stderr.splitlines() if 'error:' in line), run.stderr)
    message = message.split('error:', 1)[-1].strip()
    for pattern in NOT_READ:
        found = pattern.search(message)
        if found:
            return 'refused', found.group(1)
    return 'refused', 'other: ' + re.sub(r'"[^"]*"', '"…"', message)[:60]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--glint', default='build/release/apps/glint/glint')
    parser.add_argument('--scenes', default='/usr/share/povray-3.7/scenes')
    parser.add_argument('--jobs', type=int, default=2)
    args = parser.parse_args()
    glint = str(pathlib.Path(args.glint).resolve())
    scenes = sorted(pathlib.Path(args.scenes).resolve().rglob('*.pov'))
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        results = list(pool.map(lambda s: read(glint, s), scenes))
    reads = sum(1 for kind, _ in results if kind == 'reads')
    refusals = collections.Counter(what for kind, what in results if kind == 'refused')
    print(f'{len(scenes)} scenes: glint reads {reads}, refuses {len(scenes) - reads}\n')
    print('| what the refusal names first | scenes |')
    print('|---|---:|')
    for what, count in refusals.most_common():
        print(f'| {what} | {count} |')


if __name__ == '__main__':
    main()
