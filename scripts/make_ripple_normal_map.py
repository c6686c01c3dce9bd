#!/usr/bin/env python3
"""Writes samples/assets/ripple_normal.png: a tileable tangent-space normal map of ripples.

Two ring ripples ("drops"), one centred in the tile and one on its corners, each a height field
    h(r) = sin(2 pi * RINGS * r / R) * cos^2(pi r / (2 R))     for r < R = 0.5 tile, else 0,
with r the distance to the drop's centre measured on the torus (wrapping at the tile's edges).
The window cos^2 falls to 0 with zero slope at r = R, so each drop ends smoothly inside the tile
and the tile repeats without a seam. Slopes are central differences on the wrapped grid, scaled
so that the steepest one is STRENGTH; the normal is normalize(-dh/du, dh/dv_up, 1), encoded as
round(255 * (n * 0.5 + 0.5)) in RGB (linear, not sRGB; green = +Y toward the image's top, the
convention of snell::make_noise_normal_map and glTF).

Used by docs/mirror.md (scripts/render_mirror_docs.sh runs it) for the mirror's `normal_map`.
The output is the same byte for byte on every run. Standard library only.
Run: python3 scripts/make_ripple_normal_map.py [OUT.png]
"""
import math
import struct
import sys
import zlib
from pathlib import Path

SIZE = 256        # pixels per side
RINGS = 5         # ripple crests per drop radius
RADIUS = 0.5      # drop radius, in tiles
STRENGTH = 0.6    # steepest slope (0.6: about 31 degrees)
DROPS = [(0.5, 0.5, 1.0), (0.0, 0.0, 0.7)]  # centre u, v (tiles) and amplitude of each drop


def height(x, y):
    """The height at pixel (x, y) (u = x / SIZE, v = y / SIZE, wrapped)."""
    u, v = x / SIZE, y / SIZE
    h = 0.0
    for cu, cv, amplitude in DROPS:
        du = (u - cu + 0.5) % 1.0 - 0.5
        dv = (v - cv + 0.5) % 1.0 - 0.5
        r = math.hypot(du, dv)
        if r < RADIUS:
            window = math.cos(math.pi * r / (2.0 * RADIUS)) ** 2
            h += amplitude * math.sin(2.0 * math.pi * RINGS * r / RADIUS) * window
    return h


def png(width, height_px, rows):
    """An 8-bit RGB PNG of `rows` (bytes, 3 per pixel), filter 0, zlib level 9."""
    raw = b"".join(b"\x00" + row for row in rows)

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))

    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height_px, 8, 2,
                                                             0, 0, 0))
            + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def main(argv):
    out = Path(argv[1]) if len(argv) > 1 else \
        Path(__file__).resolve().parent.parent / "samples" / "assets" / "ripple_normal.png"
    h = [[height(x, y) for x in range(SIZE)] for y in range(SIZE)]
    # Slopes per tile (du, dv_up), central differences wrapping at the edges.
    slopes = [[((h[y][(x + 1) % SIZE] - h[y][x - 1]) * SIZE / 2.0,
                (h[y - 1][x] - h[(y + 1) % SIZE][x]) * SIZE / 2.0)
               for x in range(SIZE)] for y in range(SIZE)]
    steepest = max(math.hypot(sx, sy) for row in slopes for sx, sy in row)
    scale = STRENGTH / steepest
    rows = []
    for row in slopes:
        line = bytearray()
        for sx, sy in row:
            n = (-sx * scale, sy * scale, 1.0)
            length = math.sqrt(n[0] ** 2 + n[1] ** 2 + n[2] ** 2)
            line += bytes(round(255.0 * (c / length * 0.5 + 0.5)) for c in n)
        rows.append(bytes(line))
    out.parent.mkdir(parents=True, exist_ok=True)
    data = png(SIZE, SIZE, rows)
    if not out.exists() or out.read_bytes() != data:
        out.write_bytes(data)
    print(f"wrote {out} ({SIZE}x{SIZE}, {len(data)} bytes)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
