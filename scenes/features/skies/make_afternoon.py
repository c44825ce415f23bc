#!/usr/bin/env python3
"""Writes afternoon.hdr, the sky of scenes/features/sky.yaml: a clear afternoon sky in latitude
and longitude (glint's sky mapping, docs/scene-format.md), 256 x 128 Radiance RGBE pixels.

A blue that pales towards the horizon, a sun of 2 degrees' radius 30 degrees above it with a
glow about it, and a dim brown ground below the horizon. The sun gives about three times the
light the rest of the sky gives a level floor: a small bright source that only importance
sampling of the sky finds quickly. Run it from this folder: python3 make_afternoon.py
"""
import math
import struct

WIDTH, HEIGHT = 256, 128
SUN_ELEVATION, SUN_AZIMUTH, SUN_RADIUS = math.radians(30), math.radians(-50), math.radians(2)
SUN_RADIANCE = (1100.0, 1000.0, 820.0)


def direction(u, v):
    """glint's mapping: v = theta / pi from +y, u = 1/2 + atan2(-x, z) / 2 pi."""
    theta, phi = v * math.pi, (u - 0.5) * 2 * math.pi
    s = math.sin(theta)
    return (-s * math.sin(phi), math.cos(theta), s * math.cos(phi))


def sun_direction():
    c = math.cos(SUN_ELEVATION)
    return (-c * math.sin(SUN_AZIMUTH), math.sin(SUN_ELEVATION), c * math.cos(SUN_AZIMUTH))


def radiance(w):
    sun = sun_direction()
    angle = math.acos(max(-1.0, min(1.0, sum(a * b for a, b in zip(w, sun)))))
    if angle < SUN_RADIUS:
        return SUN_RADIANCE
    if w[1] < 0:  # the ground: darker straight down
        return tuple(c * (0.6 + 0.4 * math.exp(8 * w[1])) for c in (0.12, 0.1, 0.08))
    height = w[1]
    zenith, horizon = (0.05, 0.11, 0.27), (0.27, 0.3, 0.36)
    t = math.exp(-4 * height)  # the horizon's share
    glow = 0.35 * math.exp(-angle / 0.15) + 0.07 * math.exp(-angle / 0.6)
    return tuple(z * (1 - t) + h * t + glow * g for z, h, g in zip(zenith, horizon, (1, 0.9, 0.7)))


def rgbe(color):
    top = max(color)
    if top < 1e-32:
        return bytes(4)
    mantissa, exponent = math.frexp(top)
    scale = mantissa * 256 / top
    return bytes([int(c * scale) for c in color] + [exponent + 128])


def main():
    rows = []
    for y in range(HEIGHT):
        row = b"".join(rgbe(radiance(direction((x + 0.5) / WIDTH, (y + 0.5) / HEIGHT)))
                       for x in range(WIDTH))
        rows.append(row)
    with open("afternoon.hdr", "wb") as f:
        f.write(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n")
        f.write(b"-Y %d +X %d\n" % (HEIGHT, WIDTH))
        f.write(b"".join(rows))


if __name__ == "__main__":
    main()
