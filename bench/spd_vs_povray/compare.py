#!/usr/bin/env python3
"""Compare two renders of one SPD database: do they show the same view and geometry?

    compare.py glint.png povray.png --background 0.078 0.361 0.753

Both images are 8- or 16-bit PNGs holding sRGB values (glint's PNGs and POV-Ray 3.7's with
`assumed_gamma 1` both are); they are read with the standard library alone. Figures:

- mask agreement: the share of pixels where both images, or neither, show the background
  colour (every channel within 2/255 of it: glint dithers). It tests the camera and the
  silhouettes of the geometry; it is 100% trivially where no background is seen (balls).
- close pixels: the share of pixels whose channels all differ by at most 16/255. It tests the
  shading too, so it also catches a mirrored or shifted view where the mask cannot.
- background shares of each image, and the mean absolute difference (0-255, largest channel).
"""

import argparse
import json
import struct
import sys
import zlib


def srgb_byte(linear):
    v = min(max(linear, 0.0), 1.0)
    v = 12.92 * v if v <= 0.0031308 else 1.055 * v ** (1 / 2.4) - 0.055
    return round(255 * v)


def read_png(path):
    """(width, height, bytes of 8-bit RGB) of a non-interlaced PNG (grey, RGB, with alpha)."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("%s: not a PNG file" % path)
    pos, idat, header = 8, [], None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        chunk = data[pos + 8:pos + 8 + length]
        pos += 12 + length
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", chunk)
        elif kind == b"IDAT":
            idat.append(chunk)
        elif kind == b"IEND":
            break
    width, height, depth, colour_type, _, _, interlace = header
    channels = {0: 1, 2: 3, 4: 2, 6: 4}.get(colour_type)
    if channels is None or depth not in (8, 16) or interlace:
        raise ValueError("%s: unsupported PNG (colour type %d, depth %d, interlace %d)"
                         % (path, colour_type, depth, interlace))
    bpp = channels * depth // 8
    stride = width * bpp
    raw = zlib.decompress(b"".join(idat))
    rows, prev = [], bytearray(stride)
    for y in range(height):
        kind = raw[y * (stride + 1)]
        row = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        if kind == 1:
            for i in range(bpp, stride):
                row[i] = (row[i] + row[i - bpp]) & 255
        elif kind == 2:
            row = bytearray((a + b) & 255 for a, b in zip(row, prev))
        elif kind == 3:
            for i in range(stride):
                left = row[i - bpp] if i >= bpp else 0
                row[i] = (row[i] + ((left + prev[i]) >> 1)) & 255
        elif kind == 4:
            for i in range(stride):
                a = row[i - bpp] if i >= bpp else 0
                b, c = prev[i], prev[i - bpp] if i >= bpp else 0
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                row[i] = (row[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(row)
        prev = row
    pixels = b"".join(rows)
    if depth == 16:
        pixels = pixels[::2]  # the high bytes
    if channels == 3:
        return width, height, bytes(pixels)
    grey = channels <= 2
    out = bytearray(3 * width * height)
    for i in range(width * height):
        j = i * channels
        out[3 * i:3 * i + 3] = pixels[j:j + 1] * 3 if grey else pixels[j:j + 3]
    return width, height, bytes(out)


def compare(a_path, b_path, background, tolerance=16):
    wa, ha, a = read_png(a_path)
    wb, hb, b = read_png(b_path)
    if (wa, ha) != (wb, hb):
        raise ValueError("sizes differ: %dx%d and %dx%d" % (wa, ha, wb, hb))
    n = wa * ha
    bg = [srgb_byte(c) for c in background]
    agree = close = bg_a = bg_b = 0
    diff_sum = 0
    for i in range(0, 3 * n, 3):
        pa, pb = a[i:i + 3], b[i:i + 3]
        in_a = all(abs(pa[k] - bg[k]) <= 2 for k in range(3))
        in_b = all(abs(pb[k] - bg[k]) <= 2 for k in range(3))
        bg_a += in_a
        bg_b += in_b
        agree += in_a == in_b
        d = max(abs(pa[k] - pb[k]) for k in range(3))
        diff_sum += d
        close += d <= tolerance
    return {"pixels": n, "mask_agreement": agree / n, "close_pixels": close / n,
            "background_a": bg_a / n, "background_b": bg_b / n, "mean_abs_diff": diff_sum / n}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("a")
    ap.add_argument("b")
    ap.add_argument("--background", nargs=3, type=float, default=[0, 0, 0],
                    metavar=("R", "G", "B"), help="the NFF's b line (linear, 0-1)")
    ap.add_argument("--json", action="store_true")
    args = ap.parse_args()
    r = compare(args.a, args.b, args.background)
    if args.json:
        print(json.dumps(r))
    else:
        print("masks agree on %.3f%% of pixels (background %.2f%% and %.2f%%); %.2f%% of pixels "
              "within 16/255; mean |difference| %.2f/255"
              % (100 * r["mask_agreement"], 100 * r["background_a"], 100 * r["background_b"],
                 100 * r["close_pixels"], r["mean_abs_diff"]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
