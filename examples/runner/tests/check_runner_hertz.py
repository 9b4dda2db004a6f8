#!/usr/bin/env python3
"""The Hertz scene through mortarcontact-run, from the .geo to the pressure profile.

Gmsh meshes examples/runner/hertz/hertz.geo twice, as format 2.2 and as 4.1; the runner solves
hertz.json (unchanged) on each; from the pressure CSV alone this script checks
  - the KKT conditions: pressure >= 0, gap >= 0, pressure * gap = 0 at every contact node;
  - equilibrium: the lumped pressures integrate to the load P (p_j = lambda_j / int phi_j, and
    with the block's normals every lambda_j is vertical, so sum p_j int phi_j = P);
  - p0 and a against Hertz, computed here independently of the runner:
      |p0 / p0_Hertz - 1| <= 0.3 %: the fine-mesh limit of this scene is 0.1-0.2 % from Hertz
      (finite bodies, method.md) and at h = 0.01 the mesh adds at most 0.1 % (measured with
      h = 0.005 and 0.0025: p0 -0.07 %; at h = 0.01: -0.15 %);
      |a - a_Hertz| <= the node spacing at the edge of the contact zone (a is only known to
      within the spacing: the pressure is nodal);
  - the runner's printed p0 equals the CSV's;
  - both formats give byte-identical CSVs (same mesh, same numbering, same arithmetic), and the
    ParaView files exist.

usage: check_runner_hertz.py RUNNER GMSH GEO JSON WORK_DIR
"""

import csv
import math
import os
import re
import shutil
import subprocess
import sys

R, P, E, NU = 1.0, 0.01, 1.0, 0.3  # the scene of hertz.json (method.md)
P0_TOLERANCE = 0.003


def hertz():
    """(a, p0) for two equal plane-strain bodies."""
    e_star = 1.0 / (2.0 * (1.0 - NU * NU) / E)
    a = math.sqrt(4.0 * P * R / (math.pi * e_star))
    return a, 2.0 * P / (math.pi * a)


def run(command):
    result = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, check=False)
    if result.returncode != 0:
        sys.exit("FAILED: %s exited with %d:\n%s" % (" ".join(command), result.returncode, result.stdout))
    return result.stdout


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return [(float(r["x"]), float(r["y"]), float(r["pressure"]), float(r["gap"])) for r in rows]


def check(condition, message):
    if not condition:
        sys.exit("FAILED: " + message)


def tributary_lengths(rows):
    """int phi_j over the contact surface: half of each adjacent edge (nodes in chain order)."""
    lengths = [0.0] * len(rows)
    for j in range(len(rows) - 1):
        half = 0.5 * math.hypot(rows[j + 1][0] - rows[j][0], rows[j + 1][1] - rows[j][1])
        lengths[j] += half
        lengths[j + 1] += half
    return lengths


def half_width(rows):
    """a: on each side, midway between the outermost loaded node and the next one; and the
    larger of the two spacings there."""
    a, spacing = 0.0, 0.0
    for side in (-1.0, 1.0):
        xs = sorted(side * r[0] for r in rows if side * r[0] >= 0)
        last = max(side * r[0] for r in rows if r[2] > 0 and side * r[0] >= 0)
        following = [x for x in xs if x > last]
        check(following, "the contact zone reaches the end of the contact surface")
        a += 0.25 * (last + following[0])
        spacing = max(spacing, following[0] - last)
    return a, spacing


def check_one(rows, out, label):
    check(len(rows) > 20, "%s: only %d contact nodes" % (label, len(rows)))
    check(all(math.isfinite(r[3]) for r in rows), "%s: a contact node sees no block" % label)
    gap_scale = max(abs(r[3]) for r in rows)
    p_scale = max(r[2] for r in rows)
    for x, y, p, g in rows:
        check(p >= 0, "%s: pressure %g < 0 at x = %g" % (label, p, x))
        check(g >= -1e-10 * gap_scale, "%s: gap %g < 0 at x = %g" % (label, g, x))
        check(abs(p * g) <= 1e-10 * p_scale * gap_scale, "%s: pressure * gap = %g at x = %g" % (label, p * g, x))
    force = sum(p * w for (x, y, p, g), w in zip(rows, tributary_lengths(rows)))
    check(abs(force - P) <= 1e-10 * P, "%s: integral of the pressure %.15g != P = %g" % (label, force, P))

    check_against_hertz(rows, out, label, force)


def check_against_hertz(rows, out, label, force, dofs="", p0_tolerance=P0_TOLERANCE):
    """p0 (the largest pressure) within p0_tolerance of Hertz, the contact half-width within one
    node spacing, and the runner's printed p0 the CSV's; prints the comparison."""
    a_hertz, p0_hertz = hertz()
    p0 = max(r[2] for r in rows)
    a, spacing = half_width(rows)
    p0_error, a_error = p0 / p0_hertz - 1, a - a_hertz
    print("%s: %s%d contact nodes, p0 = %.6g (Hertz %.6g, %+.3f %%), a = %.5g (Hertz %.5g, %+.2f %%, node spacing "
          "%.4g), integral of p = %.15g" % (label, dofs + " DOFs, " if dofs else "", len(rows), p0, p0_hertz,
                                             100 * p0_error, a, a_hertz, 100 * a_error / a_hertz, spacing, force))
    check(abs(p0_error) <= p0_tolerance, "%s: p0 %+.3f %% from Hertz" % (label, 100 * p0_error))
    check(abs(a_error) <= spacing, "%s: a off Hertz by %.3g, more than the node spacing %.3g" % (label, a_error, spacing))
    printed = re.search(r"p0 = (\S+)", out)
    check(printed and abs(float(printed.group(1)) / p0 - 1) < 1e-5, "%s: the runner printed another p0" % label)


def main():
    if len(sys.argv) != 6:
        sys.exit(__doc__)
    runner, gmsh, geo, scene, work = sys.argv[1:]
    texts = []
    for fmt in ("msh22", "msh41"):
        d = os.path.join(work, fmt)
        shutil.rmtree(d, ignore_errors=True)
        os.makedirs(d)
        run([gmsh, "-2", "-format", fmt, geo, "-o", os.path.join(d, "hertz.msh")])
        shutil.copy(scene, d)
        out = run([runner, "--quiet", os.path.join(d, os.path.basename(scene))])
        print(out.strip())
        csv_path = os.path.join(d, "hertz_pressure.csv")
        check_one(read_csv(csv_path), out, fmt)
        for name in ("hertz.pvd", "hertz_body1.vtu", "hertz_body2.vtu"):
            path = os.path.join(d, name)
            check(os.path.isfile(path) and os.path.getsize(path) > 0, "%s: %s not written" % (fmt, name))
        with open(csv_path) as f:
            texts.append(f.read())
    check(texts[0] == texts[1], "format 2.2 and 4.1 meshes give different pressure CSVs")
    print("OK: formats 2.2 and 4.1 give identical results")


if __name__ == "__main__":
    main()
