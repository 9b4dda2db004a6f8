#!/usr/bin/env python3
"""Reads what mortarcontact-run wrote for hertz_quadratic.json back with meshio (Debian:
python3-meshio): the cells of each body, the peak contact pressure and the largest von Mises
stress at the nodes. docs/tutorial_quadratic.md walks through it.

usage: read_results.py DIR    (the directory holding hertz_quadratic.pvd and its .vtu files)
"""
import sys

import meshio
import numpy as np

directory = sys.argv[1] if len(sys.argv) > 1 else "."

# ---- the two bodies, one file each ----
disc = meshio.read(directory + "/hertz_quadratic_body1.vtu")
block = meshio.read(directory + "/hertz_quadratic_body2.vtu")
for name, mesh in (("disc", disc), ("block", block)):
    for cells in mesh.cells:
        print("%s: %d points, %d %s cells" % (name, len(mesh.points), len(cells.data), cells.type))

# ---- the contact pressure: point data on the disc's contact nodes ----
pressure = disc.point_data["pressure"]
peak = np.argmax(pressure)
print("p0 = %.6g at x = %.3g" % (pressure[peak], disc.points[peak, 0]))

# ---- von Mises at the nodes, from the nodal stress (xx, yy, xy, zz) ----
s = block.point_data["nodal_stress"]
von_mises = np.sqrt(0.5 * ((s[:, 0] - s[:, 1]) ** 2 + (s[:, 1] - s[:, 3]) ** 2 + (s[:, 3] - s[:, 0]) ** 2)
                    + 3 * s[:, 2] ** 2)
strongest = np.argmax(von_mises)
print("block: largest von Mises %.6g at x = %.3g, depth %.4g"
      % (von_mises[strongest], block.points[strongest, 0], -block.points[strongest, 1]))
