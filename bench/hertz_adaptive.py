#!/usr/bin/env python3
"""Adaptive refinement against uniform refinement on the Hertz scene and on the two-cylinder
scene (docs/benchmarks.md, "Adaptive refinement"), with the scene runner.

--scene hertz (the default): examples/runner/hertz/hertz.geo (hertz.json's scene), coarse mesh
h = 0.1, h_far = 0.5. --scene cylinders: examples/runner/cylinders_adaptive/cylinders.geo
(cylinders_adaptive.json's scene without its "adaptive": R = 1 on R = 3, bench/cylinders_layout.c's
bodies), coarse mesh h = 0.05, h_far = 0.2. No output files. Three ways to refine the scene's
.geo, for first-order (P1) and second-order (T6, gmsh -order 2) triangles:
  - adaptive: mortarcontact-run's "adaptive" from the coarse mesh, one run per target error (the
    runner meshes, solves and remeshes until its estimate is below the target); DOFs, estimate,
    p0 and times of every step as the runner prints them;
  - uniform: the same coarse mesh refined everywhere: h and h_far divided by sqrt(2) per size;
  - graded by hand: the .geo's own field, h divided by sqrt(2) per size near the contact and
    the coarse h_far kept.
For each: the DOFs and the time at which the estimate (MC_INFO_ERROR_ESTIMATE) first reaches
each target, and p0 against the converged p0 of this finite scene (Hertz: the Q9 reference of
bench/hertz_quadratic, -0.179 % from Hertz's half-space value; cylinders: -0.573 % from Hertz's
value, T6 meshes graded to h = 0.001 and 0.0007, 8.4e5 and 1.6e6 DOFs, agreeing to 0.001 %;
docs/benchmarks.md): the first mesh from which |p0 error| stays below 1 % and 0.1 % (for the
adaptive runs, the smallest such mesh over all of them). Times are wall seconds: for the adaptive run the whole of it (every
Gmsh run and solve, from the coarse mesh), for a fixed mesh Gmsh and the runner on that mesh
alone. And the rate of the adaptive meshes: one run per target of a sequence (--sequence-p1,
--sequence-t6), the estimate reached against the DOFs of the last step, fitted by least
squares.

usage: /usr/bin/python3 bench/hertz_adaptive.py [--scene hertz|cylinders] [--runner build/examples/runner/mortarcontact-run]
           [--gmsh gmsh] [--work /tmp/<scene>_adaptive] [--orders 1 2] [--targets 0.01 0.001]
           [--max-dofs 1500000] [--sequence-p1 0.04 0.02 0.01 0.005]
           [--sequence-t6 0.02 0.01 0.005 0.002 0.001 0.0005] [--quick]
"""
import argparse
import json
import math
import os
import re
import subprocess
import time

# Per scene: the .geo and the scene file under examples/runner, the converged p0 of the finite
# scene against Hertz's value, the coarse start mesh (h at the contact, h_far far from it).
SCENES = {
    # bench/hertz_quadratic's Q9 reference
    "hertz": {"geo": ("hertz", "hertz.geo"), "json": ("hertz", "hertz.json"), "p0_reference": -0.179e-2,
              "h": 0.1, "h_far": 0.5},
    # T6, mortar normals, cylinders.geo graded to h = 0.002, 0.001, 0.0007 (h_far 0.03 to 0.015,
    # 2.8e5 to 1.6e6 DOFs): -0.572, -0.574, -0.573 % from Hertz
    "cylinders": {"geo": ("cylinders_adaptive", "cylinders.geo"),
                  "json": ("cylinders_adaptive", "cylinders_adaptive.json"), "p0_reference": -0.573e-2,
                  "h": 0.05, "h_far": 0.2},
}
SCENE = SCENES["hertz"]
P0_REFERENCE = SCENE["p0_reference"]  # the converged p0 of this scene against Hertz
H0, H_FAR0 = SCENE["h"], SCENE["h_far"]  # the coarse start mesh


def scene_path(here, key):
    return os.path.abspath(os.path.join(here, "..", "examples", "runner", *SCENE[key]))


def scene(here, work, mesh, adaptive=None):
    with open(scene_path(here, "json")) as f:
        s = json.load(f)
    for b in s["bodies"]:
        b["mesh"] = mesh
    s.pop("output", None)
    s.pop("adaptive", None)
    if adaptive:
        s["adaptive"] = adaptive
    return s


def p0_vs_reference(p0_vs_hertz):
    return (1 + p0_vs_hertz) / (1 + P0_REFERENCE) - 1


def run_adaptive(args, here, order, target):
    work = os.path.join(args.work, "adaptive_p%d_%g" % (order, target))
    os.makedirs(work, exist_ok=True)
    geo = scene_path(here, "geo")
    s = scene(here, work, "scene.msh", {
        "geo": geo, "target_error": target, "order": order, "max_steps": 12, "max_dofs": args.max_dofs,
        "gmsh_arguments": ["-setnumber", "h", str(H0), "-setnumber", "h_far", str(H_FAR0)]})
    path = os.path.join(work, "scene.json")
    with open(path, "w") as f:
        json.dump(s, f, indent=1)
    start = time.monotonic()
    result = subprocess.run([args.runner, "--quiet", "--gmsh", args.gmsh, path], capture_output=True, text=True)
    wall = time.monotonic() - start
    if result.returncode not in (0, 3):
        raise SystemExit("runner failed (%d):\n%s%s" % (result.returncode, result.stdout, result.stderr))
    rows = []
    for m in re.finditer(r"^\s+(\d+)\s+(\d+)\s+(\d+)\s+(\S+)\s+([\d.]+) %\s+([+-][\d.]+) %\s+([\d.]+)\s+([\d.]+)\s+([\d.]+)$",
                         result.stdout, re.M):
        rows.append({"step": int(m.group(1)), "cells": int(m.group(2)), "dofs": int(m.group(3)),
                     "estimate": float(m.group(5)) / 100, "p0": p0_vs_reference(float(m.group(6)) / 100),
                     "gmsh": float(m.group(7)), "solve": float(m.group(8)), "total": float(m.group(9))})
    return rows, result.returncode == 0, wall


def run_fixed(args, here, order, h, h_far):
    work = os.path.join(args.work, "fixed_p%d" % order)
    os.makedirs(work, exist_ok=True)
    geo = scene_path(here, "geo")
    path = os.path.join(work, "scene.json")
    with open(path, "w") as f:
        json.dump(scene(here, work, "scene.msh"), f, indent=1)
    start = time.monotonic()
    command = [args.gmsh, "-2", "-format", "msh41", "-setnumber", "h", repr(h), "-setnumber", "h_far", repr(h_far)]
    if order == 2:
        command += ["-order", "2"]
    subprocess.run(command + [geo, "-o", os.path.join(work, "scene.msh")], check=True, stdout=subprocess.DEVNULL)
    gmsh = time.monotonic() - start
    out = subprocess.run([args.runner, "--quiet", path], check=True, capture_output=True, text=True).stdout
    wall = time.monotonic() - start
    return {"h": h, "h_far": h_far, "dofs": int(re.search(r"solved: (\d+) DOFs", out).group(1)),
            "estimate": float(re.search(r"error estimate: (\S+) %", out).group(1)) / 100,
            "p0": p0_vs_reference(float(re.search(r"p0 = .*relative error (\S+) %", out).group(1)) / 100),
            "solve": float(re.search(r"solved: .*, ([\d.]+) s", out).group(1)), "gmsh": gmsh, "total": wall}


def rate(rows, last_half=True):
    """Least-squares exponent r of estimate ~ DOFs^-r over the rows (their last half, at least 3)."""
    pts = [(math.log(r["dofs"]), math.log(r["estimate"])) for r in rows if r["estimate"] > 0]
    if last_half:
        pts = pts[-max(3, len(pts) // 2):]
    if len(pts) < 2:
        return float("nan")
    mx = sum(p[0] for p in pts) / len(pts)
    my = sum(p[1] for p in pts) / len(pts)
    return -sum((p[0] - mx) * (p[1] - my) for p in pts) / sum((p[0] - mx) ** 2 for p in pts)


def first(rows, test):
    for r in rows:
        if test(r):
            return r
    return None


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    global SCENE, P0_REFERENCE, H0, H_FAR0
    parser = argparse.ArgumentParser()
    parser.add_argument("--scene", choices=sorted(SCENES), default="hertz")
    parser.add_argument("--runner", default=os.path.join(here, "..", "build", "examples", "runner", "mortarcontact-run"))
    parser.add_argument("--gmsh", default="gmsh")
    parser.add_argument("--work", default=None, help="default /tmp/<scene>_adaptive")
    parser.add_argument("--orders", type=int, nargs="+", default=[1, 2])
    parser.add_argument("--targets", type=float, nargs="+", default=[0.01, 0.001])
    parser.add_argument("--max-dofs", type=int, default=1500000)
    parser.add_argument("--sequence-p1", type=float, nargs="*", default=[0.04, 0.02, 0.01, 0.005])
    parser.add_argument("--sequence-t6", type=float, nargs="*", default=[0.02, 0.01, 0.005, 0.002, 0.001, 0.0005])
    parser.add_argument("--quick", action="store_true", help="P1 and T6 to 1 %% only, fixed meshes to 2e5 DOFs")
    args = parser.parse_args()
    SCENE = SCENES[args.scene]
    P0_REFERENCE, H0, H_FAR0 = SCENE["p0_reference"], SCENE["h"], SCENE["h_far"]
    if args.work is None:
        args.work = "/tmp/%s_adaptive" % args.scene
    if args.quick:
        args.targets, args.max_dofs, args.sequence_p1, args.sequence_t6 = [0.01], 200000, [], []
    args.runner = os.path.abspath(args.runner)
    summary = []
    for order in args.orders:
        kind = "P1" if order == 1 else "T6"
        series = {}
        for target in args.targets:
            rows, reached, wall = run_adaptive(args, here, order, target)
            print("\n%s adaptive to %g %% (%s; runner wall %.2f s):" % (kind, 100 * target,
                  "reached" if reached else "NOT reached within max_dofs %d" % args.max_dofs, wall))
            print("| step | DOFs | estimate | p0 vs ref | gmsh s | solve s | total s |")
            print("|---|---|---|---|---|---|---|")
            for r in rows:
                print("| %d | %d | %.3f %% | %+.3f %% | %.2f | %.3f | %.2f |" % (
                    r["step"], r["dofs"], 100 * r["estimate"], 100 * r["p0"], r["gmsh"], r["solve"], r["total"]))
            series[("adaptive", target)] = (rows, reached)
        sequence = args.sequence_p1 if order == 1 else args.sequence_t6
        if sequence:
            final = []
            print("\n%s adaptive meshes, one run per target (the last step of each):" % kind)
            print("| target | steps | DOFs | estimate | p0 vs ref | total s |")
            print("|---|---|---|---|---|---|")
            for target in sequence:
                if ("adaptive", target) in series:
                    rows, reached = series[("adaptive", target)]
                else:
                    rows, reached, _ = run_adaptive(args, here, order, target)
                    series[("adaptive", target)] = (rows, reached)
                r = rows[-1]
                print("| %g %% | %d | %d | %.3f %%%s | %+.3f %% | %.2f |" % (
                    100 * target, r["step"], r["dofs"], 100 * r["estimate"], "" if reached else " (stopped)",
                    100 * r["p0"], r["total"]))
                if reached:
                    final.append(r)
            print("estimate ~ DOFs^%.2f over these meshes" % -rate(final, last_half=False))
        for name, far in (("uniform", True), ("graded by hand", False)):
            rows = []
            k = 0
            while True:
                h = H0 / math.sqrt(2) ** k
                row = run_fixed(args, here, order, h, H_FAR0 / math.sqrt(2) ** k if far else H_FAR0)
                rows.append(row)
                k += 1
                if row["estimate"] <= min(args.targets) or row["dofs"] * 2 > args.max_dofs:
                    break
            print("\n%s %s (h, h_far of %s; gmsh + runner on each mesh alone), estimate ~ DOFs^%.2f over the "
                  "finer half:" % (kind, name, SCENE["geo"][1], -rate(rows)))
            print("| h | h_far | DOFs | estimate | p0 vs ref | gmsh + solve s |")
            print("|---|---|---|---|---|---|")
            for r in rows:
                print("| %.4g | %.4g | %d | %.3f %% | %+.3f %% | %.2f |" % (
                    r["h"], r["h_far"], r["dofs"], 100 * r["estimate"], 100 * r["p0"], r["total"]))
            series[name] = (rows, None)
        for target in args.targets:
            line = [kind, "%g %%" % (100 * target)]
            rows, reached = series[("adaptive", target)]
            line.append("%d DOFs, %.2f s (%d steps)" % (rows[-1]["dofs"], rows[-1]["total"], rows[-1]["step"])
                        if reached else "not within %d DOFs" % args.max_dofs)
            for name in ("uniform", "graded by hand"):
                r = first(series[name][0], lambda r: r["estimate"] <= target)
                line.append("%d DOFs, %.2f s" % (r["dofs"], r["total"]) if r else
                            "not within %d DOFs (%.2f %% at %d)" % (args.max_dofs, 100 * series[name][0][-1]["estimate"],
                                                                    series[name][0][-1]["dofs"]))
            summary.append(line)
        for threshold in (0.01, 0.001):  # p0 against the converged value, from that mesh on
            line = [kind, "p0 within %g %%" % (100 * threshold)]
            runs = [v[0] for k, v in series.items() if isinstance(k, tuple)]
            for rows_list in (runs, [series["uniform"][0]], [series["graded by hand"][0]]):
                best = None
                for rows in rows_list:
                    stays = [i for i in range(len(rows)) if all(abs(r["p0"]) <= threshold for r in rows[i:])]
                    if stays and (best is None or rows[stays[0]]["dofs"] < best):
                        best = rows[stays[0]]["dofs"]
                line.append("%d DOFs" % best if best else "not reached")
            summary.append(line)
    print("\n| cells | to reach | adaptive (from h = %g, h_far = %g) | uniform | graded by hand |" % (H0, H_FAR0))
    print("|---|---|---|---|---|")
    for line in summary:
        print("| " + " | ".join(line) + " |")


if __name__ == "__main__":
    main()
