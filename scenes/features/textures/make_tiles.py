#!/usr/bin/env python3
"""Writes tiles.png beside this script: 256 x 256 texels of black and white checks, 32 texels
each (a scene unit holds 8 of them across), with a red line two texels wide along every fourth
row of checks, for texture-filtering.yaml. Plain Python (zlib), so it needs nothing else."""
import pathlib
import struct
import zlib

SIZE, CHECK = 256, 32


def texel(x, y):
    if y % (4 * CHECK) < 2:
        return (200, 30, 30)
    return (235, 235, 235) if (x // CHECK + y // CHECK) % 2 == 0 else (20, 20, 20)


def chunk(kind, data):
    body = kind + data
    return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))


rows = b"".join(b"\0" + bytes(c for x in range(SIZE) for c in texel(x, y)) for y in range(SIZE))
png = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", SIZE, SIZE, 8, 2, 0, 0, 0)) +
       chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b""))
(pathlib.Path(__file__).parent / "tiles.png").write_bytes(png)
