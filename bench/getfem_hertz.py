#!/usr/bin/python3
"""GetFEM peer benchmark of the shared Hertz scene (docs: method.md, "Shared benchmark scenes").

Scene (plane strain, unit thickness, E = 1, nu = 0.3 for both bodies):
  body 1: lower half-disc of radius R = 1 centred at (0,1), flat top y = 1, touching the origin;
          uniform downward traction P/2 per unit length on the top (total P = 0.01);
          u_x = 0 at its nodes on the axis x = 0; held vertically by contact alone.
  body 2: block [-4,4] x [-4,0], clamped at y = -4.
Meshes: the graded P1 meshes of examples/scenes/hertz_scene.c, re-implemented below in numpy
(same construction, same floating-point operations; check with --dump against the C generator).
Contact candidates: body-1 arc edges with |x| <= 0.5 (slave), body-2 top edges with |x| <= 1.

Two GetFEM formulations of frictionless contact, both solved by GetFEM's Newton solver with
MUMPS (passed explicitly: GetFEM's 'auto' choice switches to an iterative solver above 300k
DOFs in 2D):
  nodal  add_nodal_contact_between_nonmatching_meshes_brick: node-to-segment. Each body-1
         contact node is projected onto body 2's surface along the master normal; one
         multiplier per node = the nodal contact force; Alart-Curnier (non-symmetric) Newton.
  gwfl   the integral Alart-Curnier formulation written in GetFEM's weak-form language: a P1
         multiplier lam (contact pressure, >= 0) on body 1's contact edges, and the gap at a
         body-1 surface point X, g = X_y + u1_y(X) - u2_y(X_x, 0), through the interpolate
         transformation X -> (X_x, 0) onto body 2's flat top (no release distance, so unlike
         add_integral_contact_between_nonmatching_meshes_brick, whose projection drops slave
         points farther than 5% of a master element, getfem_projected_fem.cc, no point is lost):
             - int lam (v1_y - v2_y(Pi X)) + int (1/r)(lam - pos_part(lam - r g)) mu = 0.
Body 1 floats vertically, so Newton needs a start that touches: u1 starts as a rigid downward
shift of DELTA0 = 0.01 (the far end of the initial overlap is near the Hertz half-width).
No spring is added: the answer is the unregularised one.

Measured per size and formulation: DOFs (displacements of both bodies; the multipliers are
reported apart), contact nodes, Newton iterations, wall time of the GetFEM model setup (fems,
integration methods, bricks) and of the solve (assembly, MUMPS, Newton), p0, a, errors against
Hertz and the force balance |sum of contact forces - P| / P.
  p0: nodal: lumped pressure lambda_j / integral of phi_j over the contact edges (the recovery
      mortarcontact documents), max over the nodes; gwfl: the max nodal value of lam.
      p(0), the value at the node x = 0, is printed too: with non-matching meshes the nodal
      (node-to-segment) pressures oscillate node to node by several per cent, which inflates
      the max; the oscillation disappears for matching meshes (--ratio 1).
  a:  on each side, walking out from x = 0, the last node with p > 1e-10 max p (the "last
      loaded node") and the one before it: Hertz gives p^2 linear in x^2, so p^2 is
      extrapolated linearly in x^2 to zero through these two, clamped between the last loaded
      node and the next one; a is the mean of both sides. The last loaded node's value averages over a tributary that
      straddles the edge, so this "a" is biased low by a fraction of the spacing (O(h)).
      Hence also a_moment = 2 sqrt(int p x^2 / int p), exact for the Hertz (elliptical)
      distribution, from the nodal forces (nodal) or from int lam x^2 ds (gwfl); it converges
      much faster and is the better number to compare codes with.
"""
import argparse
import contextlib
import json
import math
import os
import sys
import time

import numpy as np

from getfem_common import add_flat_integral_contact, elastic_bodies

E, NU, P, RADIUS = 1.0, 0.3, 0.01, 1.0
GROWTH, FINE_HALF_WIDTH, MAX_SCALED_CELLS = 1.15, 0.4, 8
DELTA0 = 0.01  # initial rigid downward shift of body 1 (Newton start), not part of the answer


# ---------------------------------------------------------------------------------------------
# Mesh: a line-by-line mirror of examples/scenes/hertz_scene.c (see the comments there for why).
# Python floats follow the same IEEE operations in the same order, so the nodes agree bit for bit.

def graded_axis(w, h, length):
    n_u = max(1, int(math.floor(w / h + 0.5)))
    hu = w / n_u
    rest = length - w
    n_hi, s_hi, a = 0, 0.0, hu
    while s_hi < rest:
        a *= GROWTH
        s_hi += a
        n_hi += 1
    s_lo = s_hi - a
    n_g = n_hi - 1 if (n_hi > 1 and rest - s_lo < s_hi - rest) else n_hi
    for _ in range(2):
        d, total, c = [], 0.0, hu
        for _k in range(n_g):
            c *= GROWTH
            d.append(c)
            total += c
        m = min(n_g, MAX_SCALED_CELLS)
        tail = 0.0
        for k in range(n_g - m, n_g):
            tail += d[k]
        scale = (rest - (total - tail)) / tail
        for k in range(n_g - m, n_g):
            d[k] *= scale
        monotone = d[0] >= hu and all(d[k] >= d[k - 1] for k in range(1, n_g))
        if monotone or n_g == n_hi - 1 or n_hi == 1:
            break
        n_g = n_hi - 1
    p = [i * hu for i in range(n_u)] + [w]
    for k in range(n_g):
        p.append(p[n_u + k] + d[k])
    p[-1] = length
    return np.array(p)


def symmetric_axis(w, h, length):
    p = graded_axis(w, h, length)
    return np.concatenate([-p[:0:-1], [0.0], p[1:]])


def grid_triangles(nx, ny, flip_i=-1, flip_j=-1):
    """P1 triangles of an nx x ny grid, node (i,j) = j*(nx+1)+i, split along lower-left /
    upper-right except in cell (flip_i, flip_j)."""
    j, i = np.meshgrid(np.arange(ny), np.arange(nx), indexing="ij")
    ll = (j * (nx + 1) + i).ravel()
    lr, ul = ll + 1, ll + nx + 1
    ur = ul + 1
    t = np.empty((2 * nx * ny, 3), dtype=np.int64)
    t[0::2] = np.stack([ll, lr, ur], axis=1)
    t[1::2] = np.stack([ll, ur, ul], axis=1)
    if flip_i >= 0:
        c = flip_j * nx + flip_i
        t[2 * c] = [ll[c], lr[c], ul[c]]
        t[2 * c + 1] = [lr[c], ur[c], ul[c]]
    return t


def edges_within(xy, edges, xmax):
    e = np.asarray(edges, dtype=np.int64).reshape(-1, 2)
    keep = (np.abs(xy[e[:, 0], 0]) <= xmax) & (np.abs(xy[e[:, 1], 0]) <= xmax)
    return e[keep]


def hertz_scene(h1, h2):
    if not (0.0 < h1 <= 0.2 and 0.0 < h2 <= 0.2):
        raise ValueError("h1, h2 must be in (0, 0.2]")
    sc = {}
    # body 1: elliptical-grid map of the square (s,t) in [-1,1] x [-1,0]
    r2 = math.sqrt(2.0)
    s = symmetric_axis(FINE_HALF_WIDTH * r2, h1 * r2, 1.0)
    q = graded_axis(FINE_HALF_WIDTH * r2, h1 * r2, 1.0)
    ns, nt = len(s) - 1, len(q) - 1
    t = -1.0 + q
    t[-1] = 0.0
    T, S = np.meshgrid(t, s, indexing="ij")
    x = S * np.sqrt(1.0 - 0.5 * T * T)
    y = T * np.sqrt(1.0 - 0.5 * S * S)
    on_arc = np.zeros_like(x, dtype=bool)
    on_arc[0, :] = on_arc[:, 0] = on_arc[:, ns] = True
    r = np.hypot(x[on_arc], y[on_arc])
    x[on_arc] /= r
    y[on_arc] /= r
    x[:, ns // 2] = 0.0
    y = 1.0 + y
    y[nt, :] = 1.0
    xy1 = np.stack([x.ravel(), y.ravel()], axis=1)
    sc["xy1"], sc["tri1"] = xy1, grid_triangles(ns, nt, ns - 1, 0)
    node = lambda i, j: j * (ns + 1) + i  # noqa: E731
    arc = [(node(0, j), node(0, j - 1)) for j in range(nt, 0, -1)]
    arc += [(node(i, 0), node(i + 1, 0)) for i in range(ns)]
    arc += [(node(ns, j), node(ns, j + 1)) for j in range(nt)]
    sc["contact1"] = edges_within(xy1, arc, 0.5)
    sc["top1"] = np.array([(node(i + 1, nt), node(i, nt)) for i in range(ns - 1, -1, -1)])
    sc["axis1"] = np.array([node(ns // 2, j) for j in range(nt + 1)])
    # body 2: tensor grid of the block
    xg = symmetric_axis(FINE_HALF_WIDTH, h2, 4.0)
    p = graded_axis(FINE_HALF_WIDTH, h2, 4.0)
    yg = -p[::-1]
    yg[-1] = 0.0
    nx, ny = len(xg) - 1, len(yg) - 1
    Y, X = np.meshgrid(yg, xg, indexing="ij")
    xy2 = np.stack([X.ravel(), Y.ravel()], axis=1)
    sc["xy2"], sc["tri2"] = xy2, grid_triangles(nx, ny)
    top = [(ny * (nx + 1) + i + 1, ny * (nx + 1) + i) for i in range(nx - 1, -1, -1)]
    sc["contact2"] = edges_within(xy2, top, 1.0)
    sc["bottom2"] = np.arange(nx + 1)
    return sc


def hertz_analytic():
    e_star = 1.0 / (2.0 * (1.0 - NU * NU) / E)
    a = math.sqrt(4.0 * P * RADIUS / (math.pi * e_star))
    return a, 2.0 * P / (math.pi * a)


# ---------------------------------------------------------------------------------------------
# GetFEM model

CONTACT, TOP, BOTTOM = 1, 2, 3


def faces_of_edges(tri, edges):
    """(convex, local face) pairs of boundary edges; GetFEM's face f of a triangle is the edge
    opposite its vertex f."""
    loc = np.concatenate([tri[:, [1, 2]], tri[:, [2, 0]], tri[:, [0, 1]]])
    key = np.sort(loc, axis=1) @ np.array([1, 1 << 31], dtype=np.int64)
    order = np.argsort(key)
    want = np.sort(np.asarray(edges), axis=1) @ np.array([1, 1 << 31], dtype=np.int64)
    pos = order[np.searchsorted(key, want, sorter=order)]
    assert np.array_equal(key[pos], want), "edge not found in the mesh"
    n = len(tri)
    return np.stack([pos % n, pos // n])


def gf_mesh(gf, xy, tri):
    m = gf.Mesh("pt2D", xy.T.copy(), tri.T.copy())
    # GetFEM merges coincident points when building a mesh; ours are distinct, so the point
    # numbering must be ours exactly (the regions and constraints below rely on it).
    assert m.nbpts() == len(xy) and np.array_equal(m.pts(), xy.T), "GetFEM renumbered the points"
    return m


def solve(gf, sc, formulation, h1, args):
    """Builds and solves one GetFEM model; returns the measured row."""
    t0 = time.perf_counter()
    m1, m2 = gf_mesh(gf, sc["xy1"], sc["tri1"]), gf_mesh(gf, sc["xy2"], sc["tri2"])
    m1.set_region(CONTACT, faces_of_edges(sc["tri1"], sc["contact1"]))
    m1.set_region(TOP, faces_of_edges(sc["tri1"], sc["top1"]))
    m2.set_region(CONTACT, faces_of_edges(sc["tri2"], sc["contact2"]))
    bottom = sc["bottom2"]
    m2.set_region(BOTTOM, faces_of_edges(sc["tri2"], np.stack([bottom[:-1], bottom[1:]], axis=1)))
    t_mesh = time.perf_counter() - t0

    t0 = time.perf_counter()
    md, (mfu1, mfu2), (mim1, mim2) = elastic_bodies(gf, m1, m2, E, NU)
    md.add_source_term(mim1, "[0;%.17g].Test_u1" % (-P / 2.0), TOP)
    md.add_Dirichlet_condition_with_simplification("u2", BOTTOM)
    axis = sc["axis1"]
    md.add_initialized_data("axis_pts", sc["xy1"][axis].ravel())
    md.add_initialized_data("axis_dir", np.tile([1.0, 0.0], len(axis)))
    md.add_pointwise_constraints_with_multipliers("u1", "axis_pts", "axis_dir")

    # body-1 contact nodes: GetFEM orders the nodal multipliers by increasing x-dof of u1
    dofs = mfu1.basic_dof_on_region(CONTACT)
    dofs = np.sort(dofs[dofs % 2 == 0])
    pts = mfu1.basic_dof_nodes(dofs)
    # lumped weights: integral of each hat function over the contact edges (chords)
    nid = {tuple(np.round(sc["xy1"][k], 15)): k for k in np.unique(sc["contact1"])}
    node_of_dof = np.array([nid[tuple(np.round(pt, 15))] for pt in pts.T])
    w = np.zeros(len(sc["xy1"]))
    e = sc["contact1"]
    half = 0.5 * np.hypot(*(sc["xy1"][e[:, 0]] - sc["xy1"][e[:, 1]]).T)
    np.add.at(w, e[:, 0], half)
    np.add.at(w, e[:, 1], half)
    weight = w[node_of_dof]
    x_nodes = sc["xy1"][node_of_dof, 0]

    if formulation == "nodal":
        # r only steers Newton (any r > 0 gives the same solution); a nodal force over a
        # gap is a stiffness, E*h1 is the order of the diagonal of K at a surface node
        md.add_initialized_data("r", [E * h1])
        with c_stdout_silenced():  # Debian's GetFEM 5.4 prints a stray "ok here" in this call
            md.add_nodal_contact_between_nonmatching_meshes_brick(
                mim1, mim2, "u1", "u2", "lam_n", "r", CONTACT, CONTACT, 1, 0, 1)
    else:
        # pointwise the Alart-Curnier equation has the same roots for every r > 0; tested in
        # its weak (integral) form against P1 mu it does not exactly, hence --gwfl-r-scale
        mfl, mimc = add_flat_integral_contact(gf, md, m1, m2, CONTACT, args.gwfl_r_scale * E / h1)
    # Newton start: body 1 shifted rigidly down so that it overlaps body 2 near x = 0
    u1 = np.zeros(mfu1.nbdof())
    u1[1::2] = -DELTA0
    md.set_variable("u1", u1)
    t_setup = time.perf_counter() - t0

    t0 = time.perf_counter()
    nit, converged = md.solve("lsolver", "mumps", *(["lsearch", args.lsearch] if args.lsearch else []),
                              "max_res", args.max_res, "max_iter", args.max_iter,
                              *(["noisy"] if args.noisy else []))
    t_solve = time.perf_counter() - t0

    if formulation == "nodal":
        lam = np.asarray(md.variable("lam_n"))
        # GetFEM's multiplier is the force on the slave node along -n (n = (0,1) here), so a
        # compressive contact force is negative; the sign is checked by the force balance
        force = -lam
        pressure = force / weight
        total = force.sum()
        moment2 = (force * x_nodes ** 2).sum()
    else:
        # Interpolate() silently gives 0 at a point it cannot locate in body 2: check that
        # every contact quadrature point lands in body 2 by interpolating a field equal to 1
        mf2 = gf.MeshFem(m2, 1)
        mf2.set_classical_fem(1)
        md.add_initialized_fem_data("one2", mf2, np.ones(mf2.nbdof()))
        lost = gf.asm_generic(mimc, 0, "1 - Interpolate(one2,Pi)", CONTACT, md)
        assert abs(lost) < 1e-14, "contact points not located in body 2 (measure %g)" % lost
        lam_full = np.asarray(md.variable("lam"))
        # the filtered variable holds the region's dofs of mfl in increasing order
        ldofs = np.sort(mfl.basic_dof_on_region(CONTACT))
        lpts = mfl.basic_dof_nodes(ldofs)
        lnode = np.array([nid[tuple(np.round(pt, 15))] for pt in lpts.T])
        pmap = dict(zip(lnode, lam_full))
        pressure = np.array([pmap[k] for k in node_of_dof])
        total = gf.asm_generic(mimc, 0, "lam", CONTACT, md)
        moment2 = gf.asm_generic(mimc, 0, "lam*X(1)*X(1)", CONTACT, md)
    a_h, p0_h = hertz_analytic()
    p0 = pressure.max()
    pc = pressure[np.argmin(np.abs(x_nodes))]
    a, n_loaded = contact_half_width(x_nodes, pressure)
    # second moment of the Hertz (elliptical) distribution: int p x^2 = P a^2 / 4
    a_moment = 2.0 * math.sqrt(moment2 / total)
    return {
        "formulation": formulation, "h1": h1, "h2": sc["h2"],
        "dofs": int(mfu1.nbdof() + mfu2.nbdof()), "model_dofs": int(md.nbdof()),
        "contact_nodes": int(len(dofs)), "active_nodes": n_loaded,
        "newton_iterations": int(nit), "converged": bool(converged),
        "time_mesh_import": t_mesh, "time_setup": t_setup, "time_solve": t_solve,
        "time": t_setup + t_solve,
        "p0": float(p0), "a": float(a), "p0_hertz": p0_h, "a_hertz": a_h,
        "err_p0": float(p0 / p0_h - 1.0), "err_a": float(a / a_h - 1.0),
        "p_center": float(pc), "err_p_center": float(pc / p0_h - 1.0), "a_moment": float(a_moment),
        "err_a_moment": float(a_moment / a_h - 1.0),
        "force_balance": float(abs(total - P) / P),
        "profile_x": x_nodes.tolist(), "profile_p": pressure.tolist(),
    }


def contact_half_width(x, p):
    """Mean over both sides of the edge of the loaded zone (see the header), and the number of
    nodes of that zone (the contiguous run of loaded nodes around x = 0)."""
    order = np.argsort(x)
    x, p = x[order], p[order]
    # unloaded nodes come out as +-1e-23 rather than 0: "loaded" means above round-off
    loaded = p > 1e-10 * p.max()
    c = int(np.argmin(np.abs(x)))
    ends, n_loaded = [], 1
    for step in (1, -1):
        k = c
        while 0 <= k + step < len(x) and loaded[k + step]:
            k += step
        if k == c or not 0 <= k + step < len(x):
            return float("nan"), 0
        n_loaded += abs(k - c)
        x0, x1, xn = abs(x[k - step]), abs(x[k]), abs(x[k + step])
        q0, q1 = p[k - step] ** 2, p[k] ** 2
        # zero of the line through (x0^2, p0^2), (x1^2, p1^2)
        z2 = x1 * x1 + q1 * (x1 * x1 - x0 * x0) / (q0 - q1) if q0 > q1 else xn * xn
        ends.append(min(max(math.sqrt(max(z2, 0.0)), x1), xn))
    return 0.5 * (ends[0] + ends[1]), n_loaded


@contextlib.contextmanager
def c_stdout_silenced():
    """Silences the C-level stdout (file descriptor 1) for the duration of the block."""
    sys.stdout.flush()
    saved = os.dup(1)
    with open(os.devnull, "w") as null:
        os.dup2(null.fileno(), 1)
    try:
        yield
    finally:
        os.dup2(saved, 1)
        os.close(saved)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--h1", type=float, nargs="+", default=[0.04, 0.02, 0.01])
    ap.add_argument("--ratio", type=float, default=1.37, help="h2 = ratio * h1 (default 1.37)")
    ap.add_argument("--formulations", nargs="+", default=["nodal", "gwfl"], choices=["nodal", "gwfl"])
    # GetFEM stops Newton when ||residual||_1 / (estimate of ||external load||_1) < max_res.
    # Its round-off floor grows with the size (2e-11 at 23k DOFs), so 1e-11 is out of reach;
    # the semi-smooth Newton drops from ~1e-7 to that floor in the step that fixes the active
    # set, so any tolerance between the two gives the same answer.
    ap.add_argument("--max-res", type=float, default=1e-9,
                    help="GetFEM Newton tolerance (relative to the external load), default 1e-9")
    ap.add_argument("--max-iter", type=int, default=100)
    ap.add_argument("--lsearch", default=None,
                    help="GetFEM line search ('simplest', 'systematic', 'quadratic', 'basic')")
    # The vertical force balance of body 1 is a sum of residual entries, so it is bounded by the
    # Newton criterion (max_res, 1-norm relative to the load): 1e-6 leaves a wide margin.
    ap.add_argument("--tol-balance", type=float, default=1e-6)
    ap.add_argument("--gwfl-r-scale", type=float, default=1.0,
                    help="gwfl augmentation r = scale * E / h1 (default 1)")
    ap.add_argument("--repeat", type=int, default=1,
                    help="solve each case this many times and report the median run (by time)")
    ap.add_argument("--json", help="write the rows to this file")
    ap.add_argument("--noisy", action="store_true")
    ap.add_argument("--dump", help="write the numpy meshes of the first size to this .npz and exit")
    args = ap.parse_args()

    if args.dump:
        sc = hertz_scene(args.h1[0], args.ratio * args.h1[0])
        np.savez(args.dump, **sc)
        return 0

    import getfem as gf
    gf.util_trace_level(0)
    gf.util_warning_level(0)
    a_h, p0_h = hertz_analytic()
    print("Hertz: a = %.6f, p0 = %.6f; P = %g; DOFs = displacement unknowns of both bodies" % (a_h, p0_h, P))
    print("No spring: Newton starts from body 1 shifted down rigidly by %g; MUMPS; max_res %g"
          % (DELTA0, args.max_res))
    hdr = "%-6s %7s %7s %9s %6s %6s %4s %8s %8s %9s %9s %9s %9s %9s %9s %9s" % (
        "form", "h1", "h2", "DOFs", "cnodes", "active", "it", "setup_s", "solve_s",
        "p0", "err_p0", "err_p(0)", "a", "err_a", "err_a_mom", "balance")
    print(hdr)
    rows, bad = [], False
    for h1 in args.h1:
        h2 = args.ratio * h1
        sc = hertz_scene(h1, h2)
        sc["h2"] = h2
        for f in args.formulations:
            runs = sorted((solve(gf, sc, f, h1, args) for _ in range(args.repeat)), key=lambda x: x["time"])
            r = runs[len(runs) // 2]  # the median run (by time)
            rows.append(r)
            print("%-6s %7.4g %7.4g %9d %6d %6d %4d %8.2f %8.2f %9.6f %+9.2e %+9.2e %9.6f %+9.2e %+9.2e %9.1e%s" % (
                f, h1, h2, r["dofs"], r["contact_nodes"], r["active_nodes"], r["newton_iterations"],
                r["time_setup"], r["time_solve"], r["p0"], r["err_p0"], r["err_p_center"], r["a"], r["err_a"],
                r["err_a_moment"], r["force_balance"], "" if r["converged"] else "  NOT CONVERGED"),
                flush=True)
            bad |= (not r["converged"]) or not (r["force_balance"] <= args.tol_balance)
            if args.json:
                with open(args.json, "w") as fh:
                    json.dump(rows, fh, indent=1)
    if bad:
        print("FAILED: Newton did not converge or the force balance exceeds %g" % args.tol_balance)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
