#!/usr/bin/env python3
"""The program of docs/tutorial_python.md: the Hertz contact scene, step by step.

A half-disc of radius R = 1 is pressed with a total force P = 0.01 onto a block; both are
linear elastic (E = 1, nu = 0.3, plane strain) and meshed independently. The program solves
the contact problem with the paper's mortar method, compares the peak pressure p0 and the
half-width a of the contact zone with Hertz's formulas, writes the solution for ParaView,
then doubles the load and solves again, reusing the factorization.

    python3 examples/python/tutorial_hertz.py [h1] [output.pvd]

h1: mesh size of the disc at the contact point (default 0.01; the block gets 1.37 h1).
Exit status 0 only if every check of steps 11 and 13 passes (ctest runs it: tutorial_python).
"""

import math
import sys

import numpy as np

import mortarcontact as mc


# ---- step 2: two independent meshes ----
def graded(h, length, fine=0.4, growth=1.15):
    """Grid points 0 = t_0 < ... < t_n = length: steps h up to `fine`, then each step
    `growth` times the previous one; the last step is stretched to end at `length`."""
    t, step = [0.0], h
    while t[-1] + 1.5 * step < length:
        t.append(t[-1] + step)
        if t[-1] >= fine:
            step *= growth
    return np.array(t + [length])


def grid_triangles(nx, ny, flip=None):
    """Two counter-clockwise triangles per cell of an nx-by-ny grid whose node (i, j) is
    j * (nx + 1) + i; cell `flip` = (i, j) is split along its other diagonal."""
    i, j = np.meshgrid(np.arange(nx), np.arange(ny))
    ll = (j * (nx + 1) + i).ravel()
    lr, ul = ll + 1, ll + nx + 1
    ur = ul + 1
    tri = np.vstack([np.column_stack([ll, lr, ur]), np.column_stack([ll, ur, ul])])
    if flip is not None:
        k = flip[1] * nx + flip[0]
        tri[k], tri[nx * ny + k] = (ll[k], lr[k], ul[k]), (lr[k], ur[k], ul[k])
    return tri


def edges_along(row, xy, xmax):
    """Consecutive node pairs of `row` with both ends at |x| <= xmax."""
    e = np.column_stack([row[:-1], row[1:]])
    return e[np.all(np.abs(xy[e, 0]) <= xmax, axis=1)]


def disc_mesh(h1):
    """Body 1, the half-disc x^2 + (y - 1)^2 <= 1, y <= 1: the square [-1, 1] x [-1, 0]
    mapped by x = s sqrt(1 - t^2/2), y = 1 + t sqrt(1 - s^2/2), which puts the sides
    s = +-1 and t = -1 on the arc and t = 0 on the flat top. Near the contact point the map
    shrinks s by sqrt 2, hence the spacing sqrt(2) h1 in s."""
    half = graded(math.sqrt(2) * h1, 1.0, fine=0.4 * math.sqrt(2))
    s = np.concatenate([-half[::-1], half[1:]])
    t = graded(math.sqrt(2) * h1, 1.0, fine=0.4 * math.sqrt(2)) - 1.0
    S, T = np.meshgrid(s, t)
    x, y = S * np.sqrt(1 - T ** 2 / 2), T * np.sqrt(1 - S ** 2 / 2)
    arc = (np.abs(S) == 1) | (T == -1)  # exactly on the circle, not up to rounding
    r = np.where(arc, np.hypot(x, y), 1.0)
    xy = np.column_stack([(x / r).ravel(), (1 + y / r).ravel()])
    ns, nt = len(s) - 1, len(t) - 1
    node = np.arange(len(xy)).reshape(nt + 1, ns + 1)
    # the corner cell at s = 1, t = -1 would get three nodes on the arc: split it the other way
    cells = grid_triangles(ns, nt, flip=(ns - 1, 0))
    top = np.column_stack([node[-1, :-1], node[-1, 1:]])
    contact = edges_along(node[0], xy, 0.5)
    axis = node[:, ns // 2]  # s = 0: x = 0 exactly
    return xy, cells, top, contact, axis


def block_mesh(h2):
    """Body 2, the block [-4, 4] x [-4, 0]: a tensor grid graded towards (0, 0)."""
    half = graded(h2, 4.0)
    xs = np.concatenate([-half[::-1], half[1:]])
    ys = -graded(h2, 4.0)[::-1]
    X, Y = np.meshgrid(xs, ys)
    xy = np.column_stack([X.ravel(), Y.ravel()])
    node = np.arange(len(xy)).reshape(len(ys), len(xs))
    cells = grid_triangles(len(xs) - 1, len(ys) - 1)
    contact = edges_along(node[-1], xy, 1.0)
    bottom = node[0]
    return xy, cells, contact, bottom


def half_width(x, p):
    """Half-width of the contact zone: on each side of x = 0, midway between the outermost
    node that carries pressure and the next node out; the mean of the two sides."""
    a = 0.0
    for side in (-1, 1):
        xs = side * x
        last = xs[(xs >= 0) & (p > 0)].max()
        beyond = xs[xs > last]
        a += 0.25 * (last + (beyond.min() if beyond.size else last))
    return a


def main():
    h1 = float(sys.argv[1]) if len(sys.argv) > 1 else 0.01
    output = sys.argv[2] if len(sys.argv) > 2 else "tutorial_hertz.pvd"
    failures = []

    # ---- step 1: the problem and its analytic answer ----
    R, E, nu, P = 1.0, 1.0, 0.3, 0.01
    e_star = E / (2 * (1 - nu ** 2))  # two equal bodies, plane strain
    a_hertz = math.sqrt(4 * P * R / (math.pi * e_star))
    p0_hertz = 2 * P / (math.pi * a_hertz)
    print("Hertz: a = %.6f, p0 = %.6f" % (a_hertz, p0_hertz))

    # ---- step 2: two independent meshes ----
    xy1, tri1, top1, contact1, axis1 = disc_mesh(h1)
    xy2, tri2, contact2, bottom2 = block_mesh(1.37 * h1)
    print("meshes: disc %d nodes, %d triangles; block %d nodes, %d triangles"
          % (len(xy1), len(tri1), len(xy2), len(tri2)))

    # ---- step 3: the model and its two bodies ----
    with mc.Model() as m:
        m.set_plane(mc.MC_PLANE_STRAIN, 1.0)
        m.set_mesh(1, xy1, tri1)
        m.set_mesh(2, xy2, tri2)

        # ---- step 4: materials ----
        m.set_material(1, E, nu)
        m.set_material(2, E, nu)

        # ---- step 5: supports ----
        m.fix(1, axis1, mc.MC_X)      # u_x = 0 on x = 0
        m.fix(2, bottom2, mc.MC_XY)   # clamped at y = -4

        # ---- step 6: the load ----
        traction = (0.0, -P / (2 * R))  # force per unit length on the top, |x| <= R
        m.add_traction(1, top1, traction)

        # ---- step 7: the contact surfaces ----
        m.set_contact(1, contact1)    # non-mortar
        m.set_contact(2, contact2)    # mortar

        # ---- step 8: method options and progress messages ----
        m.set_option(mc.MC_OPTION_METHOD, mc.MC_METHOD_MORTAR)
        m.set_option(mc.MC_OPTION_CONTACT_NORMAL, mc.MC_NORMAL_MORTAR)
        def print_phase(level, message):  # the progress of solve(): phases, not iterations
            if level == mc.MC_LOG_PHASE:
                print("  [mc]", message)
        m.set_log_callback(print_phase)

        # ---- step 9: solve ----
        m.solve()
        info = {name: m.get_info(getattr(mc, "MC_INFO_" + name))
                for name in ("DOFS", "ITERATIONS", "ACTIVE_NODES", "CONTACT_NODES", "TIME_TOTAL")}
        print("solved: %(DOFS)d unknowns, %(ACTIVE_NODES)d active of %(CONTACT_NODES)d contact nodes, "
              "%(ITERATIONS)d active-set iterations" % info)

        # ---- step 10: read the results ----
        nodes = m.get_contact_nodes()
        pressure = m.get_contact_pressure()
        force = m.get_contact_force()
        gap = m.get_contact_gap()
        normal = m.get_contact_normal()
        x = xy1[nodes, 0]  # ids are 0-based
        u1 = m.get_displacement(1)  # (n_nodes, 2)
        print("the disc moved down by %.6f (largest -u_y of body 1)" % -u1[:, 1].min())

        # ---- step 11: check against Hertz ----
        p0 = pressure.max()
        lift = np.sum(force * -normal[:, 1])  # lambda_j pushes body 1 along -n_j
        seen = np.isfinite(gap)
        worst = np.max(np.abs(force[seen] * gap[seen]))  # force * gap = 0
        a = half_width(x, pressure)
        p0_error, a_error = p0 / p0_hertz - 1, a - a_hertz
        print("p0 = %.6f (Hertz %.6f, %+.2f %%)" % (p0, p0_hertz, 100 * p0_error))
        print("a  = %.6f (Hertz %.6f, %+.2f h1)" % (a, a_hertz, a_error / h1))
        print("contact force %.10f (load %.10f), max |force * gap| %.1e" % (lift, P, worst))
        if abs(p0_error) > 0.005:
            failures.append("p0 is not within 0.5 % of Hertz")
        if abs(a_error) > 1.5 * h1:
            failures.append("a is not within 1.5 h1 of Hertz")
        if abs(lift - P) > 1e-9 * P:
            failures.append("the contact force does not balance the load")

        # ---- step 12: write the solution for ParaView ----
        m.write_vtu(output)
        print("wrote", output)

        # ---- step 13: double the load and solve again ----
        m.clear_loads(1)
        m.add_traction(1, top1, 2 * np.array(traction))
        m.solve()
        factorizations = m.get_info(mc.MC_INFO_FACTORIZATIONS)
        p0_doubled = m.get_contact_pressure().max()
        print("load 2P: p0 = %.6f, p0(2P)/p0(P) = %.4f (Hertz: sqrt 2 = %.4f), %d factorizations"
              % (p0_doubled, p0_doubled / p0, math.sqrt(2), factorizations))
        print("time: first solve %.3f s, re-solve %.3f s" % (info["TIME_TOTAL"], m.get_info(mc.MC_INFO_TIME_TOTAL)))
        if factorizations != 0:
            failures.append("the re-solve factorized again")
        if abs(p0_doubled / p0 / math.sqrt(2) - 1) > 0.01:
            failures.append("p0 does not scale as sqrt(P)")

    # ---- step 14: clean up ----
    # (the with block has freed the model)
    for failure in failures:
        print("FAIL:", failure)
    print("tutorial: %s" % ("%d checks failed" % len(failures) if failures else "all checks passed"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
