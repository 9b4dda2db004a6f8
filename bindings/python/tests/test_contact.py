"""Contact solves through the Python binding: the patch test (mortar and dual mortar) and the
Hertz scene of examples/python/hertz.py against the analytic solution."""
import math
import os
import sys
import unittest

import numpy as np

import _paths
import mortarcontact as mc
import patch_scene

sys.path.insert(0, _paths.EXAMPLES)
import hertz  # noqa: E402


class TestPatch(unittest.TestCase):
    def check(self, method, base):
        with mc.Model(index_base=base) as m:
            xy1, xy2 = patch_scene.build(m, base)
            m.set_option_int(mc.MC_OPTION_METHOD, method)
            m.solve()
            u1, u2 = patch_scene.exact(xy1, xy2)
            scale = max(np.abs(u1).max(), np.abs(u2).max())
            np.testing.assert_allclose(m.get_displacement(1), u1, rtol=0, atol=1e-9 * scale)
            np.testing.assert_allclose(m.get_displacement(2), u2, rtol=0, atol=1e-9 * scale)
            p = m.get_contact_pressure()
            self.assertEqual(len(p), 6)  # body 1 has 5 cells along the interface
            np.testing.assert_allclose(p, patch_scene.PRESSURE, rtol=1e-8)
            nodes = m.get_contact_nodes()
            self.assertEqual(nodes.min(), base)
            np.testing.assert_allclose(m.get_contact_force().sum(), patch_scene.PRESSURE * 1.0, rtol=1e-8)
            np.testing.assert_allclose(m.get_contact_gap(), 0.0, atol=1e-9 * scale)
            np.testing.assert_allclose(m.get_contact_initial_gap(), 0.0, atol=1e-14)
            np.testing.assert_allclose(m.get_contact_normal(), np.tile([0.0, -1.0], (6, 1)), atol=1e-14)
            s = m.get_stress(1)
            np.testing.assert_allclose(s[:, 1], -patch_scene.PRESSURE, rtol=1e-8)
            sn = m.get_nodal_stress(1)
            self.assertEqual(sn.shape, (len(xy1), 4))
            np.testing.assert_allclose(sn[:, 1], -patch_scene.PRESSURE, rtol=1e-8)
            self.assertEqual(m.get_info(mc.MC_INFO_ACTIVE_NODES), int(np.sum(m.get_contact_force() > 0)))
            self.assertLess(m.get_info(mc.MC_INFO_COMPLEMENTARITY), 1e-8)
            self.assertLess(m.get_info(mc.MC_INFO_GAP_RESIDUAL), 1e-10)  # a real info (float), at round-off
            # uniform stress: the error estimate is round-off, and so is every cell's indicator
            self.assertLess(m.get_info(mc.MC_INFO_ERROR_ESTIMATE), 1e-10)
            for body in (1, 2):
                eta = m.get_error_indicator(body)
                self.assertEqual(eta.shape, (m.n_cells(body),))
                self.assertLess(eta.max(), 1e-10)

    def test_mortar(self):
        self.check(mc.MC_METHOD_MORTAR, 0)

    def test_faceted_surface_same_patch_answer(self):
        """A flat interface is its own smooth reconstruction: both geometries pass the patch test."""
        with mc.Model() as m:
            xy1, xy2 = patch_scene.build(m)
            m.solve()
            p_smooth = m.get_contact_pressure()
            m.set_option(mc.MC_OPTION_CONTACT_SURFACE, mc.MC_SURFACE_FACETED)
            m.solve()
            np.testing.assert_allclose(m.get_contact_pressure(), p_smooth, rtol=1e-12)
            np.testing.assert_allclose(p_smooth, patch_scene.PRESSURE, rtol=1e-8)

    def test_interface_solver_forced(self):
        """MC_OPTION_INTERFACE_SOLVER forces either path; MC_INFO_INTERFACE_SOLVER says which
        one ran, and both pass the patch test. 3 is not a value."""
        for path in (mc.MC_INTERFACE_SPARSE, mc.MC_INTERFACE_CONDENSED):
            with mc.Model() as m:
                xy1, xy2 = patch_scene.build(m)
                m.set_option(mc.MC_OPTION_INTERFACE_SOLVER, path)
                m.solve()
                self.assertEqual(m.get_info(mc.MC_INFO_INTERFACE_SOLVER), path)
                u1, u2 = patch_scene.exact(xy1, xy2)
                scale = max(np.abs(u1).max(), np.abs(u2).max())
                np.testing.assert_allclose(m.get_displacement(1), u1, rtol=0, atol=1e-9 * scale)
                np.testing.assert_allclose(m.get_contact_pressure(), patch_scene.PRESSURE, rtol=1e-8)
                with self.assertRaises(mc.MortarContactError) as cm:
                    m.set_option_int(mc.MC_OPTION_INTERFACE_SOLVER, 3)
                self.assertEqual(cm.exception.status, mc.MC_ERROR_ARGUMENT)

    def test_dual_mortar_one_based(self):
        self.check(mc.MC_METHOD_DUAL_MORTAR, 1)

    def test_load_step_reuses_factorization(self):
        with mc.Model() as m:
            xy1, xy2 = patch_scene.build(m)
            m.solve()
            u = m.get_displacement(1)
            self.assertGreater(m.get_info_int(mc.MC_INFO_FACTORIZATIONS), 0)
            # double the top pressure: the solution doubles, nothing is refactored
            m.clear_loads(1)
            n1 = np.arange(6 * 4).reshape(6, 4)
            m.add_pressure(1, patch_scene.chain(n1[:, -1]), 2 * patch_scene.PRESSURE)
            m.solve()
            self.assertEqual(m.get_info_int(mc.MC_INFO_FACTORIZATIONS), 0)
            np.testing.assert_allclose(m.get_displacement(1), 2 * u, rtol=0, atol=1e-9 * np.abs(u).max())


    def test_gap_offset_shifts_the_floating_block(self):
        """Body 1 floats vertically, held by contact: a uniform clearance c lowers it rigidly by
        c more, with the same stresses and pressure; the initial gap reports the offset."""
        c = 2e-3
        with mc.Model() as m:
            xy1, xy2 = patch_scene.build(m)
            m.solve()
            nodes = m.get_contact_nodes()
            m.set_gap_offset(nodes, c)
            m.solve()
            self.assertEqual(m.get_info_int(mc.MC_INFO_FACTORIZATIONS), 0)
            u1, u2 = patch_scene.exact(xy1, xy2)
            scale = max(np.abs(u1).max(), np.abs(u2).max())
            np.testing.assert_allclose(m.get_displacement(1), u1 - [0.0, c], rtol=0, atol=1e-9 * scale)
            np.testing.assert_allclose(m.get_displacement(2), u2, rtol=0, atol=1e-9 * scale)
            np.testing.assert_allclose(m.get_contact_pressure(), patch_scene.PRESSURE, rtol=1e-8)
            np.testing.assert_allclose(m.get_contact_initial_gap(), c, atol=1e-14)
            with self.assertRaises(mc.MortarContactError) as cm:
                m.set_gap_offset([1], [c])  # node (0, 1) of body 1: on its left side, not its bottom
            self.assertEqual(cm.exception.status, mc.MC_ERROR_ARGUMENT)

    def test_log_reports_iterations(self):
        with mc.Model() as m:
            patch_scene.build(m)
            iterations = []
            m.set_log_callback(lambda level, text: iterations.append(text) if level == mc.MC_LOG_ITERATION else None)
            m.solve()
            self.assertEqual(len(iterations), m.get_info_int(mc.MC_INFO_ITERATIONS))
            self.assertTrue(all(t.startswith("active-set iteration %d:" % (k + 1)) for k, t in enumerate(iterations)))


class TestHertz(unittest.TestCase):
    def test_hertz(self):
        h = float(os.environ.get("MC_HERTZ_H", "0.008"))
        a, p0 = hertz.hertz_values()
        r = hertz.solve(h)
        print("\nHertz h=%g: p0 %.5f (fit %.5f) vs %.5f, a %.5f vs %.5f, dofs %d"
              % (h, r["p_max"], r["p0_fit"], p0, r["a_fit"], a, r["info"]["MC_INFO_DOFS"]))
        self.assertAlmostEqual(r["total_force"], hertz.P, delta=1e-6 * hertz.P)
        self.assertLess(abs(r["p_max"] / p0 - 1), 0.03)
        self.assertLess(abs(r["p0_fit"] / p0 - 1), 0.03)
        self.assertLess(abs(r["a_fit"] / a - 1), 0.03)
        self.assertTrue(np.all(r["p"] >= 0))
        self.assertTrue(np.all(r["p"][np.abs(r["x"]) > 1.3 * a] == 0))

    def test_hertz_mortar_normal(self):
        """With body 2's normals the O((a/R)^2) normal effect goes: within 1 % of Hertz."""
        a, p0 = hertz.hertz_values()
        r = hertz.solve(0.01, normal=mc.MC_NORMAL_MORTAR)
        print("\nHertz h=0.01, mortar-side normals: p0 %.5f vs %.5f, a %.5f vs %.5f"
              % (r["p_max"], p0, r["a_fit"], a))
        self.assertAlmostEqual(r["total_force"], hertz.P, delta=1e-6 * hertz.P)
        self.assertLess(abs(r["p_max"] / p0 - 1), 0.01)
        self.assertLess(abs(r["a_fit"] / a - 1), 0.01)


if __name__ == "__main__":
    unittest.main()
