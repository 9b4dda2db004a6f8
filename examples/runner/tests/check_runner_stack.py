#!/usr/bin/env python3
"""The three-block stack (examples/runner/stack/) through mortarcontact-run: a scene of three
bodies and two contact pairs, and its patch test.

Gmsh meshes stack.geo (non-matching meshes on both interfaces); the runner solves stack.json
as shipped, then with the dual mortar method on the sparse interface path, then with its two
pairs listed in the other order. A uniform pressure p on the top block passes through both
frictionless interfaces as a uniform stress, so from the pressure CSV (columns pair,x,y,
pressure,gap) this script checks, for every run:
  - both pairs are there, each on its own interface (y = 2 for the top block on the middle one,
    y = 1 for the middle block on the bottom one), the rows numbered as the scene lists the pairs;
  - the contact pressure is p to round-off (1e-9 relative) at every position of both pairs,
    and the gap is 0 to round-off;
  - the runner's per-pair line prints the contact force (0, p) on each non-mortar block;
  - the ParaView collection names three bodies and their files exist.

usage: check_runner_stack.py RUNNER GMSH STACK_DIR WORK_DIR
"""

import csv
import json
import os
import re
import shutil
import subprocess
import sys

P = 0.25  # the pressure on the top block (stack.json)


def check(condition, message):
    if not condition:
        print("FAILED: " + message)
        sys.exit(1)


def run_scene(runner, work, name, scene):
    path = os.path.join(work, name + ".json")
    scene = dict(scene)
    scene["output"] = {"vtu": name + ".pvd", "pressure_csv": name + "_pressure.csv"}
    with open(path, "w") as f:
        json.dump(scene, f, indent=2)
    done = subprocess.run([runner, path], capture_output=True, text=True)
    print(done.stdout)
    check(done.returncode == 0, "%s: exit code %d:\n%s" % (name, done.returncode, done.stderr))
    with open(os.path.join(work, name + "_pressure.csv")) as f:
        rows = list(csv.reader(f))
    check(rows[0] == ["pair", "x", "y", "pressure", "gap"], "%s: CSV header %s" % (name, rows[0]))
    return done.stdout, [(int(r[0]), float(r[1]), float(r[2]), float(r[3]), float(r[4])) for r in rows[1:]]


def check_run(name, out, rows, pair_y, work):
    """pair_y: the interface height of pair 1 and pair 2."""
    for pair, y in enumerate(pair_y, start=1):
        mine = [r for r in rows if r[0] == pair]
        check(len(mine) >= 4, "%s: pair %d has %d rows" % (name, pair, len(mine)))
        check(all(abs(r[2] - y) < 1e-12 for r in mine), "%s: pair %d is not on y = %g" % (name, pair, y))
        xs = sorted(r[1] for r in mine)
        check(abs(xs[0]) < 1e-12 and abs(xs[-1] - 1) < 1e-12, "%s: pair %d does not span x = 0..1" % (name, pair))
        worst = max(abs(r[3] - P) for r in mine)
        check(worst <= 1e-9 * P, "%s: pair %d: a contact pressure is %.3g from p = %g" % (name, pair, worst, P))
        check(max(abs(r[4]) for r in mine) <= 1e-12, "%s: pair %d: a gap is not 0" % (name, pair))
        lower = 2 if y == 2 else 3  # the mortar block
        m = re.search(r"pair %d \(body %d on body %d\): (\d+) contact positions, (\d+) with pressure > 0, "
                      r"contact force on body %d: \((\S+), (\S+)\)" % (pair, lower - 1, lower, lower - 1), out)
        check(m is not None, "%s: no summary line for pair %d" % (name, pair))
        check(int(m.group(1)) == len(mine) == int(m.group(2)), "%s: pair %d: positions differ" % (name, pair))
        check(abs(float(m.group(3))) < 1e-12 and abs(float(m.group(4)) - P) < 1e-12,
              "%s: pair %d: contact force (%s, %s), expected (0, %g)" % (name, pair, m.group(3), m.group(4), P))
        print("%s: pair %d: %d positions, |p - %g| <= %.2e" % (name, pair, len(mine), P, worst))
    check(len(rows) == sum(1 for r in rows if r[0] in (1, 2)), "%s: rows of other pairs" % name)
    with open(os.path.join(work, name + ".pvd")) as f:
        pvd = f.read()
    for b in (1, 2, 3):
        vtu = "%s_body%d.vtu" % (name, b)
        check(vtu in pvd and os.path.getsize(os.path.join(work, vtu)) > 0, "%s: %s missing" % (name, vtu))


def main():
    runner, gmsh, stack_dir, work = sys.argv[1:5]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    subprocess.run([gmsh, "-2", "-format", "msh41", os.path.join(stack_dir, "stack.geo"), "-o",
                    os.path.join(work, "stack.msh")], check=True, capture_output=True)
    with open(os.path.join(stack_dir, "stack.json")) as f:
        scene = json.load(f)
    out, rows = run_scene(runner, work, "shipped", scene)
    check_run("shipped", out, rows, (2, 1), work)
    dual = dict(scene, solver={"method": "dual_mortar", "interface_solver": "sparse"})
    out, rows = run_scene(runner, work, "dual_sparse", dual)
    check_run("dual_sparse", out, rows, (2, 1), work)
    check("interface solver: sparse (set by the scene)" in out, "dual_sparse: the sparse path did not run")
    swapped = dict(scene, pairs=list(reversed(scene["pairs"])))
    out, rows = run_scene(runner, work, "swapped", swapped)
    check_run("swapped", out, rows, (1, 2), work)
    print("runner_stack: passed")


if __name__ == "__main__":
    main()
