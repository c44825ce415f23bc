#!/usr/bin/env python3
# Writes the small hand-made test meshes of this folder (glTF, GLB, PLY, STL, OBJ/MTL), so that
# their contents are reviewable and reproducible: python3 make_test_meshes.py. The PLY and STL
# files go to scenes/features/models too, where the example scenes read them.
import base64
import json
import struct
import zlib
from pathlib import Path

HERE = Path(__file__).resolve().parent
SCENE_MODELS = HERE.parents[2] / "scenes" / "features" / "models"


def write_both(name, data):
    """Writes the file here and beside the example scenes (a scene reads only its own folder)."""
    for folder in (HERE, SCENE_MODELS):
        path = folder / name
        if isinstance(data, str):
            path.write_text(data)
        else:
            path.write_bytes(data)


def png_2x2(pixels):
    """A 2x2 8-bit RGB PNG; pixels are rows from the top, each (r, g, b)."""
    raw = b"".join(b"\x00" + bytes(c for px in row for c in px) for row in pixels)

    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data +
                struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF))

    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 2, 2, 8, 2, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


# A unit quad in the xy plane facing +z: 4 vertices, 2 triangles, normals and uvs.
QUAD_POSITIONS = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
QUAD_NORMALS = [(0, 0, 1)] * 4
QUAD_UVS = [(0, 0), (1, 0), (1, 1), (0, 1)]  # glTF's v runs down the image
QUAD_INDICES = [0, 1, 2, 0, 2, 3]


def quad_buffer():
    data = b"".join(struct.pack("<3f", *p) for p in QUAD_POSITIONS)
    data += b"".join(struct.pack("<3f", *n) for n in QUAD_NORMALS)
    data += b"".join(struct.pack("<2f", *uv) for uv in QUAD_UVS)
    data += struct.pack("<6H", *QUAD_INDICES) + b"\x00\x00"  # padded to 4 bytes
    return data


def quad_gltf(buffer_uri, buffer_length, extra_buffer_views=(), images=None, orthographic=False):
    views = [
        {"buffer": 0, "byteOffset": 0, "byteLength": 48},
        {"buffer": 0, "byteOffset": 48, "byteLength": 48},
        {"buffer": 0, "byteOffset": 96, "byteLength": 32},
        {"buffer": 0, "byteOffset": 128, "byteLength": 12},
    ] + list(extra_buffer_views)
    material = {
        "name": "red_metal",
        "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.2, 0.1, 1.0], "metallicFactor": 0.5,
                                 "roughnessFactor": 0.5},
        "emissiveFactor": [0.1, 0.2, 0.3],
    }
    doc = {
        "asset": {"version": "2.0", "generator": "glint make_test_meshes.py"},
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": {"KHR_lights_punctual": {"lights": [
            {"name": "bulb", "type": "point", "color": [1.0, 0.5, 0.25], "intensity": 20.0},
            {"name": "sun", "type": "directional", "color": [1.0, 1.0, 1.0], "intensity": 2.0},
            {"name": "spot", "type": "spot", "intensity": 10.0,
             "spot": {"innerConeAngle": 0.2, "outerConeAngle": 0.4}},
        ]}},
        "scene": 0,
        "scenes": [{"nodes": [0, 1, 2, 3, 4, 5]}],
        "nodes": [
            # The quad, scaled by 2 and moved by (10, 0, 0): it spans (10,0,0) to (12,2,0).
            {"name": "quad", "mesh": 0, "translation": [10, 0, 0], "scale": [2, 2, 2]},
            {"name": "eye", "camera": 0, "translation": [11, 1, 5]},
            {"name": "bulb_node", "translation": [0, 3, 0],
             "extensions": {"KHR_lights_punctual": {"light": 0}}},
            # Rotated -90 degrees about x: its -z axis points down, -y in world space.
            {"name": "sun_node", "rotation": [-0.7071068, 0, 0, 0.7071068],
             "extensions": {"KHR_lights_punctual": {"light": 1}}},
            {"name": "spot_node", "translation": [1, 2, 3],
             "extensions": {"KHR_lights_punctual": {"light": 2}}},
            # The quad mirrored in x: it spans (-12,0,0) to (-10,2,0) and must still face +z.
            {"name": "mirror", "mesh": 0, "translation": [-10, 0, 0], "scale": [-2, 2, 2]},
        ],
        "cameras": [
            {"name": "ortho", "type": "orthographic",
             "orthographic": {"xmag": 3.0, "ymag": 2.0, "znear": 0.1, "zfar": 100.0}}
            if orthographic else
            {"name": "eye", "type": "perspective",
             "perspective": {"yfov": 0.8, "aspectRatio": 1.5, "znear": 0.1, "zfar": 100.0}}
        ],
        "meshes": [{"name": "quad", "primitives": [{
            "attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "indices": 3,
            "material": 0}]}],
        "materials": [material],
        "buffers": [{"byteLength": buffer_length}],
        "bufferViews": views,
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
             "min": [0, 0, 0], "max": [1, 1, 0]},
            {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"},
            {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2"},
            {"bufferView": 3, "componentType": 5123, "count": 6, "type": "SCALAR"},
        ],
    }
    if buffer_uri is not None:
        doc["buffers"][0]["uri"] = buffer_uri
    if images is not None:
        doc["images"] = images
        doc["textures"] = [{"source": 0}]
        material["pbrMetallicRoughness"]["baseColorTexture"] = {"index": 0}
    return doc


def write_gltf():
    data = quad_buffer()
    (HERE / "quad.bin").write_bytes(data)
    (HERE / "quad.gltf").write_text(json.dumps(quad_gltf("quad.bin", len(data)), indent=1) + "\n")


def write_glb():
    # An orthographic camera and an embedded 2x2 texture: red, green over blue, white.
    png = png_2x2([[(255, 0, 0), (0, 255, 0)], [(0, 0, 255), (255, 255, 255)]])
    data = quad_buffer() + png
    data += b"\x00" * (-len(data) % 4)
    doc = quad_gltf(None, len(data),
                    extra_buffer_views=[{"buffer": 0, "byteOffset": len(quad_buffer()),
                                        "byteLength": len(png)}],
                    images=[{"bufferView": 4, "mimeType": "image/png"}], orthographic=True)
    text = json.dumps(doc).encode()
    text += b" " * (-len(text) % 4)
    body = (struct.pack("<I4s", len(text), b"JSON") + text + struct.pack("<I4s", len(data), b"BIN\x00") +
            data)
    (HERE / "quad.glb").write_bytes(struct.pack("<4sII", b"glTF", 2, 12 + len(body)) + body)


# A unit cube from (0,0,0) to (1,1,1): 8 vertices, 6 quads (12 triangles), outward winding.
CUBE_VERTICES = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1),
                 (0, 1, 1)]
CUBE_FACES = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (2, 3, 7, 6), (1, 2, 6, 5), (0, 4, 7, 3)]


def write_ply():
    header = ("ply\nformat {}\ncomment unit cube for glint's tests\nelement vertex 8\n"
              "property float x\nproperty float y\nproperty float z\nelement face 6\n"
              "property list uchar int vertex_indices\nend_header\n")
    text = header.format("ascii 1.0")
    text += "".join("{} {} {}\n".format(*v) for v in CUBE_VERTICES)
    text += "".join("4 {} {} {} {}\n".format(*f) for f in CUBE_FACES)
    write_both("cube_ascii.ply", text)
    binary = header.format("binary_little_endian 1.0").encode()
    binary += b"".join(struct.pack("<3f", *v) for v in CUBE_VERTICES)
    binary += b"".join(struct.pack("<B4i", 4, *f) for f in CUBE_FACES)
    write_both("cube_binary.ply", binary)


# A tetrahedron with corners at the origin and on the three axes: 4 triangles, outward winding.
TETRA = [((0, 0, 0), (0, 1, 0), (1, 0, 0)), ((0, 0, 0), (1, 0, 0), (0, 0, 1)),
         ((0, 0, 0), (0, 0, 1), (0, 1, 0)), ((1, 0, 0), (0, 1, 0), (0, 0, 1))]


def write_stl():
    lines = ["solid tetra"]
    for tri in TETRA:
        lines.append("  facet normal 0 0 0\n    outer loop")
        lines += ["      vertex {} {} {}".format(*v) for v in tri]
        lines.append("    endloop\n  endfacet")
    lines.append("endsolid tetra\n")
    write_both("tetra_ascii.stl", "\n".join(lines))
    data = b"glint test tetrahedron".ljust(80, b" ") + struct.pack("<I", len(TETRA))
    for tri in TETRA:
        data += struct.pack("<3f", 0, 0, 0) + b"".join(struct.pack("<3f", *v) for v in tri)
        data += b"\x00\x00"
    write_both("tetra_binary.stl", data)


if __name__ == "__main__":
    write_gltf()
    write_glb()
    write_ply()
    write_stl()
