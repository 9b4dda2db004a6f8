"""The contact patch test: two stacked rectangles with non-matching, distorted meshes, a
uniform pressure on top, the bottom supported. The exact solution is linear in each body, so
the mortar methods must reproduce it to round-off and give a uniform contact pressure."""
import numpy as np

import _paths  # noqa: F401
import mortarcontact as mc

PRESSURE = 0.01
E1, NU1 = 1.0, 0.3     # body 1: the upper block [0, 1] x [1, 2], P1 triangles
E2, NU2 = 3.0, 0.25    # body 2: the lower block [0, 1] x [0, 1], Q1 quadrilaterals


def grid(x0, x1, y0, y1, nx, ny, seed):
    """Nodes of an nx-by-ny cell grid with its interior nodes moved (deterministically) off
    the lines; node (i, j) has id i*(ny+1) + j."""
    xs, ys = np.linspace(x0, x1, nx + 1), np.linspace(y0, y1, ny + 1)
    X, Y = np.meshgrid(xs, ys, indexing="ij")
    rng = np.random.default_rng(seed)
    inner = (slice(1, nx), slice(1, ny))
    X[inner] += 0.2 * (x1 - x0) / nx * rng.uniform(-1, 1, X[inner].shape)
    Y[inner] += 0.2 * (y1 - y0) / ny * rng.uniform(-1, 1, Y[inner].shape)
    node = np.arange((nx + 1) * (ny + 1)).reshape(nx + 1, ny + 1)
    return np.column_stack([X.ravel(), Y.ravel()]), node


def quads(node):
    """Counter-clockwise quadrilaterals of a grid numbered by ``grid``."""
    return np.column_stack([node[:-1, :-1].ravel(), node[1:, :-1].ravel(),
                            node[1:, 1:].ravel(), node[:-1, 1:].ravel()])


def triangles(node):
    q = quads(node)
    return np.vstack([q[:, [0, 1, 2]], q[:, [0, 2, 3]]])


def chain(nodes):
    return np.column_stack([nodes[:-1], nodes[1:]])


def exact(xy1, xy2):
    """Exact displacements (plane strain, sigma_yy = -p, sigma_xx = 0, rollers on the left)."""
    exx1, eyy1 = NU1 * (1 + NU1) * PRESSURE / E1, -(1 - NU1 ** 2) * PRESSURE / E1
    exx2, eyy2 = NU2 * (1 + NU2) * PRESSURE / E2, -(1 - NU2 ** 2) * PRESSURE / E2
    u2 = np.column_stack([exx2 * xy2[:, 0], eyy2 * xy2[:, 1]])
    u1 = np.column_stack([exx1 * xy1[:, 0], eyy2 * 1.0 + eyy1 * (xy1[:, 1] - 1.0)])
    return u1, u2


def build(m, base=0):
    """Sets up the patch test on model ``m`` (ids shifted by ``base``); returns (xy1, xy2)."""
    xy1, n1 = grid(0.0, 1.0, 1.0, 2.0, 5, 3, seed=1)
    xy2, n2 = grid(0.0, 1.0, 0.0, 1.0, 9, 4, seed=2)
    m.set_mesh(1, xy1, triangles(n1) + base)
    m.set_mesh(2, xy2, quads(n2) + base)
    m.set_material(1, E1, NU1)
    m.set_material(2, E2, NU2)
    m.add_pressure(1, chain(n1[:, -1]) + base, PRESSURE)   # top of body 1 (orientation-free)
    m.fix(1, n1[0, :] + base, mc.MC_X)                    # rollers on the left of body 1
    m.fix(2, n2[0, :] + base, mc.MC_X)                    # ... and of body 2
    m.fix(2, n2[:, 0] + base, mc.MC_Y)                    # body 2 rests on y = 0
    m.set_contact(1, chain(n1[:, 0]) + base)
    m.set_contact(2, chain(n2[:, -1]) + base)
    return xy1, xy2
