#!/usr/bin/env python3
"""Hertz contact of a half-disc on a block (the shared benchmark scene of docs/ and
/work/shared/design/method.md), with the Python bindings.

Body 1: lower half-disc of radius R = 1 centred at (0, 1), touching the origin; its flat top
carries a total downward force P as a uniform traction; u_x = 0 on its axis x = 0, so contact
alone holds it vertically. Body 2: the block [-4, 4] x [-4, 0], clamped at y = -4.
E = 1, nu = 0.3 for both, plane strain, unit thickness. Meshes: P1 triangles, a polar grid on
the disc and a tensor grid on the block, both graded towards the contact point.

Hertz: 1/E* = 2 (1 - nu^2) / E, a = sqrt(4 P R / (pi E*)), p0 = 2 P / (pi a),
p(x) = p0 sqrt(1 - x^2 / a^2).

    python3 examples/python/hertz.py [h] [--mortar-normal]
        h: mesh size at the contact (default 0.005); --mortar-normal: constraint directions
        from body 2's surface (MC_NORMAL_MORTAR) instead of body 1's nodal normals. With the
        default normals p0 comes out about 0.8 % high, with --mortar-normal within 0.2 %
        (the header's comment on MC_OPTION_CONTACT_NORMAL explains the difference).

Needs the package mortarcontact importable: installed (`cmake --install`, or pip; see
docs/bindings.md), or PYTHONPATH=bindings/python in a source checkout, whose package then loads
the library from build*/lib (or MORTARCONTACT_LIBRARY).
"""

import math
import sys

import numpy as np

import mortarcontact as mc

R, E, NU, P = 1.0, 1.0, 0.3, 0.01


def hertz_values(load=P, radius=R, young=E, poisson=NU):
    """(a, p0) of the Hertz solution for two identical materials."""
    e_star = 1.0 / (2.0 * (1.0 - poisson ** 2) / young)
    a = math.sqrt(4.0 * load * radius / (math.pi * e_star))
    return a, 2.0 * load / (math.pi * a)


def graded(length, h, fine, growth=1.15, hmax=None):
    """Points 0 = t_0 < ... < t_n = length: spacing h up to `fine`, then growing by `growth`
    up to hmax; the last interval is stretched so the sequence ends exactly at `length`."""
    hmax = hmax or length / 4
    t = [0.0]
    step = h
    while t[-1] < length:
        if t[-1] >= fine:
            step = min(step * growth, hmax)
        t.append(t[-1] + step)
    # merge a tiny last interval, then scale the coarse part so the end is exact
    if len(t) > 2 and length - t[-2] < 0.5 * (t[-2] - t[-3]):
        t.pop(-2)
    t = np.array(t)
    t[-1] = length
    return t


def half_disc(h):
    """Lower half-disc of radius R centred at (0, R): polar grid graded towards the bottom
    point. Returns xy, triangles, flat-top edges, contact-arc edges (|x| < 0.5), axis nodes."""
    depth = graded(R, h, 0.25 * R, hmax=0.08)        # distance from the arc, 0 .. R
    radii = (R - depth)[:-1][::-1]                    # inner ring .. arc (r > 0)
    half = graded(0.5 * math.pi, h / R, 0.25, hmax=0.08)
    phi = np.concatenate([-half[::-1], half[1:]])     # angle from the downward vertical
    nr, nphi = len(radii), len(phi)
    rr, pp = np.meshgrid(radii, phi, indexing="ij")
    xy = np.column_stack([(rr * np.sin(pp)).ravel(), (R - rr * np.cos(pp)).ravel()])
    xy = np.vstack([xy, [0.0, R]])                    # the centre, last node
    centre = len(xy) - 1
    node = np.arange(nr * nphi).reshape(nr, nphi)
    tris = []
    # ring cells between radii i and i+1, split along one diagonal; counter-clockwise
    # (phi grows counter-clockwise seen from the centre, as does r outward then phi)
    a, b = node[:-1, :-1].ravel(), node[1:, :-1].ravel()
    c, d = node[1:, 1:].ravel(), node[:-1, 1:].ravel()
    tris.append(np.column_stack([a, b, c]))
    tris.append(np.column_stack([a, c, d]))
    # fan from the centre to the innermost ring
    tris.append(np.column_stack([np.full(nphi - 1, centre), node[0, :-1], node[0, 1:]]))
    tris = np.vstack(tris)
    # flat top: the rays phi = -pi/2 and +pi/2 (y = R), from the centre out
    left = np.concatenate([[centre], node[:, 0]])
    right = np.concatenate([[centre], node[:, -1]])
    top = np.vstack([np.column_stack([left[:-1], left[1:]]), np.column_stack([right[:-1], right[1:]])])
    arc = node[-1]
    arc_edges = np.column_stack([arc[:-1], arc[1:]])
    xm = 0.5 * (xy[arc_edges[:, 0], 0] + xy[arc_edges[:, 1], 0])
    contact = arc_edges[np.abs(xm) < 0.5 * R]
    axis = np.concatenate([node[:, nphi // 2], [centre]])  # phi = 0 ray and the centre
    return xy, _ccw(xy, tris), top, contact, axis


def block(h):
    """The block [-4, 4] x [-4, 0]: tensor grid graded towards (0, 0). Returns xy, triangles,
    top contact edges (|x| < 1), bottom nodes."""
    half = graded(4.0, h, 0.25, hmax=0.6)
    xs = np.concatenate([-half[::-1], half[1:]])
    ys = -graded(4.0, h, 0.25, hmax=0.6)[::-1]       # -4 .. 0
    nx, ny = len(xs), len(ys)
    X, Y = np.meshgrid(xs, ys, indexing="ij")
    xy = np.column_stack([X.ravel(), Y.ravel()])
    node = np.arange(nx * ny).reshape(nx, ny)
    a, b = node[:-1, :-1].ravel(), node[1:, :-1].ravel()
    c, d = node[1:, 1:].ravel(), node[:-1, 1:].ravel()
    tris = np.vstack([np.column_stack([a, b, c]), np.column_stack([a, c, d])])
    top = node[:, -1]
    top_edges = np.column_stack([top[:-1], top[1:]])
    xm = 0.5 * (xy[top_edges[:, 0], 0] + xy[top_edges[:, 1], 0])
    return xy, _ccw(xy, tris), top_edges[np.abs(xm) < 1.0], node[:, 0]


def _ccw(xy, tris):
    """Reorders triangles to counter-clockwise."""
    p = xy[tris]
    area = (p[:, 1, 0] - p[:, 0, 0]) * (p[:, 2, 1] - p[:, 0, 1]) - (p[:, 2, 0] - p[:, 0, 0]) * (p[:, 1, 1] - p[:, 0, 1])
    tris = tris.copy()
    tris[area < 0] = tris[area < 0][:, [0, 2, 1]]
    return tris


def solve(h=0.005, method=mc.MC_METHOD_MORTAR, normal=None):
    """Builds and solves the scene with mesh size h at the contact, the given MC_METHOD_* and
    MC_NORMAL_* (None: the library's default); returns a dict with the contact nodes' x,
    pressure and force, the fitted p0 and a, the peak nodal pressure, and the solver infos."""
    xy1, tri1, top1, contact1, axis1 = half_disc(h)
    xy2, tri2, contact2, bottom2 = block(0.8 * h)   # non-matching on purpose
    with mc.Model() as m:
        m.set_plane(mc.MC_PLANE_STRAIN, 1.0)
        m.set_mesh(1, xy1, tri1)
        m.set_mesh(2, xy2, tri2)
        m.set_material(1, E, NU)
        m.set_material(2, E, NU)
        length = np.sum(np.linalg.norm(xy1[top1[:, 1]] - xy1[top1[:, 0]], axis=1))
        m.add_traction(1, top1, (0.0, -P / length))
        m.fix(1, axis1, mc.MC_X)
        m.fix(2, bottom2, mc.MC_XY)
        m.set_contact(1, contact1)
        m.set_contact(2, contact2)
        m.set_option_int(mc.MC_OPTION_METHOD, method)
        if normal is not None:
            m.set_option_int(mc.MC_OPTION_CONTACT_NORMAL, normal)
        m.solve()
        nodes = m.get_contact_nodes()
        p = m.get_contact_pressure()
        force = m.get_contact_force()
        normal = m.get_contact_normal()
        info = {name: m.get_info(getattr(mc, name)) for name in
                ("MC_INFO_DOFS", "MC_INFO_ITERATIONS", "MC_INFO_ACTIVE_NODES", "MC_INFO_TIME_TOTAL",
                 "MC_INFO_COMPLEMENTARITY", "MC_INFO_EQUILIBRIUM")}
    x = xy1[nodes, 0]
    order = np.argsort(x)
    x, p, force, normal = x[order], p[order], force[order], normal[order]
    # p^2 = p0^2 (1 - x^2/a^2) is linear in x^2: fit it on the clearly active nodes
    # (the nodes next to the contact edge carry a smeared, lumped pressure)
    sel = p > 0.3 * p.max()
    c1, c0 = np.polyfit(x[sel] ** 2, p[sel] ** 2, 1)
    return {"x": x, "p": p, "force": force, "p0_fit": math.sqrt(c0), "a_fit": math.sqrt(-c0 / c1),
            "p_max": p.max(), "info": info,
            # lambda_j pushes body 1 along -n_j: the vertical resultant balances P
            "total_force": float(np.sum(force * -normal[:, 1]))}


def main():
    args = [x for x in sys.argv[1:] if not x.startswith("--")]
    h = float(args[0]) if args else 0.005
    normal = mc.MC_NORMAL_MORTAR if "--mortar-normal" in sys.argv else None
    a, p0 = hertz_values()
    r = solve(h, normal=normal)
    print("mortarcontact %s (library %s), h = %g at the contact, %s normals"
          % (mc.__version__, mc.version_string(), h, "mortar-side" if normal is not None else "default"))
    for k, v in r["info"].items():
        print("  %-24s %s" % (k, v))
    print("  vertical contact force   %.6g (applied %.6g)" % (r["total_force"], P))
    print("            computed    Hertz      error")
    print("  p0 (peak) %.6f   %.6f   %+.2f %%" % (r["p_max"], p0, 100 * (r["p_max"] / p0 - 1)))
    print("  p0 (fit)  %.6f   %.6f   %+.2f %%" % (r["p0_fit"], p0, 100 * (r["p0_fit"] / p0 - 1)))
    print("  a  (fit)  %.6f   %.6f   %+.2f %%" % (r["a_fit"], a, 100 * (r["a_fit"] / a - 1)))
    print("\n         x          p    p Hertz")
    for x, p in zip(r["x"], r["p"]):
        if abs(x) < 1.3 * a:
            ph = p0 * math.sqrt(max(0.0, 1 - x * x / (a * a)))
            print("  %+.5f  %.6f  %.6f" % (x, p, ph))


if __name__ == "__main__":
    main()
