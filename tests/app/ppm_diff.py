#!/usr/bin/env python3
"""Compares two PPM files of one size (window_pixels.py's): prints the bounding box of the pixels that
differ as "X0 Y0 X1 Y1" (exclusive ends; "none" if none) and the number of pure white pixels of the
second: ppm_diff.py A.ppm B.ppm."""
import sys


def read(path):
    with open(path, "rb") as f:
        data = f.read()
    magic, w, h, top, pixels = data.split(maxsplit=4)
    assert magic == b"P6" and top == b"255", path
    return int(w), int(h), pixels


wa, ha, a = read(sys.argv[1])
wb, hb, b = read(sys.argv[2])
if (wa, ha) != (wb, hb):
    sys.exit(f"ppm_diff.py: {wa}x{ha} and {wb}x{hb}")
xs, ys = [], []
white = 0
for i in range(wa * ha):
    if a[3 * i:3 * i + 3] != b[3 * i:3 * i + 3]:
        xs.append(i % wa)
        ys.append(i // wa)
    if b[3 * i:3 * i + 3] == b"\xff\xff\xff":
        white += 1
box = f"{min(xs)} {min(ys)} {max(xs) + 1} {max(ys) + 1}" if xs else "none"
print(box, white)
