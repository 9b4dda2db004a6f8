#!/usr/bin/env python3
"""The two-cylinder scene (examples/runner/cylinders_adaptive: R = 1 on R = 3, plane strain) run
as shipped: from a coarse mesh to an estimated error of 0.5 % on second-order triangles.

Copies cylinders.geo and cylinders_adaptive.json into WORK_DIR, runs the runner on the scene and
checks:
  - exit code 0, the target of 0.5 % reached within 5 refinement steps, and the estimate of the
    last step at or below it;
  - p0 within 0.5 % of the converged p0 of this finite scene (0.573 % below Hertz's value with
    the scene's mortar normals; docs/benchmarks.md, "Adaptive refinement"), the vertical
    contact force equal to the load;
  - the collection of every step's VTU files and the pressure CSV.
About a second.

usage: check_runner_cylinders_adaptive.py RUNNER GMSH RUNNER_SOURCE_DIR WORK_DIR
"""

import os
import re
import shutil
import subprocess
import sys

P0_REFERENCE = -0.573  # % from Hertz: the converged p0 of this scene


def check(condition, message):
    if not condition:
        sys.exit("FAILED: " + message)


def main():
    runner, gmsh, source, work = sys.argv[1:5]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    for name in ("cylinders.geo", "cylinders_adaptive.json"):
        shutil.copy(os.path.join(source, "cylinders_adaptive", name), work)
    result = subprocess.run([runner, "--gmsh", gmsh, "cylinders_adaptive.json"], cwd=work, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, check=False)
    out = result.stdout
    print(out)
    check(result.returncode == 0, "the runner exited with %d:\n%s" % (result.returncode, result.stderr))
    m = re.search(r"target reached at step (\d+): error estimate ([\d.]+) % <= 0.5 %", out)
    check(m is not None, "no 'target reached' line")
    check(int(m.group(1)) <= 5, "%s refinement steps, at most 5 expected" % m.group(1))
    check(float(m.group(2)) <= 0.5, "estimate %s %% above the target" % m.group(2))
    p0 = float(re.search(r"p0 = .*relative error (\S+) %", out).group(1))
    p0_vs_reference = 100 * ((1 + p0 / 100) / (1 + P0_REFERENCE / 100) - 1)
    check(abs(p0_vs_reference) <= 0.5, "p0 %+.3f %% from the converged value (0.5 %% allowed)" % p0_vs_reference)
    force = re.search(r"contact force on body 1: \((\S+), (\S+)\)", out)
    check(force is not None and abs(float(force.group(2)) - 0.01) <= 1e-8, "the contact force is not the load")
    for name in ("cylinders_adaptive_steps.pvd", "cylinders_adaptive.pvd", "cylinders_adaptive_pressure.csv",
                 "cylinders_adaptive_step%s_body1.vtu" % m.group(1)):
        check(os.path.getsize(os.path.join(work, name)) > 0, "no " + name)
    print("ok")


if __name__ == "__main__":
    main()
