#!/usr/bin/env python3
"""Friction through mortarcontact-run (examples/runner/friction/): the scene keys "friction" and
"load_steps", the friction columns of the contact CSV, the friction lines of the summary and the
friction arrays of the VTU files.

Gmsh meshes friction.geo (two blocks, non-matching meshes on the contact surface, nu = 0); the
blocks are loaded into the uniform stress sigma_yy = -p, sigma_xy = tau, sigma_xx = 0, exact on
any mesh. Runs, each checked on the CSV (every row) and the printed summary:
  - friction.json as shipped (Coulomb, mu = 0.5, tau = 0.4 mu p, 5 load steps, the two-body form
    with a top-level "friction"): every position sticks, shear -tau, pressure p, no slip; the
    upper block's VTU has the friction point arrays with those values;
  - the same scene written with "pairs" (Tresca, bound mu p, in pairs[0].friction, 1 load step):
    the same answer, the CSV with its pair column first;
  - the slip patch test: the upper block's top moved by delta along x beyond the exact field
    (a support with a value): every position slips, shear -mu p, slip and accumulated slip delta;
  - without friction the upper block has nothing holding it along x: exit code 1, MC_ERROR_SINGULAR.

usage: check_runner_friction.py RUNNER GMSH FRICTION_DIR WORK_DIR
"""

import copy
import csv
import json
import os
import re
import shutil
import subprocess
import sys

P, TAU, MU, E = 0.01, 0.002, 0.5, 1.0  # friction.json: pressure, shear, mu, Young's modulus (nu = 0)


def check(condition, message):
    if not condition:
        print("FAILED: " + message)
        sys.exit(1)


def run_scene(runner, work, name, scene, expect_code=0):
    path = os.path.join(work, name + ".json")
    scene = copy.deepcopy(scene)
    scene["output"] = {"vtu": name + ".pvd", "pressure_csv": name + "_contact.csv"}
    with open(path, "w") as f:
        json.dump(scene, f, indent=2)
    done = subprocess.run([runner, path], capture_output=True, text=True)
    print(done.stdout)
    check(done.returncode == expect_code, "%s: exit code %d, expected %d:\n%s" % (name, done.returncode, expect_code,
                                                                                  done.stderr))
    return done


def read_rows(work, name, pair_column):
    with open(os.path.join(work, name + "_contact.csv")) as f:
        rows = list(csv.reader(f))
    header = (["pair"] if pair_column else []) + ["x", "y", "pressure", "gap", "shear", "slip", "slip_total", "state"]
    check(rows[0] == header, "%s: CSV header %s, expected %s" % (name, rows[0], header))
    out = []
    for r in rows[1:]:
        if pair_column:
            check(r[0] == "1", "%s: a row of pair %s" % (name, r[0]))
            r = r[1:]
        out.append(dict(zip(header[-8:], [float(v) for v in r[:7]] + [r[7]])))
    check(len(out) >= 4, "%s: %d contact rows" % (name, len(out)))
    xs = sorted(r["x"] for r in out)
    check(abs(xs[0]) < 1e-12 and abs(xs[-1] - 1) < 1e-12 and all(abs(r["y"] - 1) < 1e-12 for r in out),
          "%s: the rows are not the upper block's bottom" % name)
    return out


def check_rows(name, rows, state, shear, slip, slip_total):
    for r in rows:
        where = "%s: x = %.4g" % (name, r["x"])
        check(r["state"] == state, "%s: state %s, expected %s" % (where, r["state"], state))
        check(abs(r["pressure"] - P) <= 1e-9 * P, "%s: pressure %.17g, expected %g" % (where, r["pressure"], P))
        check(abs(r["shear"] - shear) <= 1e-9 * P, "%s: shear %.17g, expected %g" % (where, r["shear"], shear))
        check(abs(r["slip"] - slip) <= 1e-9 * max(abs(slip), P), "%s: slip %.17g, expected %g" % (where, r["slip"], slip))
        check(abs(r["slip_total"] - slip_total) <= 1e-9 * max(slip_total, P),
              "%s: accumulated slip %.17g, expected %g" % (where, r["slip_total"], slip_total))
        check(abs(r["gap"]) <= 1e-10, "%s: gap %.3g" % (where, r["gap"]))
    print("%s: %d positions %s, shear %g, slip %g" % (name, len(rows), state, shear, slip))


def check_summary(name, out, n, state):
    counts = {"open": 0, "stick": 0, "slip": 0}
    counts[state] = n
    m = re.search(r"pair 1 friction: (\d+) open, (\d+) stick, (\d+) slip positions", out)
    check(m is not None, "%s: no friction line for pair 1" % name)
    check([int(g) for g in m.groups()] == [counts["open"], counts["stick"], counts["slip"]],
          "%s: friction line %s, expected %s" % (name, m.group(0), counts))
    m = re.search(r"friction: (\d+) stick, (\d+) slip \(constraint rows\), complementarity ([^,\s]+),", out)
    check(m is not None, "%s: no friction summary" % name)
    check((int(m.group(1)) > 0) == (state == "stick") and (int(m.group(2)) > 0) == (state == "slip"),
          "%s: %s" % (name, m.group(0)))
    check(float(m.group(3)) <= 1e-10, "%s: friction complementarity %s" % (name, m.group(3)))


def vtu_point_array(path, name):
    """The values of a point-data array of an ASCII .vtu."""
    with open(path) as f:
        text = f.read()
    m = re.search(r'<DataArray[^>]*Name="%s"[^>]*>(.*?)</DataArray>' % re.escape(name), text, re.S)
    check(m is not None, "%s: no array %s" % (path, name))
    return [float(v) for v in m.group(1).split()]


def main():
    runner, gmsh, friction_dir, work = sys.argv[1:5]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    mesh = os.path.join(work, "friction.msh")
    done = subprocess.run([gmsh, "-2", "-format", "msh41", os.path.join(friction_dir, "friction.geo"), "-o", mesh],
                          capture_output=True, text=True)
    check(done.returncode == 0 and os.path.exists(mesh), "gmsh failed:\n" + done.stdout + done.stderr)
    with open(os.path.join(friction_dir, "friction.json")) as f:
        shipped = json.load(f)
    check(shipped["friction"] == {"law": "coulomb", "mu": MU} and shipped["load_steps"] == 5,
          "test bug: friction.json's friction changed")

    # 1. as shipped: stick everywhere
    out = run_scene(runner, work, "stick", shipped).stdout
    rows = read_rows(work, "stick", False)
    check_rows("stick", rows, "stick", -TAU, 0.0, 0.0)
    check_summary("stick", out, len(rows), "stick")
    check("5 load steps" in out, "stick: the load steps are not printed")
    # the VTU of the non-mortar body: the friction fields on its contact nodes
    vtu = os.path.join(work, "stick_body1.vtu")
    shear = vtu_point_array(vtu, "shear")
    state = vtu_point_array(vtu, "state")
    on_contact = [k for k, s in enumerate(state) if s == 1]  # MC_STATE_STICK
    check(len(on_contact) == len(rows), "stick VTU: %d sticking nodes, %d contact rows" % (len(on_contact), len(rows)))
    check(all(abs(shear[k] + TAU) <= 1e-9 * P for k in on_contact), "stick VTU: shear is not -tau")
    check(len(vtu_point_array(vtu, "slip")) == len(state) == len(vtu_point_array(vtu, "slip_total")),
          "stick VTU: array lengths")

    # 2. Tresca with "pairs": the same answer
    pairs = copy.deepcopy(shipped)
    del pairs["friction"], pairs["load_steps"]
    for body in pairs["bodies"]:
        del body["contact"]
    pairs["pairs"] = [{"nonmortar": 1, "mortar": 2, "nonmortar_surface": "upper_bottom", "mortar_surface": "lower_top",
                       "friction": {"law": "tresca", "bound": MU * P}}]
    out = run_scene(runner, work, "tresca_pairs", pairs).stdout
    check_rows("tresca_pairs", read_rows(work, "tresca_pairs", True), "stick", -TAU, 0.0, 0.0)
    check_summary("tresca_pairs", out, len(rows), "stick")

    # 3. slip: the upper top moved along x by the exact field (gamma y, gamma = 2 tau / E with
    # nu = 0, tau = mu p) plus delta; its x traction replaced by that support
    delta, tau = 0.05, MU * P
    slip = copy.deepcopy(shipped)
    upper, lower = slip["bodies"]
    upper["loads"] = [{"type": "traction", "group": "upper_top", "value": [0.0, -P]},
                      {"type": "traction", "group": "upper_left", "value": [0.0, -tau]},
                      {"type": "traction", "group": "upper_right", "value": [0.0, tau]}]
    upper["supports"] = [{"group": "upper_top", "components": "x", "value": 2 * tau / E * 2.0 + delta}]
    lower["loads"] = [{"type": "traction", "group": "lower_left", "value": [0.0, -tau]},
                      {"type": "traction", "group": "lower_right", "value": [0.0, tau]}]
    out = run_scene(runner, work, "slip", slip).stdout
    check_rows("slip", read_rows(work, "slip", False), "slip", -tau, delta, delta)
    check_summary("slip", out, len(rows), "slip")

    # 4. no friction: nothing holds the upper block along x
    frictionless = copy.deepcopy(shipped)
    del frictionless["friction"]
    done = run_scene(runner, work, "frictionless", frictionless, expect_code=1)
    check("MC_ERROR_SINGULAR" in done.stderr, "frictionless: %s" % done.stderr)
    print("runner friction checks passed")


if __name__ == "__main__":
    main()
