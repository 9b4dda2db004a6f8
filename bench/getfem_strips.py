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
started with a rigid downward shift (it floats vertically). Prints, per nx: DOFs, Newton
iterations, the wall time of the model setup and of the solve, and the largest |lam - p| / p.

usage: /usr/bin/python3 bench/getfem_strips.py [--max-res r] [nx ...]
       (default: Newton's residual tolerance 1e-12, nx = 250 500 1000 2000 4000)
"""
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


def main():
    gf.util_trace_level(0)
    gf.util_warning_level(0)
    global MAX_RES
    args = sys.argv[1:]
    if len(args) >= 2 and args[0] == "--max-res":
        MAX_RES, args = float(args[1]), args[2:]
    sizes = [int(a) for a in args] or [250, 500, 1000, 2000, 4000]
    print("| nx | DOFs | multipliers | Newton iterations | converged | setup s | solve s | pressure error / p |")
    print("|---|---|---|---|---|---|---|---|")
    for nx in sizes:
        dofs, nlam, nit, conv, ts, tsol, err = solve(nx)
        print("| %d | %d | %d | %d | %s | %.3f | %.3f | %.1e |" % (nx, dofs, nlam, nit, conv, ts, tsol, err), flush=True)


if __name__ == "__main__":
    main()
