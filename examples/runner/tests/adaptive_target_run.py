"""What the checks of the shipped adaptive scenes share (check_runner_hertz_adaptive.py,
check_runner_cylinders_adaptive.py): copy the scene into a fresh work directory, run the runner
with Gmsh, and check that it exits 0 with the target of 0.5 % reached within 5 refinement steps,
the last step's estimate at or below it, and the files of every step written."""

import os
import re
import shutil
import subprocess
import sys


def check(condition, message):
    if not condition:
        sys.exit("FAILED: " + message)


def run_to_target(runner, gmsh, work, sources, scene):
    """Copies the files `sources` into `work`, runs the runner on `work/scene.json` and checks the
    run as the module says. Returns the runner's output and the last step's number."""
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    for path in sources:
        shutil.copy(path, work)
    result = subprocess.run([runner, "--gmsh", gmsh, scene + ".json"], cwd=work, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, check=False)
    out = result.stdout
    print(out)
    check(result.returncode == 0, "the runner exited with %d:\n%s" % (result.returncode, result.stderr))
    m = re.search(r"target reached at step (\d+): error estimate ([\d.]+) % <= 0.5 %", out)
    check(m is not None, "no 'target reached' line")
    check(int(m.group(1)) <= 5, "%s refinement steps, at most 5 expected" % m.group(1))
    check(float(m.group(2)) <= 0.5, "estimate %s %% above the target" % m.group(2))
    for name in (scene + "_steps.pvd", scene + ".pvd", scene + "_pressure.csv",
                 "%s_step%s_body1.vtu" % (scene, m.group(1))):
        check(os.path.getsize(os.path.join(work, name)) > 0, "no " + name)
    return out, m.group(1)


def p0_relative_error(out):
    """p0's relative error against Hertz in %, as the runner prints it."""
    return float(re.search(r"p0 = .*relative error (\S+) %", out).group(1))
