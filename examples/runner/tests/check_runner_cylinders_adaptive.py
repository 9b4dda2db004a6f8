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
import sys

from adaptive_target_run import check, p0_relative_error, run_to_target

P0_REFERENCE = -0.573  # % from Hertz: the converged p0 of this scene


def main():
    runner, gmsh, source, work = sys.argv[1:5]
    out, _ = run_to_target(runner, gmsh, work, [os.path.join(source, "cylinders_adaptive", name)
                                                for name in ("cylinders.geo", "cylinders_adaptive.json")],
                           "cylinders_adaptive")
    p0 = p0_relative_error(out)
    p0_vs_reference = 100 * ((1 + p0 / 100) / (1 + P0_REFERENCE / 100) - 1)
    check(abs(p0_vs_reference) <= 0.5, "p0 %+.3f %% from the converged value (0.5 %% allowed)" % p0_vs_reference)
    force = re.search(r"contact force on body 1: \((\S+), (\S+)\)", out)
    check(force is not None and abs(float(force.group(2)) - 0.01) <= 1e-8, "the contact force is not the load")
    print("ok")


if __name__ == "__main__":
    main()
