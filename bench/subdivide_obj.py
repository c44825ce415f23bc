#!/usr/bin/env python3
"""Splits every triangle of an OBJ mesh into four at its edges' midpoints, N times over: a mesh of
the same shape with 4^N times the triangles, to measure builds and traversal on meshes of a
million triangles and more from the shared ones. Faces with more corners are fanned first;
normals and texture coordinates are dropped.

    bench/subdivide_obj.py ../shared/data/meshes/stanford-bunny.obj /tmp/bunny-1m.obj --times 2
"""
import argparse


def read_obj(path):
    vertices, triangles = [], []
    with open(path) as f:
        for line in f:
            fields = line.split()
            if not fields:
                continue
            if fields[0] == "v":
                vertices.append(tuple(float(x) for x in fields[1:4]))
            elif fields[0] == "f":
                corners = [int(c.split("/")[0]) for c in fields[1:]]
                corners = [c - 1 if c > 0 else len(vertices) + c for c in corners]
                for k in range(1, len(corners) - 1):
                    triangles.append((corners[0], corners[k], corners[k + 1]))
    return vertices, triangles


def subdivide(vertices, triangles):
    midpoints = {}

    def midpoint(a, b):
        edge = (min(a, b), max(a, b))
        if edge not in midpoints:
            vertices.append(tuple((x + y) / 2 for x, y in zip(vertices[a], vertices[b])))
            midpoints[edge] = len(vertices) - 1
        return midpoints[edge]

    out = []
    for a, b, c in triangles:
        ab, bc, ca = midpoint(a, b), midpoint(b, c), midpoint(c, a)
        out += [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("input")
    parser.add_argument("output")
    parser.add_argument("--times", type=int, default=1, help="how often to subdivide (default 1)")
    args = parser.parse_args()
    vertices, triangles = read_obj(args.input)
    for _ in range(args.times):
        triangles = subdivide(vertices, triangles)
    with open(args.output, "w") as f:
        for v in vertices:
            f.write("v %.6f %.6f %.6f\n" % v)
        for a, b, c in triangles:
            f.write("f %d %d %d\n" % (a + 1, b + 1, c + 1))
    print(f"{args.output}: {len(vertices)} vertices, {len(triangles)} triangles")


if __name__ == "__main__":
    main()
