#!/usr/bin/env python3
"""Convert an NFF file (plain or gzip) to a POV-Ray 3.7 scene of the same database, as glint
renders it (docs/nff.md, src/glint/scene/nff/nff_to_scene.cpp), so that the two renderers can
be timed on the same work and their images compared.

    nff2pov.py balls.nff balls.pov
    nff2pov.py tetra-s10.nff.gz - > tetra-s10.pov

The file is read as a stream of tokens (the SPD writes a cone's 8 numbers on its `c` line and
`b` before `v`), and objects are written as they come; triangles wait in temporary files until
the end, so a million primitives take no more memory than a few. The mapping, entity by entity:

- `v`: a perspective camera with explicit vectors, as glint builds it: `direction` the unit view
  vector, `right` = direction x up (right-handed, as in glint; POV-Ray takes explicit vectors as
  given) and `up` = right x direction, scaled by 2 tan(angle / 2) (times the aspect for
  `right`): `angle` is the full edge-to-edge angle. `hither` is ignored, as glint does.
- ray tree: `max_trace_level 5` (the eye ray is level 1 in both) and `adc_bailout 0`;
  `assumed_gamma 1` (colours are linear, as in glint; both write sRGB PNGs).
- `b`: `background`; black when absent.
- `l` (N lights): point lights of intensity sqrt(N) / 2N (times the light's colour when given),
  no fading; the same ambient light: `ambient_light 1` and `ambient Kd * sqrt(N) / 2N`.
- `f r g b Kd Ks Shine T ior`: one declared material per distinct `f` (lattice repeats its `f`
  before every object): `pigment { rgb }` (`rgbt` with transmit T where T > 0), `diffuse Kd`,
  `phong Ks phong_size Shine` ((R.V)^n, like glint's; none where Shine is 100000),
  `reflection Ks` (uncoloured, like glint's), `interior { ior }` where T > 0. POV-Ray scales
  the ambient and diffuse terms of a transmitting pigment by (1 - T) and glint does not, so both
  are divided by (1 - T). Where T > 0 and Ks = 0 (the gears' glass), `reflection` is the
  head-on Fresnel reflectance ((ior - 1) / (ior + 1))^2, as in glint.
- `s`: `sphere`. `c`: `cylinder { ... open }` for equal radii, else `cone { ... open }`.
- `p` with more than 3 vertices: `polygon`, the first vertex repeated to close it (POV-Ray's
  inside test is even-odd, so the gears' concave 144-gons work, as in glint).
- `p` with 3 vertices and `pp` (a fan if ever more than 3 vertices): triangles, gathered as
  glint gathers them, into one `mesh2` per material and kind (flat, or smooth with the vertex
  normals). mesh2 is what POV-Ray parses fastest, and each mesh has its own bounding hierarchy.
- transmitting objects (T > 0) of one material: one declared union (or mesh2), used twice (see
  write_glass): as glass that casts no shadow, and as an opaque copy that only shadow rays see.
  So shadows are opaque, as glint's NFF shadows are, and a ray leaving a gear through another
  polygon than it entered by is seen to leave, as glint sees it by the side of the surface.

Differences that remain (see README.md): POV-Ray decides whether a ray enters or leaves glass by
the objects it is inside, glint by the side of the surface, so overlapping glass of one material
would differ (no SPD file has it); with T = 1 POV-Ray has no diffuse term at all (no SPD file
has it); 1-pixel differences where the two renderers' rounding picks different tiny objects.
"""

import argparse
import gzip
import math
import os
import shutil
import sys
import tempfile

NO_HIGHLIGHT_SHINE = 100000.0  # the SPD's Shine for "no highlight"


class NffError(Exception):
    pass


def open_nff(path):
    """A text stream of an NFF file; gzip is recognised by its magic bytes, as glint does."""
    with open(path, "rb") as f:
        gzipped = f.read(2) == b"\x1f\x8b"
    if gzipped:
        return gzip.open(path, "rt", encoding="ascii")
    return open(path, "r", encoding="ascii")


class Tokens:
    """The whitespace-separated tokens of a stream, `#` comments removed, with a look-ahead."""

    def __init__(self, stream):
        self._it = (t for line in stream for t in line.split("#", 1)[0].split())
        self._ahead = []

    def __iter__(self):
        return self

    def __next__(self):
        return self._ahead.pop() if self._ahead else next(self._it)

    def peek(self):
        if not self._ahead:
            self._ahead.append(next(self._it, None))
        return self._ahead[-1]

    def take(self, what):
        t = next(self, None)
        if t is None:
            raise NffError("the file ends inside %s" % what)
        return t

    def number(self, what):
        t = self.take(what)
        try:
            return float(t)
        except ValueError:
            raise NffError("expected a number in %s, got %r" % (what, t)) from None

    def point(self, what):
        """"<x,y,z>" with the numbers as written (checked), so nothing is lost to formatting."""
        xs = [self.take(what) for _ in range(3)]
        for x in xs:
            try:
                float(x)
            except ValueError:
                raise NffError("expected a number in %s, got %r" % (what, x)) from None
        return "<%s,%s,%s>" % tuple(xs)


def is_number(t):
    try:
        float(t)
        return True
    except (TypeError, ValueError):
        return False


def g(x):
    return "%.9g" % x


def vec(v):
    return "<%s,%s,%s>" % (g(v[0]), g(v[1]), g(v[2]))


def vec_exact(v):
    # Full precision: POV-Ray checks that the camera's vectors are perpendicular.
    return "<%r,%r,%r>" % tuple(float(x) for x in v)


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def normalize(a):
    n = math.sqrt(sum(x * x for x in a))
    if n == 0:
        raise NffError("the view has a zero-length direction or an up along it")
    return tuple(x / n for x in a)


def scale(a, s):
    return tuple(x * s for x in a)


class MeshRun:
    """The triangles of one material and kind, kept in temporary files until the end."""

    def __init__(self, smooth):
        self.count = 0
        self.vertices = tempfile.TemporaryFile("w+", encoding="ascii")
        self.normals = tempfile.TemporaryFile("w+", encoding="ascii") if smooth else None

    def write(self, out, material):
        """The mesh2; material is " material{M}" or "" (for an object{} to give it one)."""
        n = self.count
        out.write("mesh2{vertex_vectors{%d,\n" % (3 * n))
        self.vertices.seek(0)
        shutil.copyfileobj(self.vertices, out)
        out.write("}\n")
        if self.normals:
            # Without normal_indices, face_indices index the normals too.
            out.write("normal_vectors{%d,\n" % (3 * n))
            self.normals.seek(0)
            shutil.copyfileobj(self.normals, out)
            out.write("}\n")
        out.write("face_indices{%d,\n" % n)
        out.writelines("<%d,%d,%d>,\n" % (i, i + 1, i + 2) for i in range(0, 3 * n, 3))
        out.write("}%s}\n" % material)
        self.vertices.close()
        if self.normals:
            self.normals.close()


def write_glass(out, shape, material):
    """The two instances of a declared transmitting shape. POV-Ray's shadow rays pass through
    transmitting surfaces, attenuated by T, where glint's NFF shadows are opaque: so the glass
    casts no shadow, and an opaque copy that only shadow rays see casts it instead. One
    material{} for the whole shape also gives it one interior, so that POV-Ray, which decides
    whether a ray enters or leaves by the interiors it is inside, sees a ray that enters a gear
    through one polygon leave it through another."""
    out.write("object{%s material{%s} no_shadow}\n" % (shape, material))
    out.write("object{%s pigment{rgb 0} no_image no_reflection}\n" % shape)


class Converter:
    def __init__(self):
        self.view = None
        self.background = (0.0, 0.0, 0.0)
        self.lights = []       # (position, colour or None)
        self.materials = {}    # distinct f values -> name (M1, M2, ...), in order of appearance
        self.transmitting = set()  # the names of materials with T > 0
        self.current = None    # the name of the last f's material
        self.body = tempfile.TemporaryFile("w+", encoding="ascii")  # opaque objects
        self.glass = {}        # transmitting material -> [temporary file, count] of its objects
        self.meshes = {}       # (material, smooth) -> MeshRun, in order of appearance
        self.counts = dict.fromkeys(("sphere", "cylinder", "cone", "polygon", "triangle",
                                     "smooth_triangle", "mesh2"), 0)

    def set_material(self, f):
        # One declaration for each distinct f: lattice repeats its f before every object, and
        # 270,000 declarations would cost POV-Ray more to parse than the objects themselves.
        name = self.materials.setdefault(f, "M%d" % (len(self.materials) + 1))
        if f[6] > 0:
            self.transmitting.add(name)
        self.current = name

    def material_name(self, what):
        if self.current is None:
            raise NffError('a %s before any material: an "f" line must come first' % what)
        return self.current

    def add(self, kind, text):
        """One object other than a triangle; text has a %s where its material goes."""
        name = self.material_name(kind)
        self.counts[kind] += 1
        if name not in self.transmitting:
            self.body.write(text % (" material{%s}" % name))
            return
        group = self.glass.get(name)
        if group is None:
            group = self.glass[name] = [tempfile.TemporaryFile("w+", encoding="ascii"), 0]
        group[0].write(text % "")
        group[1] += 1

    def add_triangle(self, vertices, normals=None):
        key = (self.material_name("triangle"), normals is not None)
        run = self.meshes.get(key)
        if run is None:
            run = self.meshes[key] = MeshRun(normals is not None)
        run.count += 1
        run.vertices.write("%s,%s,%s,\n" % tuple(vertices))
        if normals:
            run.normals.write("%s,%s,%s,\n" % tuple(normals))
        self.counts["smooth_triangle" if normals else "triangle"] += 1

    def write(self, out):
        if self.view is None:
            raise NffError("the file has no view (v)")
        v = self.view
        n = max(1, len(self.lights))
        intensity = math.sqrt(n) / (2 * n)  # each light's and the ambient light's (SPD README)
        w = out.write
        w("// Converted from NFF by bench/spd_vs_povray/nff2pov.py: the database as glint renders it.\n")
        w("#version 3.7;\n")
        w("global_settings { max_trace_level 5 adc_bailout 0 assumed_gamma 1 ambient_light 1 }\n")
        direction = normalize(sub(v["at"], v["from"]))
        right = normalize(cross(direction, v["up"]))
        up = cross(right, direction)
        h = 2 * math.tan(math.radians(v["angle"]) / 2)
        w("camera { perspective location %s direction %s right %s up %s }\n" % (
            vec(v["from"]), vec_exact(direction), vec_exact(scale(right, h * v["aspect"])),
            vec_exact(scale(up, h))))
        w("background { rgb %s }\n" % vec(self.background))
        for position, colour in self.lights:
            w("light_source { %s rgb %s }\n" % (vec(position),
                                                vec(scale(colour or (1, 1, 1), intensity))))
        for f, name in self.materials.items():
            w("#declare %s = %s\n" % (name, pov_material(f, intensity)))
        self.body.seek(0)
        shutil.copyfileobj(self.body, out)
        self.body.close()
        for name, (objects, count) in self.glass.items():
            objects.seek(0)
            w("#declare Glass%s = %s" % (name, "union{\n" if count > 1 else ""))
            shutil.copyfileobj(objects, out)
            w("}\n" if count > 1 else "")
            objects.close()
            write_glass(out, "Glass" + name, name)
        for (name, smooth), run in self.meshes.items():
            if name in self.transmitting:
                shape = "Mesh%s%s" % (name, "s" if smooth else "")
                w("#declare %s = " % shape)
                run.write(out, "")
                write_glass(out, shape, name)
            else:
                run.write(out, " material{%s}" % name)
            self.counts["mesh2"] += 1


def pov_material(f, ambient_light):
    """A POV-Ray material for an NFF `f` (glint's to_material in nff_to_scene.cpp)."""
    r, gr, b, kd, ks, shine, t, ior = f
    t = min(t, 1.0)
    # POV-Ray scales the ambient and diffuse terms of a transmitting pigment by (1 - T).
    opacity = 1 - t if 0 < t < 1 else 1
    finish = "ambient %s diffuse %s" % (g(kd * ambient_light / opacity), g(kd / opacity))
    if shine < NO_HIGHLIGHT_SHINE and ks > 0:
        finish += " phong %s phong_size %s" % (g(ks), g(shine))
    reflection = min(ks, 1.0)
    if t > 0 and reflection == 0:
        reflection = ((ior - 1) / (ior + 1)) ** 2  # head-on Fresnel reflectance
    if reflection > 0:
        finish += " reflection %s" % g(reflection)
    if t > 0:
        return ("material { texture { pigment { rgbt <%s,%s,%s,%s> } finish { %s } } "
                "interior { ior %s } }" % (g(r), g(gr), g(b), g(t), finish, g(ior)))
    return "material { texture { pigment { rgb <%s,%s,%s> } finish { %s } } }" % (
        g(r), g(gr), g(b), finish)


def parse(stream, conv):
    tok = Tokens(stream)
    for keyword in tok:
        if keyword == "v":
            view = {}
            for line in ("from", "at", "up", "angle", "hither", "resolution"):
                if tok.take("the view") != line:
                    raise NffError("the view's lines must be from, at, up, angle, hither, "
                                   "resolution; expected %r" % line)
                if line in ("from", "at", "up"):
                    view[line] = tuple(tok.number(line) for _ in range(3))
                elif line == "resolution":
                    width, height = tok.number(line), tok.number(line)
                    view["aspect"] = width / height
                else:
                    view[line] = tok.number(line)
            conv.view = view
        elif keyword == "b":
            conv.background = tuple(tok.number("the background") for _ in range(3))
        elif keyword == "l":
            position = tuple(tok.number("a light") for _ in range(3))
            colour = None
            if is_number(tok.peek()):
                colour = tuple(tok.number("a light's colour") for _ in range(3))
            conv.lights.append((position, colour))
        elif keyword == "f":
            conv.set_material(tuple(tok.number("a material") for _ in range(8)))
        elif keyword == "s":
            c = tok.point("a sphere")
            r = tok.number("a sphere")
            conv.add("sphere", "sphere{%s,%s%%s}\n" % (c, g(r)))
        elif keyword == "c":
            base, br = tok.point("a cone"), tok.number("a cone")
            apex, ar = tok.point("a cone"), tok.number("a cone")
            if br == ar:
                conv.add("cylinder", "cylinder{%s,%s,%s open%%s}\n" % (base, apex, g(br)))
            else:
                conv.add("cone", "cone{%s,%s,%s,%s open%%s}\n" % (
                    base, g(br), apex, g(ar)))
        elif keyword == "p":
            n = int(tok.number("a polygon"))
            if n < 3:
                raise NffError("a polygon with %d vertices" % n)
            vs = [tok.point("a polygon") for _ in range(n)]
            if n == 3:
                conv.add_triangle(vs)
            else:
                conv.add("polygon", "polygon{%d,%s,%s%%s}\n" % (
                    n + 1, ",".join(vs), vs[0]))
        elif keyword == "pp":
            n = int(tok.number("a patch"))
            if n < 3:
                raise NffError("a patch with %d vertices" % n)
            vs, ns = [], []
            for _ in range(n):
                vs.append(tok.point("a patch"))
                ns.append(tok.point("a patch's normal"))
            for i in range(1, n - 1):
                conv.add_triangle([vs[0], vs[i], vs[i + 1]], [ns[0], ns[i], ns[i + 1]])
        else:
            raise NffError("unknown entity %r" % keyword)


def convert(nff_path, out):
    """Writes the POV-Ray scene of nff_path to the text stream out; returns the object counts."""
    conv = Converter()
    with open_nff(nff_path) as stream:
        parse(stream, conv)
    conv.write(out)
    return conv.counts


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("nff", help="NFF file, plain or gzip")
    ap.add_argument("pov", help="POV-Ray scene to write ('-': standard output)")
    args = ap.parse_args(argv)
    out = sys.stdout if args.pov == "-" else open(args.pov, "w", encoding="ascii",
                                                  buffering=1 << 20)
    try:
        counts = convert(args.nff, out)
    except NffError as e:
        print("%s: error: %s" % (args.nff, e), file=sys.stderr)
        if out is not sys.stdout:
            out.close()
            os.remove(args.pov)  # no half-written scene
        return 1
    if out is not sys.stdout:
        out.close()
    print("%s: %s" % (args.nff, ", ".join("%d %s" % (v, k) for k, v in counts.items() if v)),
          file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
