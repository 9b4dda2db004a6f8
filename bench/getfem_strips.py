#!/usr/bin/python3
"""GetFEM peer of bench/long_interface.c: two strips in contact along their whole length.

Scene (plane strain, E = 1, nu = 0.3, as long_interface.c): body 1 = [0, L] x [0, 0.4] on
nx x 4 squares, body 2 = [0, L] x [-0.4, 0] on round(1.37 nx) x 4 (P1, two triangles per
square, GetFEM's regular simplices; non-matching meshes), L = nx / 10; a pressure p = 0.01 on
body 1's top; body 2 held vertically on its bottom; both held horizontally at their left
bottom corner. Every contact pressure is exactly p.

Contact: GetFEM's integral Alart-Curnier formulation in its weak-form language, as the "gwfl"
formulation of bench/getfem_hertz.py: a P1 multiplier lam on body 1's bottom, the gap through
the interpolate transformation X -> (X_x, 0) onto body 2's flat top; Newton with MUMPS, body 1
started with a rigid downward shift (it floats vertically). Prints, per nx (the nx list of
build/bench/long_interface, so that the rows go beside its tables): DOFs, Newton iterations,
the wall time of the model setup, of the solve and both, the largest |lam - p| / p, and the
peak resident memory of that size alone: each size runs in a child process of its own (this
script again, with --one nx), whose ru_maxrss the parent reads with wait4 (it includes the
Python interpreter and GetFEM's modules, about 60 MiB).

usage: /usr/bin/python3 bench/getfem_strips.py [--max-res r] [--timeout s] [--json file] [nx ...]
       --max-res  Newton's residual tolerance (default 1e-12; the documented runs use 1e-9:
                  from nx = 2000 on GetFEM's residual does not reach 1e-12, and Newton stops at
                  its 30-iteration limit)
       --timeout  wall-time limit per size in seconds (default 3600; the row then says so)
       --json     also writes the rows to this file
       nx ...     default 250 500 1000 2000 4000 8000 16000
"""
import json
import os
import signal
import subprocess
import sys
import time

import numpy as np

import getfem as gf
from getfem_common import add_flat_integral_contact, elastic_bodies

E, NU, PRESSURE, HEIGHT, SHIFT = 1.0, 0.3, 0.01, 0.4, 1e-3
MAX_RES = 1e-12  # Newton's residual tolerance (--max-res)
BOTTOM, TOP, CONTACT = 1, 2, 3


def strip(nx, length, y0):
    """GetFEM's structured P1 mesh of [0, length] x [y0, y0 + HEIGHT], nx x 4 squares."""
    m = gf.Mesh("regular simplices", np.linspace(0, length, nx + 1), np.linspace(y0, y0 + HEIGHT, 5))
    normals = m.normal_of_faces(m.outer_faces())
    faces = m.outer_faces()
    m.set_region(BOTTOM, faces[:, normals[1] < -0.5])
    m.set_region(TOP, faces[:, normals[1] > 0.5])
    return m


def corner_dof(mf):
    """The x dof of the node at the strip's left bottom corner."""
    nodes = mf.basic_dof_nodes()
    xs = np.arange(0, mf.nbdof(), 2)
    k = xs[np.lexsort((nodes[1, xs], nodes[0, xs]))[0]]
    return int(k)


def solve(nx):
    length = 0.1 * nx
    t0 = time.perf_counter()
    m1, m2 = strip(nx, length, 0.0), strip(int(round(1.37 * nx)), length, -HEIGHT)
    m1.set_region(CONTACT, m1.region(BOTTOM))
    md, (mfu1, mfu2), (mim1, _) = elastic_bodies(gf, m1, m2, E, NU)
    md.add_source_term(mim1, "[0;%.17g].Test_u1" % -PRESSURE, TOP)
    # body 2: u_y = 0 on its bottom; both bodies: u_x = 0 at the left bottom corner (pointwise)
    bottom_pts = mfu2.basic_dof_nodes(np.sort(mfu2.basic_dof_on_region(BOTTOM))[::2])
    md.add_initialized_data("b2_pts", bottom_pts.T.ravel())
    md.add_initialized_data("b2_dir", np.tile([0.0, 1.0], bottom_pts.shape[1]))
    md.add_pointwise_constraints_with_multipliers("u2", "b2_pts", "b2_dir")
    for name, mf, var in (("c1", mfu1, "u1"), ("c2", mfu2, "u2")):
        pt = mf.basic_dof_nodes([corner_dof(mf)])[:, 0]
        md.add_initialized_data(name + "_pt", pt)
        md.add_initialized_data(name + "_dir", [1.0, 0.0])
        md.add_pointwise_constraints_with_multipliers(var, name + "_pt", name + "_dir")
    add_flat_integral_contact(gf, md, m1, m2, CONTACT, E * nx / length)  # r = E / h
    u1 = np.zeros(mfu1.nbdof())
    u1[1::2] = -SHIFT
    md.set_variable("u1", u1)
    t_setup = time.perf_counter() - t0
    t0 = time.perf_counter()
    nit, converged = md.solve("lsolver", "mumps", "max_res", MAX_RES, "max_iter", 30)
    t_solve = time.perf_counter() - t0
    lam = np.asarray(md.variable("lam"))
    err = float(np.max(np.abs(lam - PRESSURE)) / PRESSURE)
    return mfu1.nbdof() + mfu2.nbdof(), len(lam), int(nit), bool(converged), t_setup, t_solve, err


KEYS = ("dofs", "multipliers", "newton_iterations", "converged", "setup_s", "solve_s", "pressure_error")


def run_one(nx, timeout):
    """One size in a child process (this script with --one): its row, and its own peak RSS."""
    proc = subprocess.Popen([sys.executable, os.path.abspath(__file__), "--one", str(nx), "--max-res", repr(MAX_RES),
                             "--timeout", str(timeout)], stdout=subprocess.PIPE)
    out = proc.stdout.read()
    proc.stdout.close()
    _, status, usage = os.wait4(proc.pid, 0)
    proc.returncode = os.waitstatus_to_exitcode(status)  # already reaped: Popen must not wait again
    row = {"nx": nx, "peak_mib": usage.ru_maxrss / 1024.0}
    if proc.returncode == 0:
        row.update(json.loads(out))
    elif proc.returncode == -signal.SIGALRM:
        row["failed"] = "timed out after %d s" % timeout
    else:
        row["failed"] = "exit status %d" % proc.returncode
    return row


def main():
    global MAX_RES
    args, sizes, timeout, json_path, one = sys.argv[1:], [], 3600, None, None
    while args:
        if args[0] == "--max-res" and len(args) >= 2:
            MAX_RES, args = float(args[1]), args[2:]
        elif args[0] == "--timeout" and len(args) >= 2:
            timeout, args = int(args[1]), args[2:]
        elif args[0] == "--json" and len(args) >= 2:
            json_path, args = args[1], args[2:]
        elif args[0] == "--one" and len(args) >= 2:
            one, args = int(args[1]), args[2:]
        else:
            sizes.append(int(args[0]))
            args = args[1:]
    if one is not None:  # the child: one size, its row as JSON on stdout
        gf.util_trace_level(0)
        gf.util_warning_level(0)
        if timeout > 0:
            signal.alarm(timeout)
        print(json.dumps(dict(zip(KEYS, solve(one)))))
        return
    sizes = sizes or [250, 500, 1000, 2000, 4000, 8000, 16000]
    try:
        version = subprocess.run(["dpkg-query", "-W", "-f", "${Version}", "python3-getfem"], capture_output=True,
                                 text=True).stdout.strip() or "?"
    except OSError:
        version = "?"
    print("GetFEM (python3-getfem %s), MUMPS, max_res %g, one child process per size (timeout %d s)"
          % (version, MAX_RES, timeout))
    print()
    print("| nx | DOFs | multipliers | Newton iterations | converged | setup s | solve s | total s | peak MiB "
          "| pressure error / p |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    rows = []
    for nx in sizes:
        r = run_one(nx, timeout)
        rows.append(r)
        if "failed" in r:
            print("| %d | FAILED: %s | | | | | | | %.0f | |" % (nx, r["failed"], r["peak_mib"]), flush=True)
            continue
        print("| %d | %d | %d | %d | %s | %.3f | %.3f | %.3f | %.0f | %.1e |" % (
            nx, r["dofs"], r["multipliers"], r["newton_iterations"], r["converged"], r["setup_s"], r["solve_s"],
            r["setup_s"] + r["solve_s"], r["peak_mib"], r["pressure_error"]), flush=True)
    if json_path:
        with open(json_path, "w") as fh:
            json.dump(rows, fh, indent=1)


if __name__ == "__main__":
    main()
