"""Assemblies through the Python binding (mc_set_body_count, mc_add_contact_pair,
mc_set_pair_surface, mc_set_pair_gap_offset, mc_get_pair_contact*): a stack of three blocks with
non-matching, distorted meshes under a uniform pressure, two contact pairs (top on middle,
middle on bottom) - a patch test: every contact pressure of both pairs is p - and bad input."""
import unittest

import numpy as np

import _paths  # noqa: F401
import mortarcontact as mc
from patch_scene import chain, grid, quads, triangles

P = 0.25
E, NU = 2.0, 0.3


def build_stack(m, base=0):
    """Blocks [0, 1] x [y0, y0 + 1], y0 = 2, 1, 0 as bodies 1, 2, 3 (P1, Q1, P1 cells; 3, 5 and 4
    cells across); rollers on every block's left side, the bottom block on rollers at y = 0, p
    on the top block's top. The top and middle blocks are held in y by contact alone. Returns
    the grids' node numbers and the two pairs."""
    blocks = ((2.0, 3, triangles), (1.0, 5, quads), (0.0, 4, triangles))
    nodes = []
    m.set_body_count(3)
    for body, (y0, nx, cells) in enumerate(blocks, start=1):
        xy, node = grid(0.0, 1.0, y0, y0 + 1.0, nx, 2, seed=body)
        m.set_mesh(body, xy, cells(node) + base)
        m.set_material(body, E, NU)
        m.fix(body, node[0, :] + base, mc.MC_X)
        nodes.append(node)
    m.fix(3, nodes[2][:, 0] + base, mc.MC_Y)
    m.add_pressure(1, chain(nodes[0][:, -1]) + base, P)
    pairs = []
    for upper in (1, 2):  # body `upper` (non-mortar) on the body below it (mortar)
        pair = m.add_contact_pair(upper, upper + 1)
        m.set_pair_surface(pair, upper, chain(nodes[upper - 1][:, 0]) + base)
        m.set_pair_surface(pair, upper + 1, chain(nodes[upper][:, -1]) + base)
        pairs.append(pair)
    return nodes, pairs


class TestPairs(unittest.TestCase):
    def check_stack(self, method, base):
        with mc.Model(index_base=base) as m:
            nodes, pairs = build_stack(m, base)
            self.assertEqual(pairs, [1, 2])  # numbered from 1 whatever the index base
            self.assertEqual(m.body_count, 3)
            m.set_option_int(mc.MC_OPTION_METHOD, method)
            m.solve()
            counts = []
            for pair, upper in zip(pairs, (1, 2)):
                n = m.get_pair_contact_count(pair)
                counts.append(n)
                bottom = nodes[upper - 1][:, 0] + base  # the non-mortar body's bottom nodes
                self.assertEqual(n, len(bottom))
                ids = m.get_pair_contact_nodes(pair)
                self.assertEqual(ids.dtype, np.int32)
                self.assertEqual(sorted(ids), sorted(bottom))
                p = m.get_pair_contact(pair, mc.MC_CONTACT_PRESSURE)
                self.assertEqual(p.shape, (n,))
                np.testing.assert_allclose(p, P, rtol=1e-10, atol=0)
                f = m.get_pair_contact(pair, mc.MC_CONTACT_FORCE)
                self.assertAlmostEqual(f.sum(), P * 1.0, delta=1e-10 * P)
                normal = m.get_pair_contact(pair, mc.MC_CONTACT_NORMAL)
                self.assertEqual(normal.shape, (n, 2))
                np.testing.assert_allclose(normal, np.tile([0.0, -1.0], (n, 1)), atol=1e-12)
                np.testing.assert_allclose(m.get_pair_contact(pair, mc.MC_CONTACT_INITIAL_GAP), 0.0, atol=1e-14)
                np.testing.assert_allclose(m.get_pair_contact(pair, mc.MC_CONTACT_GAP), 0.0, atol=1e-10)
            self.assertEqual(m.get_info(mc.MC_INFO_ACTIVE_NODES), sum(counts))
            # the two-body getters read pair 1
            np.testing.assert_array_equal(m.get_contact_pressure(), m.get_pair_contact(1, mc.MC_CONTACT_PRESSURE))
            np.testing.assert_array_equal(m.get_contact_nodes(), m.get_pair_contact_nodes(1))
            # every body 1..3 reads back: the uniform stress sigma_yy = -p, sigma_xx = 0
            for body in (1, 2, 3):
                s = m.get_stress(body)
                self.assertEqual(s.shape, (m.n_cells(body), 4))
                np.testing.assert_allclose(s[:, 1], -P, rtol=1e-10)
                np.testing.assert_allclose(s[:, 0], 0.0, atol=1e-10 * P)
                self.assertEqual(m.get_displacement(body).shape, (m.n_nodes(body), 2))
            u1 = m.get_displacement(1)
            # an interference on pair 2: the two upper blocks rise by it, the pressures stay p;
            # a re-solve (offsets are values: the factorizations are kept) ...
            delta = 1e-3
            m.set_pair_gap_offset(2, nodes[1][:, 0] + base, -delta)
            m.solve()
            self.assertEqual(m.get_info(mc.MC_INFO_FACTORIZATIONS), 0)
            np.testing.assert_allclose(m.get_pair_contact(2, mc.MC_CONTACT_INITIAL_GAP), -delta, rtol=1e-12)
            for pair in pairs:
                np.testing.assert_allclose(m.get_pair_contact(pair, mc.MC_CONTACT_PRESSURE), P, rtol=1e-10)
            np.testing.assert_allclose(m.get_displacement(1)[:, 1] - u1[:, 1], delta, rtol=1e-8)
        # ... and a model given the offset before its first solve
        with mc.Model(index_base=base) as m:
            nodes, pairs = build_stack(m, base)
            m.set_option_int(mc.MC_OPTION_METHOD, method)
            m.set_pair_gap_offset(2, nodes[1][:, 0] + base, -delta)
            m.solve()
            np.testing.assert_allclose(m.get_pair_contact(2, mc.MC_CONTACT_INITIAL_GAP), -delta, rtol=1e-12)
            np.testing.assert_allclose(m.get_pair_contact(1, mc.MC_CONTACT_INITIAL_GAP), 0.0, atol=1e-14)
            for pair in pairs:
                np.testing.assert_allclose(m.get_pair_contact(pair, mc.MC_CONTACT_PRESSURE), P, rtol=1e-10)
            np.testing.assert_allclose(m.get_displacement(1)[:, 1] - u1[:, 1], delta, rtol=1e-8)

    def test_stack_mortar(self):
        self.check_stack(mc.MC_METHOD_MORTAR, 0)

    def test_stack_dual_mortar_one_based(self):
        self.check_stack(mc.MC_METHOD_DUAL_MORTAR, 1)

    def test_bad_input(self):
        """A pair of a body with itself, a pair that does not exist, a body beyond the count:
        the library's status and message (or the binding's ArgumentError); the model stays usable."""
        with mc.Model() as m:
            with self.assertRaises(mc.MortarContactError) as cm:
                m.set_body_count(1)
            self.assertEqual(cm.exception.status, mc.MC_ERROR_ARGUMENT)
            self.assertIn("n = 1", cm.exception.message)
            m.set_body_count(3)
            with self.assertRaises(mc.MortarContactError) as cm:
                m.add_contact_pair(2, 2)
            self.assertEqual(cm.exception.status, mc.MC_ERROR_ARGUMENT)
            self.assertIn("two different bodies", cm.exception.message)
            self.assertEqual(cm.exception.message, m.errmsg)
            self.assertIn(cm.exception.message, str(cm.exception))
            self.assertEqual(m.add_contact_pair(1, 2), 1)  # usable afterwards
            with self.assertRaises(mc.MortarContactError) as cm:
                m.set_pair_surface(2, 1, [[0, 1]])
            self.assertEqual(cm.exception.status, mc.MC_ERROR_ARGUMENT)
            self.assertIn("pair = 2", cm.exception.message)
            with self.assertRaises(mc.MortarContactError) as cm:
                m.set_pair_surface(1, 3, [[0, 1]])  # body 3 is not in pair 1
            self.assertEqual(cm.exception.status, mc.MC_ERROR_ARGUMENT)
            with self.assertRaises(mc.MortarContactError) as cm:
                m.get_pair_contact_count(1)  # no solve yet
            self.assertEqual(cm.exception.status, mc.MC_ERROR_STATE)
            with self.assertRaises(mc.ArgumentError):
                m.set_pair_surface(1, 1, [[0, 1, 2]])  # 3 ids per edge: set_pair_surface_curved
            with self.assertRaises(mc.ArgumentError):
                m.get_displacement(4)  # the model has 3 bodies
            with self.assertRaises(mc.MortarContactError) as cm:
                m.get_displacement(3)  # a body of the model without a mesh
            self.assertEqual(cm.exception.status, mc.MC_ERROR_STATE)
            m.set_body_count(2)  # pair 1 uses bodies 1 and 2 only: allowed
            with self.assertRaises(mc.ArgumentError):
                m.get_displacement(3)  # dropped
            m.set_body_count(3)
            self.assertEqual(m.add_contact_pair(2, 3), 2)
            with self.assertRaises(mc.MortarContactError) as cm:
                m.set_body_count(2)  # pair 2 uses body 3
            self.assertEqual(cm.exception.status, mc.MC_ERROR_STATE)
            self.assertEqual(m.body_count, 3)


if __name__ == "__main__":
    unittest.main()
