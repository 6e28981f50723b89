"""Writes door_planks.png, the texture of door_textured.obj: 16 x 32 pixels,
vertical planks (brown, each a shade apart, dark seams) and a brass handle.
Standard library only, so the bytes are the same on every machine."""
import struct
import zlib

W, H = 16, 32


def pixel(x, y):
    if 11 <= x <= 12 and 14 <= y <= 16:  # the handle (row 0 is the image's top)
        return (200, 160, 60)
    if x % 4 == 0:  # a seam between planks
        return (70, 40, 20)
    shade = 20 * (x // 4)
    return (150 + shade // 2, 95 + shade // 3, 50)


def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))


rows = b"".join(b"\0" + bytes(c for x in range(W) for c in pixel(x, y)) for y in range(H))
png = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", W, H, 8, 2, 0, 0, 0)) +
       chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b""))
with open("door_planks.png", "wb") as f:
    f.write(png)
