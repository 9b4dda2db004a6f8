#!/usr/bin/env python3
"""The runner's adaptive refinement (scene key "adaptive") on a small scene, end to end.

adaptive_disc.json (a half-disc pressed on a block, adaptive_disc.geo meshed coarse and
uniform) asks for an estimated error of 3 %. The runner meshes the .geo with Gmsh, solves,
remeshes with the size field of the error indicators, and repeats. This script checks:
  - exit code 0, the target reached within 4 refinement steps, the table printed, every step's
    estimate falling and the last one at or below the target;
  - every step's files: the mesh, the size field and .geo Gmsh meshed it from (steps >= 1), the
    VTU files with the cell data "error_indicator", whose squares over both bodies add up to the
    square of the step's estimate; the collection of all steps, and the scene's output .pvd
    naming the last step's files; the pressure CSV;
  - refinement where the error is: in the last mesh, the cells near the contact (within 0.3 of
    the first contact point) are at least 4 times smaller than the coarse start's, and smaller
    than those far from it (the lower quarter of the block);
  - the same scene on second-order triangles ("order": 2) to 1 % within 4 steps;
  - adaptive.max_dofs: a mesh predicted above it stops the run with exit code 3 and its message.

usage: check_runner_adaptive.py RUNNER GMSH DATA_DIR WORK_DIR
"""

import json
import math
import os
import re
import shutil
import subprocess
import sys


def check(condition, message):
    if not condition:
        sys.exit("FAILED: " + message)


def run(command, cwd, code=0):
    result = subprocess.run(command, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, check=False)
    if result.returncode != code:
        sys.exit("FAILED: %s exited with %d, expected %d:\n%s%s" % (" ".join(command), result.returncode, code,
                                                                     result.stdout, result.stderr))
    return result.stdout, result.stderr


def table(out):
    """The runner's table: [(step, cells, dofs, estimate)]."""
    rows = [(int(m.group(1)), int(m.group(2)), int(m.group(3)), float(m.group(4)) / 100)
            for m in re.finditer(r"^\s+(\d+)\s+(\d+)\s+(\d+)\s+\S+\s+([\d.]+) %\s", out, re.M)]
    check(rows and [r[0] for r in rows] == list(range(len(rows))), "no table of steps 0, 1, ... in:\n" + out)
    return rows


def vtu_array(text, name):
    m = re.search(r'Name="%s"[^>]*>(.*?)</DataArray>' % name, text, re.S)
    check(m is not None, "no array %s" % name)
    return [float(v) for v in m.group(1).split()]


def cell_sizes(vtu):
    """(centroid x, y, size) of every cell of a VTU written by mc_write_vtu (corners only)."""
    text = open(vtu).read()
    xyz = vtu_array(text, "coordinates")
    conn = [int(v) for v in vtu_array(text, "connectivity")]
    offsets = [int(v) for v in vtu_array(text, "offsets")]
    types = [int(v) for v in vtu_array(text, "types")]
    cells, start = [], 0
    for end, t in zip(offsets, types):
        corners = conn[start:start + (3 if t in (5, 22) else 4)]
        start = end
        pts = [(xyz[3 * i], xyz[3 * i + 1]) for i in corners]
        area = 0.5 * abs(sum(pts[k][0] * pts[(k + 1) % len(pts)][1] - pts[(k + 1) % len(pts)][0] * pts[k][1]
                             for k in range(len(pts))))
        size = math.sqrt(4 * area / math.sqrt(3)) if len(pts) == 3 else math.sqrt(area)
        cells.append((sum(p[0] for p in pts) / len(pts), sum(p[1] for p in pts) / len(pts), size))
    return cells


def main():
    runner, gmsh, data, work = sys.argv[1:5]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    for name in ("adaptive_disc.geo", "adaptive_disc.json"):
        shutil.copy(os.path.join(data, name), work)
    target = 0.03

    # ---- P1 to 3 % ----
    out, err = run([runner, "--gmsh", gmsh, "adaptive_disc.json"], work)
    rows = table(out)
    steps = rows[-1][0]
    check(1 <= steps <= 4, "the target of 3 %% took %d refinement steps (at most 4 expected):\n%s" % (steps, out))
    check("target reached at step %d" % steps in out, "no 'target reached' line:\n" + out)
    check(rows[-1][3] <= target, "last estimate %g above the target" % rows[-1][3])
    check(all(b[3] < a[3] for a, b in zip(rows, rows[1:])), "the estimate does not fall at every step: %s" % rows)
    check(all(r[3] > target for r in rows[:-1]), "the loop went on below the target: %s" % rows)
    print("P1: %s" % ", ".join("step %d %d DOFs %.2f %%" % (r[0], r[2], 100 * r[3]) for r in rows))

    out_dir = os.path.join(work, "adaptive_out")
    for step, cells, dofs, estimate in rows:
        check(os.path.getsize(os.path.join(work, "adaptive_disc_step%d.msh" % step)) > 0, "no mesh of step %d" % step)
        if step > 0:
            for suffix in (".geo", "_size.pos"):
                check(os.path.exists(os.path.join(work, "adaptive_disc_step%d%s" % (step, suffix))),
                      "no adaptive_disc_step%d%s" % (step, suffix))
        squares, n_cells = 0.0, 0
        for body in (1, 2):
            text = open(os.path.join(out_dir, "adaptive_disc_step%d_body%d.vtu" % (step, body))).read()
            eta = vtu_array(text, "error_indicator")
            n_cells += len(eta)
            check(len(eta) == len(vtu_array(text, "von_mises")), "step %d body %d: one indicator per cell" % (step, body))
            check(all(e >= 0 for e in eta), "negative indicator")
            squares += sum(e * e for e in eta)
        check(n_cells == cells, "step %d: %d cells in the VTU files, the table says %d" % (step, n_cells, cells))
        # The table prints the estimate to 3 decimals of a percent.
        check(abs(math.sqrt(squares) - estimate) <= 5.1e-6 + 1e-9 * estimate,
              "step %d: the indicators' squares sum to %.6g^2, the estimate is %.6g" % (step, math.sqrt(squares), estimate))
    collection = open(os.path.join(out_dir, "adaptive_disc_steps.pvd")).read()
    for step, *_ in rows:
        for body in (1, 2):
            check('timestep="%d" group="" part="%d" file="adaptive_disc_step%d_body%d.vtu"' % (step, body - 1, step, body)
                  in collection, "the steps collection misses step %d body %d" % (step, body))
    final = open(os.path.join(out_dir, "adaptive_disc.pvd")).read()
    check('file="adaptive_disc_step%d_body1.vtu"' % steps in final, "the scene's .pvd does not name the last step")
    check(os.path.getsize(os.path.join(out_dir, "adaptive_disc_pressure.csv")) > 0, "no pressure CSV")
    check("contact force on body 1: (0, 0.02)" in out, "the contact force is not the load 0.02:\n" + out)

    # Refined where the error is: the contact zone, not the far side of the block.
    first = cell_sizes(os.path.join(out_dir, "adaptive_disc_step0_body2.vtu"))
    last = cell_sizes(os.path.join(out_dir, "adaptive_disc_step%d_body1.vtu" % steps)) + \
        cell_sizes(os.path.join(out_dir, "adaptive_disc_step%d_body2.vtu" % steps))
    near = [c[2] for c in last if math.hypot(c[0], c[1]) < 0.3]
    far = [c[2] for c in last if c[1] < -0.75]
    start = sum(c[2] for c in first) / len(first)
    near_mean, far_mean = sum(near) / len(near), sum(far) / len(far)
    print("cell size: start %.4g; last step near the contact %.4g, far (y < -0.75) %.4g" % (start, near_mean, far_mean))
    check(near_mean < start / 4, "the contact zone was not refined 4 times: %.4g against %.4g" % (near_mean, start))
    check(near_mean < far_mean / 2, "the contact zone (%.4g) is not finer than far from it (%.4g)" % (near_mean, far_mean))

    # ---- T6 to 1 % ----
    scene = json.load(open(os.path.join(work, "adaptive_disc.json")))
    scene["adaptive"].update({"order": 2, "target_error": 0.01})
    for b in scene["bodies"]:
        b["mesh"] = "t6.msh"
    scene["output"] = {"vtu": "t6_out/t6.vtu"}
    json.dump(scene, open(os.path.join(work, "t6.json"), "w"))
    out, _ = run([runner, "--quiet", "--gmsh", gmsh, "t6.json"], work)
    rows = table(out)
    check(1 <= rows[-1][0] <= 4 and rows[-1][3] <= 0.01, "T6 to 1 %%: %s" % rows)
    text = open(os.path.join(work, "t6_out", "t6_step%d.vtu" % rows[-1][0])).read()
    check(set(vtu_array(text, "types")) == {22.0}, "T6: VTK type 22 expected")
    check(abs(math.sqrt(sum(e * e for e in vtu_array(text, "error_indicator"))) - rows[-1][3]) <= 5.1e-6,
          "T6: indicators against the estimate")
    print("T6: %s" % ", ".join("step %d %d DOFs %.3f %%" % (r[0], r[2], 100 * r[3]) for r in rows))

    # ---- a DOF limit ----
    scene["adaptive"].update({"order": 1, "target_error": 0.001, "max_dofs": 5000})
    scene.pop("output")
    for b in scene["bodies"]:
        b["mesh"] = "limited.msh"
    json.dump(scene, open(os.path.join(work, "limited.json"), "w"))
    out, err = run([runner, "--quiet", "--gmsh", gmsh, "limited.json"], work, code=3)
    check(re.search(r"adaptive refinement stopped above its target: the next mesh would have about \d+ DOFs, above "
                    r"adaptive.max_dofs = 5000; the estimate is \S+ % at step \d+", err), "max_dofs message:\n" + err)
    print("ok")


if __name__ == "__main__":
    main()
