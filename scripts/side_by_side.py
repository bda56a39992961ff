#!/usr/bin/env python3
"""Joins 8-bit RGB/RGBA PNGs left to right (same height) into one RGB PNG: side_by_side.py OUT IN...
The docs' paired pictures are made with it (scripts/pictures.sh); only Python's standard library."""
import struct
import sys
import zlib


def load(path):
    data = open(path, 'rb').read()
    if data[:8] != b'\x89PNG\r\n\x1a\n':
        sys.exit(f'{path}: not a PNG')
    i, idat, width, height, colour = 8, b'', 0, 0, 0
    while i < len(data):
        n, kind = struct.unpack('>I4s', data[i:i + 8])
        chunk = data[i + 8:i + 8 + n]
        i += 12 + n
        if kind == b'IHDR':
            width, height, depth, colour, _, _, interlace = struct.unpack('>IIBBBBB', chunk)
            if depth != 8 or colour not in (2, 6) or interlace:
                sys.exit(f'{path}: only 8-bit RGB or RGBA, not interlaced')
        elif kind == b'IDAT':
            idat += chunk
    bpp = 3 if colour == 2 else 4
    raw, stride, rows, prev, p = zlib.decompress(idat), width * bpp, [], bytearray(width * bpp), 0
    for _ in range(height):
        kind, line = raw[p], bytearray(raw[p + 1:p + 1 + stride])
        p += 1 + stride
        for x in range(stride):
            a = line[x - bpp] if x >= bpp else 0
            b = prev[x]
            c = prev[x - bpp] if x >= bpp else 0
            if kind == 1:
                line[x] = (line[x] + a) & 255
            elif kind == 2:
                line[x] = (line[x] + b) & 255
            elif kind == 3:
                line[x] = (line[x] + (a + b) // 2) & 255
            elif kind == 4:
                pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line) if bpp == 3 else bytes(v for k, v in enumerate(line) if k % 4 != 3))
        prev = line
    return width, height, rows


def save(path, width, height, rows):
    def chunk(kind, body):
        return struct.pack('>I', len(body)) + kind + body + struct.pack('>I', zlib.crc32(kind + body) & 0xffffffff)
    raw = b''.join(b'\x00' + r for r in rows)
    with open(path, 'wb') as f:
        f.write(b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', width, height, 8, 2, 0, 0, 0))
                + chunk(b'IDAT', zlib.compress(raw, 9)) + chunk(b'IEND', b''))


if len(sys.argv) < 3:
    sys.exit(__doc__)
images = [load(p) for p in sys.argv[2:]]
if len({h for _, h, _ in images}) != 1:
    sys.exit('the pictures differ in height')
height = images[0][1]
save(sys.argv[1], sum(w for w, _, _ in images), height,
     [b''.join(rows[y] for _, _, rows in images) for y in range(height)])
