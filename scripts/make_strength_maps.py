#!/usr/bin/env python3
"""Writes the painted tear strength maps in assets/strength_maps/ and the tear regions' images in
assets/tear_regions/ (run from anywhere; deterministic).

Each map is an 8-bit grayscale PNG over the cloth's material-space bounding box (the scenes name no
extent): column 0 at the smallest x, row 0 at the LARGEST y (the image as seen, material y up).
The scene's "tear_strength_map" says which multiplier black and white stand for
(core/tearing/strength_map.h); in a "tear_region" white is the region (core/tearing/tear_region.h). Written with the standard library only (zlib), no image package.

    python3 scripts/make_strength_maps.py
"""
import struct
import zlib
from pathlib import Path

ASSETS = Path(__file__).resolve().parent.parent / "assets"
MAP_DIR = ASSETS / "strength_maps"
REGION_DIR = ASSETS / "tear_regions"
SIZE = 256  # pixels a side, over a 1 m sheet: 3.9 mm a pixel


def write_png(name, grey_of, folder=MAP_DIR):
    """grey_of(x, y) -> 0..255 at the pixel centre (x, y) in [0, 1]^2 material space, y up."""
    rows = []
    for j in range(SIZE):
        y = 1.0 - (j + 0.5) / SIZE
        rows.append(b"\x00" + bytes(grey_of((i + 0.5) / SIZE, y) for i in range(SIZE)))
    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)
    png = b"\x89PNG\r\n\x1a\n"
    png += chunk(b"IHDR", struct.pack(">IIBBBBB", SIZE, SIZE, 8, 0, 0, 0, 0))  # 8-bit grey
    png += chunk(b"IDAT", zlib.compress(b"".join(rows), 9))
    png += chunk(b"IEND", b"")
    (folder / name).write_bytes(png)


def perforation(x, y):
    """A vertical dashed line at x = 0.35 m: dashes 3 cm wide and 2.5 cm long, every 4 cm, black
    (weak) on white. 3 cm is about an edge of a 32-vertex metre, so a column of vertices lies in it."""
    on_line = abs(x - 0.35) < 0.015
    in_dash = (y % 0.04) < 0.025
    return 0 if on_line and in_dash else 255


def hem(x, y):
    """A hem 8 cm deep along the bottom edge, white (strong) on black."""
    return 255 if y < 0.08 else 0


def left_panel(x, y):
    """The left half of the sheet, white (the region) on black."""
    return 255 if x < 0.5 else 0


if __name__ == "__main__":
    MAP_DIR.mkdir(parents=True, exist_ok=True)
    write_png("perforation.png", perforation)
    write_png("hem.png", hem)
    REGION_DIR.mkdir(parents=True, exist_ok=True)
    write_png("left-panel.png", left_panel, REGION_DIR)
