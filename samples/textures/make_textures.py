"""Writes the textures of textured_house.pxg, 64 x 64 pixels each, made for
procex: brick.png (eight courses of stretcher bond, four bricks across, pale
mortar: one tile is 1 m square, so a brick is 0.25 m by 0.125 m with its
joint) and roof_tiles.png (four rows of four clay tiles, each row shaded
darker at its lower edge, alternate rows offset by half a tile). Standard
library only, so the bytes are the same on every machine."""
import struct
import zlib

W = H = 64


def brick(x, y):
    course, row_y = divmod(y, 8)
    shift = 8 * (course % 2)  # stretcher bond: every other course half a brick along
    col_x = (x + shift) % 16
    if row_y == 7 or col_x == 15:  # a joint
        return (205, 200, 188)
    shade = ((x + shift) // 16 * 37 + course * 23) % 30  # each brick a little apart
    return (150 + shade, 62 + shade // 2, 40 + shade // 3)


def roof_tile(x, y):
    row, row_y = divmod(y, 16)
    col_x = (x + 8 * (row % 2)) % 16
    if col_x == 0:  # the gap between tiles
        return (60, 30, 20)
    dark = row_y * 4  # darker toward the tile's lower edge (row 0 is the image's top)
    return (170 - dark, 75 - dark // 3, 50 - dark // 4)


def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))


def write(name, pixel):
    rows = b"".join(b"\0" + bytes(c for x in range(W) for c in pixel(x, y)) for y in range(H))
    png = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", W, H, 8, 2, 0, 0, 0)) +
           chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b""))
    with open(name, "wb") as f:
        f.write(png)


write("brick.png", brick)
write("roof_tiles.png", roof_tile)
