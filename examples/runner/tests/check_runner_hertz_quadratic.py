#!/usr/bin/env python3
"""The Hertz scene on second-order meshes through mortarcontact-run: gmsh -order 2, the runner,
the pressure profile against Hertz.

Gmsh meshes examples/runner/hertz_quadratic/hertz_quadratic.geo (the geometry of
examples/runner/hertz/hertz.geo, h = 0.02 near the contact) with -order 2 four times:
  t6_msh22, t6_msh41   6-node triangles, as format 2.2 and as 4.1;
  q9                   9-node quadrilaterals (Mesh.RecombineAll, Mesh.SubdivisionAlgorithm = 1);
  q8                   8-node quadrilaterals (and Mesh.SecondOrderIncomplete = 1).
The runner solves hertz_quadratic.json (unchanged) on each; from its output files alone this
script checks
  - the VTU: every cell of the right VTK type (22 T6, 28 Q9, 23 Q8), with that many nodes;
  - the pressure CSV: the contact nodes alternate corner, mid-edge node, corner, ... along the
    surface (a mid-edge node midway along the arc between its corners), and
      - the KKT conditions at the corners, which carry the constraints (the multipliers of a
        quadratic body 1 are the paper's P1 ones, on the corners): pressure >= 0, gap >= 0,
        pressure * gap = 0, to round-off relative to the largest pressure and gap;
      - at the mid-edge nodes, which the constraints hold only weakly (through the integrals
        against the corners' multipliers): pressure >= 0, and a penetration of at most
        MID_GAP_TOLERANCE of the largest gap (measured: 1.75e-4 for T6, 6.0e-5 for Q9 and Q8);
      - equilibrium: the pressures integrate to the load P. p_j = lambda_j / int phi_j with the
        quadratic shape functions phi_j of each 3-node edge (a parabola through its nodes),
        integrated here along that parabola: sum p_j int phi_j = P;
      - p0 against Hertz (computed here independently of the runner) to P0_TOLERANCE, and a
        within the node spacing there (a is only known to within it: the pressure is nodal;
        a node counts as loaded above 1e-9 p0, as in the runner);
      - the runner's printed p0 equals the CSV's;
  - formats 2.2 and 4.1 give byte-identical CSVs (same mesh, same numbering, same arithmetic).

usage: check_runner_hertz_quadratic.py RUNNER GMSH GEO JSON WORK_DIR
"""

import math
import os
import re
import shutil
import sys
import xml.etree.ElementTree as ET

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_runner_hertz import P, check, check_against_hertz, read_csv, run  # noqa: E402

P0_TOLERANCE = 0.003
ROUND_OFF = 1e-9         # relative: pressure and gap signs and pressure * gap at the corners
MID_GAP_TOLERANCE = 5e-4  # relative to the largest gap: penetration allowed at a mid-edge node

RECOMBINE = "Mesh.RecombineAll=1; Mesh.SubdivisionAlgorithm=1;"
VARIANTS = [  # name, gmsh format, extra gmsh options, VTK cell type, nodes per cell
    ("t6_msh22", "msh22", "", 22, 6),
    ("t6_msh41", "msh41", "", 22, 6),
    ("q9", "msh41", RECOMBINE, 28, 9),
    ("q8", "msh41", RECOMBINE + " Mesh.SecondOrderIncomplete=1;", 23, 8),
]

# 8-point Gauss-Legendre rule on [0, 1]
_GAUSS = [(-0.9602898564975363, 0.1012285362903763), (-0.7966664774136267, 0.2223810344533745),
          (-0.5255324099163290, 0.3137066458778873), (-0.1834346424956498, 0.3626837833783620)]
GAUSS = [(0.5 * (1 + s * sign), 0.5 * w) for s, w in _GAUSS for sign in (-1, 1)]


def quadratic_tributary(rows):
    """int phi_j over the contact surface for nodes in chain order corner, middle, corner, ...:
    per 3-node edge, the quadratic shape functions integrated along the parabola x(s) through
    its nodes (s = 0, 1/2, 1)."""
    w = [0.0] * len(rows)
    for k in range(0, len(rows) - 1, 2):
        (x0, y0), (xm, ym), (x1, y1) = [rows[k + i][:2] for i in range(3)]
        for s, weight in GAUSS:
            dx = (4 * s - 3) * x0 + (4 * s - 1) * x1 + (4 - 8 * s) * xm
            dy = (4 * s - 3) * y0 + (4 * s - 1) * y1 + (4 - 8 * s) * ym
            jw = weight * math.hypot(dx, dy)
            w[k] += jw * (1 - s) * (1 - 2 * s)
            w[k + 1] += jw * 4 * s * (1 - s)
            w[k + 2] += jw * s * (2 * s - 1)
    return w


def check_vtu(path, vtk_type, nodes_per_cell, label):
    """Every cell of the file has the expected VTK type and node count."""
    piece = ET.parse(path).getroot().find("UnstructuredGrid/Piece")
    arrays = {a.get("Name"): a.text.split() for a in piece.iter("DataArray")}
    n_cells = int(piece.get("NumberOfCells"))
    check(len(arrays["types"]) == n_cells and set(arrays["types"]) == {str(vtk_type)},
          "%s: %s has cell types %s, expected %d" % (label, path, sorted(set(arrays["types"])), vtk_type))
    offsets = [int(o) for o in arrays["offsets"]]
    check(offsets == [nodes_per_cell * (c + 1) for c in range(n_cells)],
          "%s: %s: cells not of %d nodes each" % (label, path, nodes_per_cell))
    check("nodal_stress" in arrays, "%s: %s has no nodal_stress" % (label, path))
    return n_cells


def check_one(rows, out, label):
    check(len(rows) > 20 and len(rows) % 2 == 1, "%s: %d contact nodes, expected an odd number > 20 (corner, "
          "middle, ..., corner)" % (label, len(rows)))
    for k in range(1, len(rows), 2):  # on the circle, midway in arc between its corners
        (x0, y0), (xm, ym), (x1, y1) = [rows[k + i][:2] for i in (-1, 0, 1)]
        t0, tm, t1 = [math.atan2(x, 1.0 - y) for x, y in ((x0, y0), (xm, ym), (x1, y1))]
        check(abs(tm - 0.5 * (t0 + t1)) < 1e-6 * abs(t1 - t0) + 1e-12,
              "%s: contact node %d at (%g, %g) is not the middle of its edge" % (label, k, xm, ym))
    check(all(math.isfinite(r[3]) for r in rows), "%s: a contact node sees no block" % label)
    gap_scale = max(abs(r[3]) for r in rows)
    p_scale = max(r[2] for r in rows)
    for j, (x, y, p, g) in enumerate(rows):
        if j % 2 == 0:  # a corner
            check(p >= -ROUND_OFF * p_scale, "%s: pressure %g < 0 at corner x = %g" % (label, p, x))
            check(g >= -ROUND_OFF * gap_scale, "%s: gap %g < 0 at corner x = %g" % (label, g, x))
            check(abs(p * g) <= ROUND_OFF * p_scale * gap_scale,
                  "%s: pressure * gap = %g at corner x = %g" % (label, p * g, x))
        else:
            check(p >= 0, "%s: pressure %g < 0 at mid-edge node x = %g" % (label, p, x))
            check(g >= -MID_GAP_TOLERANCE * gap_scale,
                  "%s: gap %g at mid-edge node x = %g, below -%g of the largest gap" % (label, g, x, MID_GAP_TOLERANCE))
    force = sum(r[2] * w for r, w in zip(rows, quadratic_tributary(rows)))
    check(abs(force - P) <= 1e-10 * P, "%s: integral of the pressure %.15g != P = %g" % (label, force, P))

    dofs = re.search(r"solved: (\d+) DOFs", out)
    check_against_hertz([(x, y, p if p > ROUND_OFF * p_scale else 0.0, g) for x, y, p, g in rows], out, label, force,
                        dofs.group(1) if dofs else "?", P0_TOLERANCE)


def main():
    if len(sys.argv) != 6:
        sys.exit(__doc__)
    runner, gmsh, geo, scene, work = sys.argv[1:]
    stem = os.path.splitext(os.path.basename(scene))[0]
    texts = {}
    for label, fmt, options, vtk_type, nodes_per_cell in VARIANTS:
        d = os.path.join(work, label)
        shutil.rmtree(d, ignore_errors=True)
        os.makedirs(d)
        command = [gmsh, "-2", "-order", "2", "-format", fmt]
        if options:
            command += ["-string", options]
        run(command + [geo, "-o", os.path.join(d, stem + ".msh")])
        shutil.copy(scene, d)
        out = run([runner, "--quiet", os.path.join(d, os.path.basename(scene))])
        print(out.strip())
        csv_path = os.path.join(d, stem + "_pressure.csv")
        check_one(read_csv(csv_path), out, label)
        for b in (1, 2):
            check_vtu(os.path.join(d, "%s_body%d.vtu" % (stem, b)), vtk_type, nodes_per_cell, label)
        with open(csv_path) as f:
            texts[label] = f.read()
    check(texts["t6_msh22"] == texts["t6_msh41"], "format 2.2 and 4.1 meshes give different pressure CSVs")
    print("OK: T6, Q9 and Q8 agree with Hertz; formats 2.2 and 4.1 give identical results")


if __name__ == "__main__":
    main()
