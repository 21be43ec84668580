#!/usr/bin/env python3
"""render_png.py: reads build/render's PNGs for tests/test_render.sh, checking every CRC and the
zlib stream (so a broken writer fails), and prints facts about them.

  render_png.py info A.png        -> "WIDTH HEIGHT COVERED" (COVERED: pixels not background)
  render_png.py diff A.png B.png  -> the number of pixels that differ
"""
import struct
import sys
import zlib

BACKGROUND = b"\xff\xff\xff\xff"


def read(path):
    """The (width, height, rows of RGBA bytes) of an 8-bit RGBA PNG with filter 0 rows."""
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("%s: not a PNG" % path)
    pos, idat, size = 8, b"", None
    while pos < len(data):
        (n,) = struct.unpack(">I", data[pos:pos + 4])
        kind, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + n]
        (crc,) = struct.unpack(">I", data[pos + 8 + n:pos + 12 + n])
        if zlib.crc32(kind + body) & 0xFFFFFFFF != crc:
            raise ValueError("%s: bad CRC in %r" % (path, kind))
        if kind == b"IHDR":
            size = struct.unpack(">II", body[:8])
            if body[8:13] != b"\x08\x06\x00\x00\x00":
                raise ValueError("%s: not 8-bit RGBA" % path)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    w, h = size
    raw = zlib.decompress(idat)
    stride = w * 4 + 1
    if len(raw) != stride * h or any(raw[y * stride] for y in range(h)):
        raise ValueError("%s: bad image data" % path)
    return w, h, [raw[y * stride + 1:(y + 1) * stride] for y in range(h)]


def pixels(rows):
    return [r[i:i + 4] for r in rows for i in range(0, len(r), 4)]


def main():
    if sys.argv[1] == "info":
        w, h, rows = read(sys.argv[2])
        print(w, h, sum(p != BACKGROUND for p in pixels(rows)))
    else:
        a, b = read(sys.argv[2]), read(sys.argv[3])
        if a[:2] != b[:2]:
            raise ValueError("sizes differ")
        print(sum(p != q for p, q in zip(pixels(a[2]), pixels(b[2]))))


if __name__ == "__main__":
    main()
