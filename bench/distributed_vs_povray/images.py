#!/usr/bin/env python3
"""Linear RGB images for the error measurements: glint's PFM and POV-Ray's OpenEXR, read with
the standard library alone, and the RMSE between two of them.

    images.py glint.pfm povray.exr          # prints the RMSE and the mean of each image

An image is (width, height, values): values a flat list of floats, R, G, B a pixel, rows from
the top. Both formats hold linear values, unclamped (PFM: 32-bit floats; POV-Ray's EXR: half
floats, 11 significant bits, far finer than any error measured here).
"""

import argparse
import math
import struct
import sys
import zlib


def read_pfm(path):
    """A colour PFM ("PF"): a text header, then rows of 3 floats a pixel, bottom row first,
    little-endian when the scale is negative."""
    with open(path, "rb") as f:
        data = f.read()
    tokens, pos = [], 0
    while len(tokens) < 4:  # "PF", width, height, scale, each followed by whitespace
        while data[pos:pos + 1].isspace():
            pos += 1
        end = pos
        while not data[end:end + 1].isspace():
            end += 1
        tokens.append(data[pos:end].decode("ascii"))
        pos = end
    pos += 1  # the single whitespace byte before the pixels
    if tokens[0] != "PF":
        raise ValueError("%s: not a colour PFM (%r)" % (path, tokens[0]))
    width, height, scale = int(tokens[1]), int(tokens[2]), float(tokens[3])
    fmt = ("<" if scale < 0 else ">") + "%df" % (3 * width)
    row_bytes = 12 * width
    values = []
    for y in range(height - 1, -1, -1):  # bottom row first in the file
        start = pos + y * row_bytes
        values.extend(struct.unpack(fmt, data[start:start + row_bytes]))
    return width, height, values


def _exr_attributes(data):
    """The header's attributes (name -> (type, bytes)) and the offset just past it."""
    if data[:4] != b"\x76\x2f\x31\x01":
        raise ValueError("not an OpenEXR file")
    attrs, pos = {}, 8
    while data[pos] != 0:
        end = data.index(b"\0", pos)
        name = data[pos:end].decode("ascii")
        type_end = data.index(b"\0", end + 1)
        kind = data[end + 1:type_end].decode("ascii")
        size = struct.unpack("<i", data[type_end + 1:type_end + 5])[0]
        attrs[name] = (kind, data[type_end + 5:type_end + 5 + size])
        pos = type_end + 5 + size
    return attrs, pos + 1


def _exr_channels(raw):
    """[(name, pixel type)] in file order (alphabetical); type 1 half, 2 float."""
    channels, pos = [], 0
    while raw[pos] != 0:
        end = raw.index(b"\0", pos)
        name = raw[pos:end].decode("ascii")
        pixel_type = struct.unpack("<i", raw[end + 1:end + 5])[0]
        channels.append((name, pixel_type))
        pos = end + 17  # type, pLinear and 3 reserved bytes, x and y sampling
    return channels


def _unzip_exr(block):
    """OpenEXR's ZIP(S) chunk: zlib, then a byte delta predictor, then the two halves of the
    bytes interleaved."""
    t = bytearray(zlib.decompress(block))
    for i in range(1, len(t)):
        t[i] = (t[i - 1] + t[i] - 128) & 255
    half = (len(t) + 1) // 2
    out = bytearray(len(t))
    out[0::2] = t[:half]
    out[1::2] = t[half:]
    return bytes(out)


def read_exr(path):
    """A scanline OpenEXR file with R, G and B (half or float), uncompressed or ZIP/ZIPS, as
    POV-Ray 3.7 and glint write them."""
    with open(path, "rb") as f:
        data = f.read()
    attrs, pos = _exr_attributes(data)
    compression = attrs["compression"][1][0]
    lines_per_chunk = {0: 1, 2: 1, 3: 16}.get(compression)
    if lines_per_chunk is None:
        raise ValueError("%s: EXR compression %d not supported (only none, ZIPS, ZIP)"
                         % (path, compression))
    x0, y0, x1, y1 = struct.unpack("<4i", attrs["dataWindow"][1])
    width, height = x1 - x0 + 1, y1 - y0 + 1
    channels = _exr_channels(attrs["channels"][1])
    names = [name for name, _ in channels]
    if not {"R", "G", "B"} <= set(names):
        raise ValueError("%s: no R, G and B channels (%s)" % (path, names))
    chunks = (height + lines_per_chunk - 1) // lines_per_chunk
    offsets = struct.unpack("<%dQ" % chunks, data[pos:pos + 8 * chunks])
    values = [0.0] * (3 * width * height)
    rgb_index = {"R": 0, "G": 1, "B": 2}
    for offset in offsets:
        y, size = struct.unpack("<ii", data[offset:offset + 8])
        block = data[offset + 8:offset + 8 + size]
        lines = min(lines_per_chunk, y1 - y + 1)
        expected = lines * width * sum(2 if t == 1 else 4 for _, t in channels)
        if compression != 0 and size < expected:
            block = _unzip_exr(block)
        p = 0
        for line in range(lines):  # each line holds every channel's row in turn
            row = y - y0 + line
            for name, pixel_type in channels:
                fmt, step = ("<%de" % width, 2) if pixel_type == 1 else ("<%df" % width, 4)
                xs = struct.unpack(fmt, block[p:p + step * width])
                p += step * width
                k = rgb_index.get(name)
                if k is not None:
                    values[3 * row * width + k:3 * (row + 1) * width:3] = xs
    return width, height, values


def read_image(path):
    if path.endswith(".pfm"):
        return read_pfm(path)
    if path.endswith(".exr"):
        return read_exr(path)
    raise ValueError("%s: only .pfm and .exr are read" % path)


def mirrored(image):
    """The image flipped left to right."""
    width, height, values = image
    out = []
    for y in range(height):
        row = values[3 * y * width:3 * (y + 1) * width]
        for x in range(width - 1, -1, -1):
            out.extend(row[3 * x:3 * x + 3])
    return width, height, out


def rmse(a, b, clamp=None):
    """Root mean square difference over all channels of two images of one size; with clamp,
    both are first clamped to [0, clamp] (what a display shows)."""
    wa, ha, va = a
    wb, hb, vb = b
    if (wa, ha) != (wb, hb):
        raise ValueError("sizes differ: %dx%d and %dx%d" % (wa, ha, wb, hb))
    if clamp is None:
        s = sum((x - y) * (x - y) for x, y in zip(va, vb))
    else:
        s = sum((min(max(x, 0.0), clamp) - min(max(y, 0.0), clamp)) ** 2 for x, y in zip(va, vb))
    return math.sqrt(s / len(va))


def mean(image):
    return sum(image[2]) / len(image[2])


def _srgb_byte(v):
    v = min(max(v, 0.0), 1.0)
    v = 12.92 * v if v <= 0.0031308 else 1.055 * v ** (1 / 2.4) - 0.055
    return int(255 * v + 0.5)


def write_png(image, path):
    """An 8-bit sRGB PNG of a linear image (clamped to [0, 1]), for looking at."""
    width, height, values = image
    rows = []
    for y in range(height):
        row = values[3 * y * width:3 * (y + 1) * width]
        rows.append(b"\0" + bytes(_srgb_byte(v) for v in row))  # filter type 0 a row

    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data
                + struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff))

    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n")
        f.write(chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)))
        f.write(chunk(b"IDAT", zlib.compress(b"".join(rows), 6)))
        f.write(chunk(b"IEND", b""))


def write_difference_png(a, b, path, gain=8.0):
    """|a - b| channel by channel, times gain, as a PNG: where two images differ."""
    width, height, va = a
    write_png((width, height, [gain * abs(x - y) for x, y in zip(va, b[2])]), path)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("a", help=".pfm or .exr")
    ap.add_argument("b", help=".pfm or .exr")
    args = ap.parse_args()
    a, b = read_image(args.a), read_image(args.b)
    print("RMSE %.5f (clamped to [0, 1]: %.5f); means %.5f and %.5f"
          % (rmse(a, b), rmse(a, b, clamp=1.0), mean(a), mean(b)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
