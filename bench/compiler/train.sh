#!/usr/bin/env bash
# PGO's training run (README.md): scenes of every kind at small sizes, none of those that
# compare_builds.py times. Usage: train.sh path/to/instrumented/glint
set -euo pipefail
G=$(realpath "$1")
cd "$(dirname "$0")/../.."
D=../shared/data
O=$(mktemp -d)
trap 'rm -rf "$O"' EXIT
for f in reflection refraction soft-shadows glossy depth-of-field motion-blur colour-bleeding \
    meshes csg quadrics textures fog caustics translucency dispersion; do
    "$G" render "scenes/features/$f.yaml" -o "$O/f.png" --width 200 --height 150 --quiet
done
for s in tetra teapot mount sombrero jacks lattice tree shells; do
    "$G" render "$D/spd/$s.nff" -o "$O/s.png" --width 256 --height 256 --quiet
done
"$G" render "$D/meshes/suzanne.obj" -o "$O/m.png" --width 256 --height 256 --quiet
