#!/usr/bin/env python3
"""png_mean_diff.py A.png B.png — mean |a - b| over the RGB channels of two same-sized PNGs,
in 0..255 units, as the golden tests measure it."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'tests', 'e2e'))
from png import read_png  # noqa: E402

a, b = read_png(sys.argv[1]), read_png(sys.argv[2])
if (a.width, a.height) != (b.width, b.height):
    sys.exit('png_mean_diff: the images differ in size')
total = 0
for ra, rb in zip(a.rows, b.rows):
    for x in range(a.width):
        total += sum(abs(ra[x * a.channels + k] - rb[x * b.channels + k]) for k in range(3))
print('%.2f' % (total / (3.0 * a.width * a.height)))
