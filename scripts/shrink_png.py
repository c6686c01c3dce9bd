#!/usr/bin/env python3
"""Recompresses PNG files in place, losslessly, to keep the docs' pictures small.

The CLI writes 8-bit RGBA through stb_image_write, whose deflate is light. This rewrites each
file as RGB when every pixel is opaque (RGBA otherwise), with each row's filter chosen by the
usual heuristic (the smallest sum of absolute filtered values, PNG spec section 12.8) and zlib
level 9; the pixels are unchanged. A file is rewritten only when the result is smaller, and the
output is the same byte for byte on every run. 8-bit RGB/RGBA, non-interlaced PNGs only (others
are left alone, with a message). Standard library only.
Run: python3 scripts/shrink_png.py FILE.png...
"""
import struct
import sys
import zlib


def paeth(a, b, c):
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    if pa <= pb and pa <= pc:
        return a
    return b if pb <= pc else c


def decode(data):
    """(width, height, channels, rows) of an 8-bit RGB/RGBA non-interlaced PNG, else None."""
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        return None
    pos, idat, header = 8, [], None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        pos += 12 + length
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat.append(body)
        elif kind == b"IEND":
            break
    if header is None:
        return None
    width, height, depth, colour, _, _, interlace = header
    if depth != 8 or colour not in (2, 6) or interlace != 0:
        return None
    bpp = 3 if colour == 2 else 4
    stride = width * bpp
    raw = zlib.decompress(b"".join(idat))
    rows, prev = [], bytearray(stride)
    for y in range(height):
        kind = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        if kind == 1:
            for i in range(bpp, stride):
                line[i] = (line[i] + line[i - bpp]) & 255
        elif kind == 2:
            line = bytearray((x + p) & 255 for x, p in zip(line, prev))
        elif kind == 3:
            for i in range(stride):
                left = line[i - bpp] if i >= bpp else 0
                line[i] = (line[i] + ((left + prev[i]) >> 1)) & 255
        elif kind == 4:
            for i in range(stride):
                if i >= bpp:
                    line[i] = (line[i] + paeth(line[i - bpp], prev[i], prev[i - bpp])) & 255
                else:
                    line[i] = (line[i] + prev[i]) & 255
        rows.append(line)
        prev = line
    return width, height, bpp, rows


def encode(width, height, bpp, rows):
    """A PNG of `rows` with per-row filters (none, sub, up, average) and zlib level 9."""
    stride = width * bpp
    prev, out = bytes(stride), bytearray()
    for line in rows:
        line = bytes(line)
        left = bytes(bpp) + line[:-bpp]
        candidates = [
            (0, line),
            (1, bytes((x - l) & 255 for x, l in zip(line, left))),
            (2, bytes((x - p) & 255 for x, p in zip(line, prev))),
            (3, bytes((x - ((l + p) >> 1)) & 255 for x, l, p in zip(line, left, prev))),
        ]
        kind, filtered = min(candidates,
                             key=lambda c: sum(v if v < 128 else 256 - v for v in c[1]))
        out += bytes([kind]) + filtered
        prev = line

    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))

    colour = 2 if bpp == 3 else 6
    return (b"\x89PNG\r\n\x1a\n"
            + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, colour, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(bytes(out), 9)) + chunk(b"IEND", b""))


def shrink(path):
    with open(path, "rb") as f:
        data = f.read()
    decoded = decode(data)
    if decoded is None:
        print(f"shrink_png: {path}: not an 8-bit RGB/RGBA non-interlaced PNG, left alone")
        return
    width, height, bpp, rows = decoded
    if bpp == 4 and all(line[3::4] == b"\xff" * width for line in rows):
        rows = [line[:] for line in rows]
        for i, line in enumerate(rows):
            del line[3::4]
        bpp = 3
    smaller = encode(width, height, bpp, rows)
    if len(smaller) < len(data):
        with open(path, "wb") as f:
            f.write(smaller)


def main(argv):
    for path in argv[1:]:
        shrink(path)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
