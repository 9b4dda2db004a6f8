#!/usr/bin/env python3
"""NAFEMS R0094 benchmark 2 (Code_Aster SSNA122): the punch with rounded edges, axisymmetric,
frictionless, with the scene runner. Meshes examples/runner/nafems_punch/punch.geo with Gmsh at
each fine size h, solves punch.json and prints, per mesh: DOFs, the axial displacement and the
contact pressure on the axis, the radius where the pressure falls to zero, the peak pressure,
and the pressure and displacement at r = 17.5 mm (see docs/benchmarks.md for why). Exits
non-zero unless the axial contact force equals the load, 100 MPa x pi 50^2 (ctest
runner_nafems_punch runs it at h = 1).

usage: /usr/bin/python3 bench/nafems_punch.py [--runner build/examples/runner/mortarcontact-run]
                                              [--work build/nafems_punch] [h ...]   (default 1 0.5 0.25 0.125)
"""
import argparse
import csv
import math
import os
import re
import shutil
import subprocess


def vtu_displacements(path):
    """{(x, y): (ux, uy)} of a VTU written by mc_write_vtu."""
    text = open(path).read()
    xyz = re.search(r'Name="coordinates".*?>(.*?)</DataArray>', text, re.S).group(1).split()
    u = re.search(r'Name="displacement".*?>(.*?)</DataArray>', text, re.S).group(1).split()
    return {(float(xyz[3 * i]), float(xyz[3 * i + 1])): (float(u[3 * i]), float(u[3 * i + 1]))
            for i in range(len(xyz) // 3)}


def at_radius(rows, r):
    """Linear interpolation of (pressure, uy) along the flat contact surface at radius r."""
    flat = [x for x in rows if x[1] == 200.0]
    for a, b in zip(flat, flat[1:]):
        if a[0] <= r <= b[0]:
            s = (r - a[0]) / (b[0] - a[0])
            return a[2] + s * (b[2] - a[2]), a[3] + s * (b[3] - a[3])
    raise ValueError("radius %g not on the flat contact surface" % r)


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser()
    parser.add_argument("--runner", default=os.path.join(here, "..", "build", "examples", "runner", "mortarcontact-run"))
    parser.add_argument("--work", default=os.path.join(here, "..", "build", "nafems_punch"))
    parser.add_argument("h", nargs="*", type=float, default=[1.0, 0.5, 0.25, 0.125])
    args = parser.parse_args()
    source = os.path.join(here, "..", "examples", "runner", "nafems_punch")
    os.makedirs(args.work, exist_ok=True)
    for name in ("punch.geo", "punch.json"):
        shutil.copy(os.path.join(source, name), args.work)
    print("| h mm | DOFs | contact nodes (active) | u_z(0) mm | p(0) MPa | contact radius mm | peak p MPa "
          "| p(17.5) MPa | u_z(17.5) mm | solve s |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for h in args.h:
        subprocess.run(["gmsh", "-2", "-setnumber", "h", str(h), "-format", "msh41", "punch.geo", "-o", "punch.msh"],
                       cwd=args.work, check=True, stdout=subprocess.DEVNULL)
        out = subprocess.run([args.runner, "--quiet", "punch.json"], cwd=args.work, check=True,
                             capture_output=True, text=True).stdout
        force = float(re.search(r"contact force on body 1: \(\S+, (\S+)\)", out).group(1))
        if abs(force / (100.0 * math.pi * 50.0 ** 2) - 1) > 1e-8:
            raise SystemExit("axial contact force %.10g differs from the load 100 pi 50^2" % force)
        dofs, active, nodes, seconds = re.search(
            r"solved: (\d+) DOFs, \d+ active-set iterations, (\d+) of (\d+) contact nodes active, ([\d.]+) s", out).groups()
        u = vtu_displacements(os.path.join(args.work, "punch_body1.vtu"))
        rows = []
        for row in csv.DictReader(open(os.path.join(args.work, "punch_pressure.csv"))):
            x, y, p = float(row["x"]), float(row["y"]), float(row["pressure"])
            rows.append((x, y, p, u[(x, y)][1]))
        loaded = [x for x in rows if x[2] > 0]
        p175, u175 = at_radius(rows, 17.5)
        print("| %g | %s | %s (%s) | %.5f | %.2f | %.2f | %.0f | %.2f | %.5f | %s |" % (
            h, dofs, nodes, active, rows[0][3], rows[0][2], max(x[0] for x in loaded), max(x[2] for x in rows), p175,
            u175, seconds))


if __name__ == "__main__":
    main()
