"""Host bodies through the Python binding: the contact patch test (patch_scene) with body 1, then
both bodies, given as a host's own stiffness (assembled here in numpy, in a shuffled equation
numbering with the restrained freedoms left without equations) and compared with the same scene
given as meshes: displacements and pressures equal to round-off, for coordinate arrays, SciPy
matrices of every format (full and one triangle), dense arrays and element matrices (MUMPS's
form and one row per element), index bases 0 and 1. Also the equation vectors (K u = f + r),
a re-solve with a new load vector, quadratic edges (mc_set_contact_curved) on mesh and host
bodies, and the binding's and the library's errors. Needs SciPy (Debian: python3-scipy)."""
import unittest

import numpy as np
import scipy.sparse as sp

import _paths  # noqa: F401
import mortarcontact as mc
import patch_scene

PRESSURE = patch_scene.PRESSURE


# ---- the host's side: element stiffness matrices, numbering, assembly ------------------------

def plane_strain(young, poisson):
    f = young / ((1 + poisson) * (1 - 2 * poisson))
    return f * np.array([[1 - poisson, poisson, 0], [poisson, 1 - poisson, 0], [0, 0, (1 - 2 * poisson) / 2]])


def p1_stiffness(xy, tri, young, poisson):
    """(n_cells, 6, 6) plane-strain stiffness of P1 triangles, freedoms x0 y0 x1 y1 x2 y2."""
    d = plane_strain(young, poisson)
    out = np.empty((len(tri), 6, 6))
    for e, cell in enumerate(tri):
        x, y = xy[cell, 0], xy[cell, 1]
        area = 0.5 * ((x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]))
        b = np.zeros((3, 6))
        for i in range(3):
            j, k = (i + 1) % 3, (i + 2) % 3
            bi, ci = (y[j] - y[k]) / (2 * area), (x[k] - x[j]) / (2 * area)
            b[0, 2 * i], b[1, 2 * i + 1], b[2, 2 * i], b[2, 2 * i + 1] = bi, ci, ci, bi
        out[e] = area * b.T @ d @ b
    return out


# Reference coordinates of the nodes of Q1 and Q9 cells in Gmsh's order.
Q_NODES = {4: [(-1, -1), (1, -1), (1, 1), (-1, 1)],
           9: [(-1, -1), (1, -1), (1, 1), (-1, 1), (0, -1), (1, 0), (0, 1), (-1, 0), (0, 0)]}


def lagrange_1d(points, t):
    """Values and derivatives at t of the 1D Lagrange polynomials through `points`."""
    values, derivs = [], []
    for i, pi in enumerate(points):
        others = [pj for j, pj in enumerate(points) if j != i]
        den = np.prod([pi - pj for pj in others])
        values.append(np.prod([t - pj for pj in others]) / den)
        derivs.append(sum(np.prod([t - pk for pk in others if pk is not pj]) for pj in others) / den)
    return np.array(values), np.array(derivs)


def quad_stiffness(xy, cells, young, poisson):
    """(n_cells, 2k, 2k) plane-strain stiffness of Q1 (k = 4, 2x2 Gauss) or Q9 (k = 9, 3x3 Gauss)
    quadrilaterals, the tensor-product Lagrange cells of the library."""
    k = cells.shape[1]
    points = [-1.0, 1.0] if k == 4 else [-1.0, 0.0, 1.0]
    gauss, weights = np.polynomial.legendre.leggauss(2 if k == 4 else 3)
    d = plane_strain(young, poisson)
    index = [(points.index(a), points.index(b)) for a, b in Q_NODES[k]]
    out = np.zeros((len(cells), 2 * k, 2 * k))
    for e, cell in enumerate(cells):
        xe = xy[cell]
        for gx, wx in zip(gauss, weights):
            for gy, wy in zip(gauss, weights):
                nx, dx = lagrange_1d(points, gx)
                ny, dy = lagrange_1d(points, gy)
                dn = np.array([[dx[i] * ny[j], nx[i] * dy[j]] for i, j in index])  # (k, 2): d/dxi, d/deta
                jac = dn.T @ xe
                grad = np.linalg.solve(jac, dn.T)  # (2, k): d/dx, d/dy
                b = np.zeros((3, 2 * k))
                b[0, 0::2], b[1, 1::2], b[2, 0::2], b[2, 1::2] = grad[0], grad[1], grad[1], grad[0]
                out[e] += wx * wy * np.linalg.det(jac) * b.T @ d @ b
    return out


def numbering(n_nodes, restrained, base, seed):
    """Equation numbers (n_nodes, 2) as a host numbers them: the free freedoms shuffled, the
    restrained ones with none (base - 1); and the count of equations."""
    free = ~restrained
    n_eq = int(free.sum())
    eq = np.full((n_nodes, 2), base - 1, dtype=np.int64)
    eq[free] = np.random.default_rng(seed).permutation(n_eq) + base
    return eq, n_eq


def element_freedoms(eq, cells):
    """Each element's equations, x, y per node: (n_cells, 2 npc)."""
    return eq[cells].reshape(len(cells), -1)


def coo_entries(eq, cells, ke):
    """Coordinate entries of all element matrices, restrained freedoms included."""
    dofs = element_freedoms(eq, cells)
    n = dofs.shape[1]
    return np.repeat(dofs, n, axis=1).ravel(), np.tile(dofs, (1, n)).ravel(), ke.ravel()


def dense_stiffness(eq, cells, ke, n_eq, base):
    """The host's system matrix (n_eq, n_eq), equation i + base in row i."""
    rows, cols, values = coo_entries(eq, cells, ke)
    keep = (rows >= base) & (cols >= base)
    k = np.zeros((n_eq, n_eq))
    np.add.at(k, (rows[keep] - base, cols[keep] - base), values[keep])
    return k


def top_load(eq, xy, top_nodes, n_eq, base):
    """The pressure on the horizontal top edge as the host's load vector."""
    f = np.zeros(n_eq)
    for a, b in zip(top_nodes[:-1], top_nodes[1:]):
        half = 0.5 * PRESSURE * abs(xy[b, 0] - xy[a, 0])
        f[eq[a, 1] - base] -= half
        f[eq[b, 1] - base] -= half
    return f


class HostPatch:
    """The patch scene's geometry, both bodies as a host sees them."""

    def __init__(self, base):
        self.base = base
        self.xy1, n1 = patch_scene.grid(0.0, 1.0, 1.0, 2.0, 5, 3, seed=1)
        self.xy2, n2 = patch_scene.grid(0.0, 1.0, 0.0, 1.0, 9, 4, seed=2)
        self.n1, self.n2 = n1, n2
        self.tri1, self.quad2 = patch_scene.triangles(n1), patch_scene.quads(n2)
        self.ke1 = p1_stiffness(self.xy1, self.tri1, patch_scene.E1, patch_scene.NU1)
        self.ke2 = quad_stiffness(self.xy2, self.quad2, patch_scene.E2, patch_scene.NU2)
        r1 = np.zeros((len(self.xy1), 2), dtype=bool)
        r1[n1[0, :], 0] = True                        # rollers on the left of body 1
        r2 = np.zeros((len(self.xy2), 2), dtype=bool)
        r2[n2[0, :], 0] = True                        # ... and of body 2
        r2[n2[:, 0], 1] = True                        # body 2 rests on y = 0
        self.eq1, self.n_eq1 = numbering(len(self.xy1), r1, base, seed=3)
        self.eq2, self.n_eq2 = numbering(len(self.xy2), r2, base, seed=4)
        self.f1 = top_load(self.eq1, self.xy1, n1[:, -1], self.n_eq1, base)
        self.k1 = dense_stiffness(self.eq1, self.tri1, self.ke1, self.n_eq1, base)

    def host_body_1(self, m):
        m.set_host_body(1, self.xy1, self.eq1, self.n_eq1)
        m.set_load_vector(1, self.f1)
        m.set_contact(1, patch_scene.chain(self.n1[:, 0]) + self.base)  # the body on the left of each edge

    def host_body_2(self, m):
        m.set_host_body(2, self.xy2, self.eq2, self.n_eq2)
        m.add_stiffness(2, *coo_entries(self.eq2, self.quad2, self.ke2))
        m.set_contact(2, patch_scene.chain(self.n2[::-1, -1]) + self.base)  # top, right to left

    def mesh_body_2(self, m):
        b = self.base
        m.set_mesh(2, self.xy2, self.quad2 + b)
        m.set_material(2, patch_scene.E2, patch_scene.NU2)
        m.fix(2, self.n2[0, :] + b, mc.MC_X)
        m.fix(2, self.n2[:, 0] + b, mc.MC_Y)
        m.set_contact(2, patch_scene.chain(self.n2[:, -1]) + b)


def solve_meshes(base=0):
    with mc.Model(index_base=base) as m:
        patch_scene.build(m, base)
        m.solve()
        return m.get_displacement(1), m.get_displacement(2), m.get_contact_pressure()


class TestHostBody(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.u1, cls.u2, cls.p = solve_meshes()
        cls.scale = max(np.abs(cls.u1).max(), np.abs(cls.u2).max())

    def assert_as_meshes(self, m):
        np.testing.assert_allclose(m.get_displacement(1), self.u1, rtol=0, atol=1e-10 * self.scale)
        np.testing.assert_allclose(m.get_displacement(2), self.u2, rtol=0, atol=1e-10 * self.scale)
        np.testing.assert_allclose(m.get_contact_pressure(), self.p, rtol=0, atol=1e-10 * PRESSURE)
        np.testing.assert_allclose(self.p, PRESSURE, rtol=1e-8)  # and the patch test's exact answer

    def solve_host_1(self, base, add):
        """The patch scene, body 1 a host body whose stiffness `add(m, host)` gives."""
        host = HostPatch(base)
        with mc.Model(index_base=base) as m:
            host.host_body_1(m)
            add(m, host)
            host.mesh_body_2(m)
            m.solve()
            self.assert_as_meshes(m)
            return host, m.get_equation_solution(1), m.get_contact_load(1)

    def test_coordinate_arrays_full_restrained_given(self):
        for base in (0, 1):
            with self.subTest(base=base):
                self.solve_host_1(base, lambda m, h: m.add_stiffness(1, *coo_entries(h.eq1, h.tri1, h.ke1)))

    def test_coordinate_arrays_triangle(self):
        def lower(m, h):
            rows, cols, values = coo_entries(h.eq1, h.tri1, h.ke1)
            keep = (rows >= h.base) & (cols >= h.base) & (rows >= cols)
            m.add_stiffness(1, rows[keep], cols[keep], values[keep], storage=mc.MC_MATRIX_TRIANGLE)
        for base in (0, 1):
            with self.subTest(base=base):
                self.solve_host_1(base, lower)

    def test_repeated_calls_add(self):
        def element_by_element(m, h):
            for e in range(len(h.tri1)):
                m.add_stiffness(1, *coo_entries(h.eq1, h.tri1[e:e + 1], h.ke1[e:e + 1]))
        self.solve_host_1(1, element_by_element)

    def test_scipy_matrices_of_every_format(self):
        for fmt in ("coo", "csr", "csc", "lil", "dok", "bsr"):
            for base in (0, 1):
                with self.subTest(format=fmt, base=base):
                    self.solve_host_1(base, lambda m, h: m.add_stiffness(1, sp.csr_matrix(h.k1).asformat(fmt)))
        # a sparse array (not matrix), and one triangle of either side
        self.solve_host_1(0, lambda m, h: m.add_stiffness(1, sp.csr_array(h.k1)))
        self.solve_host_1(0, lambda m, h: m.add_stiffness(1, sp.triu(sp.csr_matrix(h.k1)), storage=mc.MC_MATRIX_TRIANGLE))
        self.solve_host_1(1, lambda m, h: m.add_stiffness(1, sp.tril(sp.csc_matrix(h.k1)), storage=mc.MC_MATRIX_TRIANGLE))

    def test_dense_matrix(self):
        self.solve_host_1(1, lambda m, h: m.add_stiffness(1, h.k1))

    def test_element_matrices(self):
        def mumps(m, h):  # MUMPS's ELTPTR, ELTVAR, A_ELT
            eltvar = element_freedoms(h.eq1, h.tri1).ravel()
            eltptr = h.base + 6 * np.arange(len(h.tri1) + 1)
            m.add_element_matrices(1, eltptr, eltvar, h.ke1.transpose(0, 2, 1).ravel())
        def per_element(m, h):  # Smith and Griffiths' g_g and storkm, one row per element
            m.add_element_matrices(1, eltvar=element_freedoms(h.eq1, h.tri1), a_elt=h.ke1)
        for base in (0, 1):
            with self.subTest(base=base):
                self.solve_host_1(base, mumps)
                self.solve_host_1(base, per_element)

    def test_equation_vectors(self):
        """The solution in the host's numbering; K u = f + r on the free equations."""
        host, u, r = self.solve_host_1(1, lambda m, h: m.add_stiffness(1, h.k1))
        self.assertEqual(u.shape, (host.n_eq1,))
        free = host.eq1 >= 1
        np.testing.assert_allclose(u[host.eq1[free] - 1], self.u1[free], rtol=0, atol=1e-10 * self.scale)
        np.testing.assert_allclose(host.k1 @ u, host.f1 + r, rtol=0, atol=1e-10 * PRESSURE)
        self.assertAlmostEqual(r[host.eq1[free[:, 1], 1] - 1].sum(), PRESSURE * 1.0, delta=1e-12)

    def test_mesh_body_equation_vectors(self):
        with mc.Model() as m:
            patch_scene.build(m)
            m.solve()
            u2 = m.get_equation_solution(2)
            self.assertEqual(u2.shape, (2 * m.n_nodes(2),))
            self.assertEqual(m.n_equations(2), 2 * m.n_nodes(2))
            np.testing.assert_array_equal(u2, m.get_displacement(2).ravel())
            r2 = m.get_contact_load(2)
            self.assertAlmostEqual(r2[1::2].sum(), -PRESSURE * 1.0, delta=1e-12)

    def test_new_load_vector_resolves(self):
        host = HostPatch(0)
        with mc.Model() as m:
            host.host_body_1(m)
            m.add_stiffness(1, sp.coo_matrix(host.k1))
            host.mesh_body_2(m)
            m.solve()
            u = m.get_equation_solution(1)
            m.set_load_vector(1, 2 * host.f1)  # replaces the load
            m.solve()
            np.testing.assert_allclose(m.get_equation_solution(1), 2 * u, rtol=0, atol=1e-10 * self.scale)
            np.testing.assert_allclose(m.get_contact_pressure(), 2 * PRESSURE, rtol=1e-8)
            m.clear_loads(1)
            m.solve()
            np.testing.assert_allclose(m.get_equation_solution(1), 0.0, atol=1e-14)

    def test_two_host_bodies(self):
        for base in (0, 1):
            with self.subTest(base=base):
                host = HostPatch(base)
                with mc.Model(index_base=base) as m:
                    host.host_body_1(m)
                    m.add_stiffness(1, sp.csr_matrix(host.k1))
                    host.host_body_2(m)
                    for method in (mc.MC_METHOD_MORTAR, mc.MC_METHOD_DUAL_MORTAR):
                        m.set_option(mc.MC_OPTION_METHOD, method)
                        m.solve()
                        self.assert_as_meshes(m)
                    self.assertEqual(m.n_cells(2), 0)
                    self.assertEqual(m.n_equations(2), host.n_eq2)

    def test_curved_edges(self):
        """Body 1 of Q9 cells (no distortion), its bottom given by corners (set_contact) and by
        end, end, middle (set_contact_curved), as a mesh and as a host body: four equal answers."""
        node = np.arange(9 * 5).reshape(9, 5)  # the 9 x 5 lattice of a 4 x 2 Q9 mesh of [0, 1] x [1, 2]
        xy = np.column_stack([np.repeat(np.linspace(0, 1, 9), 5), np.tile(np.linspace(1, 2, 5), 9)])
        c = node[0:-1:2, 0:-1:2], node[2::2, 0:-1:2], node[2::2, 2::2], node[0:-1:2, 2::2]
        mid = node[1::2, 0:-1:2], node[2::2, 1::2], node[1::2, 2::2], node[0:-1:2, 1::2]
        q9 = np.column_stack([a.ravel() for a in c + mid] + [node[1::2, 1::2].ravel()])
        bottom, top = node[:, 0], node[:, -1]
        corners = patch_scene.chain(bottom[::2])
        curved = np.column_stack([bottom[0:-1:2], bottom[2::2], bottom[1::2]])
        restrained = np.zeros((len(xy), 2), dtype=bool)
        restrained[node[0, :], 0] = True
        eq, n_eq = numbering(len(xy), restrained, 0, seed=5)
        ke = quad_stiffness(xy, q9, patch_scene.E1, patch_scene.NU1)
        f = np.zeros(n_eq)  # the pressure on the top's quadratic edges: 1/6, 2/3, 1/6 of p h
        for a, mm, b in zip(top[0:-1:2], top[1::2], top[2::2]):
            h = xy[b, 0] - xy[a, 0]
            for n, w in ((a, 1 / 6), (mm, 2 / 3), (b, 1 / 6)):
                f[eq[n, 1]] -= w * PRESSURE * h
        results = []
        for as_host in (False, True):
            for edges in (corners, curved):
                host = HostPatch(0)
                with mc.Model() as m:
                    if as_host:
                        m.set_host_body(1, xy, eq, n_eq)
                        m.add_element_matrices(1, eltvar=element_freedoms(eq, q9), a_elt=ke)
                        m.set_load_vector(1, f)
                        if edges is corners:
                            continue  # a host body has no cells to find the middles from
                    else:
                        m.set_mesh(1, xy, q9)
                        m.set_material(1, patch_scene.E1, patch_scene.NU1)
                        m.fix(1, node[0, :], mc.MC_X)
                        m.add_pressure(1, patch_scene.chain(top[::2]), PRESSURE)
                    if edges is curved:
                        m.set_contact_curved(1, edges)
                    else:
                        m.set_contact(1, edges)
                    host.mesh_body_2(m)
                    m.solve()
                    results.append((m.get_displacement(1), m.get_contact_pressure()))
        self.assertEqual(len(results), 3)
        for u, p in results[1:]:
            np.testing.assert_allclose(u, results[0][0], rtol=0, atol=1e-10 * self.scale)
            np.testing.assert_allclose(p, results[0][1], rtol=0, atol=1e-10 * PRESSURE)
        np.testing.assert_allclose(results[0][1], PRESSURE, rtol=1e-8)

    def test_binding_checks(self):
        host = HostPatch(0)
        with mc.Model() as m:
            with self.assertRaises(mc.MortarContactError) as cm:
                m.get_equation_solution(1)  # no body yet: the size is unknown
            self.assertEqual(cm.exception.status, mc.MC_ERROR_STATE)
            with self.assertRaises(mc.ArgumentError):
                m.set_host_body(1, host.xy1, host.eq1[:-1], host.n_eq1)  # one row short
            with self.assertRaises(mc.ArgumentError):
                m.set_host_body(1, host.xy1, host.eq1.astype(float), host.n_eq1)
            m.set_host_body(1, host.xy1, host.eq1, host.n_eq1)
            with self.assertRaises(mc.ArgumentError):
                m.add_stiffness(1, [0, 1], [0, 1])  # no values
            with self.assertRaises(mc.ArgumentError):
                m.add_stiffness(1, [0, 1], [0], [1.0, 1.0])
            with self.assertRaises(mc.ArgumentError):
                m.add_stiffness(1, sp.eye(host.n_eq1 + 1))  # not n_equations square
            with self.assertRaises(mc.ArgumentError):
                m.add_stiffness(1, np.ones((2, 3)))
            with self.assertRaises(mc.ArgumentError):
                m.add_element_matrices(1, [1, 3], [0, 1], np.eye(2).ravel())  # eltptr[0] is not the base
            with self.assertRaises(mc.ArgumentError):
                m.add_element_matrices(1, [0, 2], [0, 1, 2], np.eye(2).ravel())
            with self.assertRaises(mc.ArgumentError):
                m.add_element_matrices(1, [0, 2, 1], [0, 1], np.eye(2).ravel())
            with self.assertRaises(mc.ArgumentError):
                m.add_element_matrices(1, eltvar=[[0, 1]], a_elt=np.eye(3)[None])
            with self.assertRaises(mc.ArgumentError):
                m.set_contact_curved(1, [[0, 1]])
            self.assertEqual(m.n_cells(1), 0)
            self.assertEqual(m.n_equations(1), host.n_eq1)

    def test_library_errors(self):
        host = HostPatch(0)
        with mc.Model() as m:
            m.set_host_body(1, host.xy1, host.eq1, host.n_eq1)
            bad = [
                (mc.MC_ERROR_ARGUMENT, lambda: m.add_stiffness(1, [0, 2], [1, 1], [1.0, 2.0],  # both triangles
                                                               storage=mc.MC_MATRIX_TRIANGLE)),
                (mc.MC_ERROR_ARGUMENT, lambda: m.add_stiffness(1, [0], [host.n_eq1], [1.0])),    # above the system
                (mc.MC_ERROR_ARGUMENT, lambda: m.add_stiffness(1, [0], [0], [np.nan])),
                (mc.MC_ERROR_ARGUMENT, lambda: m.set_load_vector(1, np.zeros(host.n_eq1 + 1))),
                (mc.MC_ERROR_ARGUMENT, lambda: m.set_host_body(1, host.xy1, np.zeros_like(host.eq1), host.n_eq1)),
                (mc.MC_ERROR_STATE, lambda: m.set_material(1, 1.0, 0.3)),
                (mc.MC_ERROR_STATE, lambda: m.get_contact_load(1)),  # before a solve
            ]
            for status, call in bad:
                with self.assertRaises(mc.MortarContactError) as cm:
                    call()
                self.assertEqual(cm.exception.status, status, cm.exception.message)
                self.assertTrue(cm.exception.message)
            # the model is still usable, and the host body is what it was
            self.assertEqual(m.n_equations(1), host.n_eq1)
            m.add_stiffness(1, host.k1)
            m.set_load_vector(1, host.f1)
            m.set_contact(1, patch_scene.chain(host.n1[:, 0]))
            host.mesh_body_2(m)
            m.solve()
            self.assert_as_meshes(m)
            for getter in (m.get_stress, m.get_nodal_stress, m.get_error_indicator, m.get_reaction):
                with self.assertRaises(mc.MortarContactError) as cm:
                    getter(1)  # they need cells: the library says why
                self.assertEqual(cm.exception.status, mc.MC_ERROR_STATE)
            # MC_MATRIX_FULL entries summed over the calls must be symmetric: checked by the solve
            m.add_stiffness(1, [0, 1], [1, 0], [1e-3, 2e-3])
            with self.assertRaises(mc.MortarContactError) as cm:
                m.solve()
            self.assertEqual(cm.exception.status, mc.MC_ERROR_ARGUMENT)


if __name__ == "__main__":
    unittest.main()
