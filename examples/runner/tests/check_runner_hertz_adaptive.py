#!/usr/bin/env python3
"""docs/tutorial_adaptive.md, run as it says: the Hertz scene from a coarse uniform mesh to an
estimated error of 0.5 % on second-order triangles, and the plot of its meshes.

Copies examples/runner/hertz/hertz.geo and examples/runner/hertz_adaptive/hertz_adaptive.json
into WORK_DIR, runs the runner on the scene and checks:
  - exit code 0, the target of 0.5 % reached within 5 refinement steps, and the estimate of the
    last step at or below it;
  - the solution against Hertz: p0 within 0.3 % (the fine-mesh limit of this finite scene is
    0.18 % below Hertz's half-space value), the contact force equal to the load;
  - the files the tutorial names: the collection of every step, the scene's .pvd (the last
    step's), the pressure CSV;
then runs plot_steps.py on the collection, which must write its PNG.

usage: check_runner_hertz_adaptive.py RUNNER GMSH RUNNER_SOURCE_DIR WORK_DIR
"""

import os
import subprocess
import sys

from adaptive_target_run import check, p0_relative_error, run_to_target


def main():
    runner, gmsh, source, work = sys.argv[1:5]
    out, _ = run_to_target(runner, gmsh, work, [os.path.join(source, "hertz", "hertz.geo"),
                                                os.path.join(source, "hertz_adaptive", "hertz_adaptive.json")],
                           "hertz_adaptive")
    p0 = p0_relative_error(out)
    check(abs(p0) <= 0.3, "p0 %+.3f %% from Hertz (0.3 %% allowed)" % p0)
    check("contact force on body 1: (0, 0.01)" in out, "the contact force is not the load")
    png = os.path.join(work, "hertz_adaptive_steps.png")
    subprocess.run([sys.executable, os.path.join(source, "hertz_adaptive", "plot_steps.py"),
                    os.path.join(work, "hertz_adaptive_steps.pvd"), png], check=True)
    check(os.path.getsize(png) > 0, "no PNG")
    print("ok")


if __name__ == "__main__":
    main()
