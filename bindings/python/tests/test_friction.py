"""Friction through the Python binding (mc_set_friction, mc_reset_history, MC_OPTION_LOAD_STEPS,
MC_OPTION_FRICTION_CT, MC_INFO_STICK_NODES/_SLIP_NODES/_FRICTION_COMPLEMENTARITY and the
MC_CONTACT_SHEAR/_SLIP/_SLIP_TOTAL/_STATE fields): the frictional patch tests on two blocks with
non-matching, distorted meshes (same material) in the uniform stress sigma_xx = 0,
sigma_yy = -p, sigma_xy = tau, exact in both bodies:
- stick: tau = 0.4 mu p, the upper block held along x by friction alone: every position sticks,
  shear -tau, slip 0, the displacements the exact field;
- slip: the upper block's top moved by delta along x beyond the exact field: every position
  slips, shear -mu p (Coulomb) or minus the Tresca bound, slip delta; solved again with the same
  loads nothing moves (slip 0, the accumulated slip still delta); reset_history forgets it;
- bad input: a negative mu or bound, an unknown law, a pair out of range, friction without
  contact, load steps < 1, a negative complementarity parameter; the model stays usable."""
import unittest

import numpy as np

import _paths  # noqa: F401
import mortarcontact as mc
from patch_scene import chain, grid, quads, triangles

P = 0.01
E, NU = 1.0, 0.3


def exact(xy, tau, delta=0.0):
    """The exact field (plane strain): u_x = exx x + gamma y (+ delta above y = 1), u_y = eyy y."""
    exx, eyy, gamma = NU * (1 + NU) * P / E, -(1 - NU ** 2) * P / E, 2 * (1 + NU) * tau / E
    return np.column_stack([exx * xy[:, 0] + gamma * xy[:, 1] + delta, eyy * xy[:, 1]])


def build(m, tau, base=0, delta=None):
    """Body 1 the upper block [0, 1] x [1, 2] (P1, 5 cells across), body 2 the lower one
    [0, 1] x [0, 1] (Q1, 7 cells across), the lower base held to the exact field, tractions on
    every free side. delta: the upper top's x prescribed (the exact field plus delta) instead
    of loaded in x. Returns (xy1, xy2)."""
    xy1, n1 = grid(0.0, 1.0, 1.0, 2.0, 5, 3, seed=1)
    xy2, n2 = grid(0.0, 1.0, 0.0, 1.0, 7, 2, seed=2)
    m.set_mesh(1, xy1, triangles(n1) + base)
    m.set_mesh(2, xy2, quads(n2) + base)
    for body, node in ((1, n1), (2, n2)):
        m.set_material(body, E, NU)
        m.add_traction(body, chain(node[0, :]) + base, [0.0, -tau])   # left, n = (-1, 0)
        m.add_traction(body, chain(node[-1, :]) + base, [0.0, tau])   # right, n = (1, 0)
    bottom = n2[:, 0]
    m.fix(2, bottom + base, mc.MC_XY, exact(xy2[bottom], tau))
    top = n1[:, -1]
    if delta is None:
        m.add_traction(1, chain(top) + base, [tau, -P])
    else:
        m.add_traction(1, chain(top) + base, [0.0, -P])
        m.fix(1, top + base, mc.MC_X, exact(xy1[top], tau, delta))
    m.set_contact(1, chain(n1[:, 0]) + base)
    m.set_contact(2, chain(n2[:, -1]) + base)
    return xy1, xy2


class TestFriction(unittest.TestCase):
    def check_fields(self, m, n, state, shear, slip):
        for field in (mc.MC_CONTACT_SHEAR, mc.MC_CONTACT_SLIP, mc.MC_CONTACT_SLIP_TOTAL, mc.MC_CONTACT_STATE):
            self.assertEqual(m.get_pair_contact(1, field).shape, (n,))
        np.testing.assert_array_equal(m.get_pair_contact(1, mc.MC_CONTACT_STATE), np.full(n, float(state)))
        np.testing.assert_allclose(m.get_pair_contact(1, mc.MC_CONTACT_PRESSURE), P, rtol=1e-10)
        np.testing.assert_allclose(m.get_pair_contact(1, mc.MC_CONTACT_SHEAR), shear, rtol=0, atol=1e-10 * P)
        np.testing.assert_allclose(m.get_pair_contact(1, mc.MC_CONTACT_SLIP), slip, rtol=0,
                                   atol=1e-10 * max(abs(slip), P))

    def check_displacements(self, m, xy1, xy2, tau, delta=0.0):
        u1, u2 = exact(xy1, tau, delta), exact(xy2, tau)
        scale = max(np.abs(u1).max(), np.abs(u2).max())
        np.testing.assert_allclose(m.get_displacement(1), u1, rtol=0, atol=1e-10 * scale)
        np.testing.assert_allclose(m.get_displacement(2), u2, rtol=0, atol=1e-10 * scale)

    def test_stick(self):
        mu = 0.5
        tau = 0.4 * mu * P
        for law, value in ((mc.MC_FRICTION_COULOMB, mu), (mc.MC_FRICTION_TRESCA, mu * P)):
            for method, base in ((mc.MC_METHOD_MORTAR, 0), (mc.MC_METHOD_DUAL_MORTAR, 1)):
                with self.subTest(law=law, method=method), mc.Model(index_base=base) as m:
                    xy1, xy2 = build(m, tau, base)
                    m.set_option_int(mc.MC_OPTION_METHOD, method)
                    m.set_friction(1, law, value)
                    m.solve()
                    n = m.get_pair_contact_count(1)
                    self.assertEqual(n, 6)  # body 1 has 5 cells along the interface
                    self.check_fields(m, n, mc.MC_STATE_STICK, -tau, 0.0)
                    np.testing.assert_allclose(m.get_pair_contact(1, mc.MC_CONTACT_SLIP_TOTAL), 0.0, atol=1e-10 * P)
                    self.check_displacements(m, xy1, xy2, tau)
                    self.assertEqual(m.get_info(mc.MC_INFO_STICK_NODES), n)
                    self.assertIsInstance(m.get_info(mc.MC_INFO_STICK_NODES), int)
                    self.assertEqual(m.get_info(mc.MC_INFO_SLIP_NODES), 0)
                    self.assertLessEqual(m.get_info(mc.MC_INFO_FRICTION_COMPLEMENTARITY), 1e-10)

    def test_options_do_not_change_the_answer(self):
        """MC_OPTION_LOAD_STEPS (through set_option's integer dispatch) and MC_OPTION_FRICTION_CT
        (real): a proportional ramp and another complementarity parameter, the same answer."""
        mu = 0.5
        tau = 0.4 * mu * P
        with mc.Model() as m:
            xy1, xy2 = build(m, tau)
            m.set_friction(1, mc.MC_FRICTION_COULOMB, mu)
            m.set_option(mc.MC_OPTION_LOAD_STEPS, 3)
            m.set_option(mc.MC_OPTION_FRICTION_CT, 7.5)
            m.solve()
            self.check_fields(m, 6, mc.MC_STATE_STICK, -tau, 0.0)
            self.check_displacements(m, xy1, xy2, tau)

    def test_slip_and_history(self):
        mu, bound, delta = 0.3, 0.25 * P, 0.05
        for law, value, tau in ((mc.MC_FRICTION_COULOMB, mu, mu * P), (mc.MC_FRICTION_TRESCA, bound, bound)):
            with self.subTest(law=law), mc.Model() as m:
                xy1, xy2 = build(m, tau, delta=delta)
                m.set_friction(1, law, value)
                m.solve()
                self.check_fields(m, 6, mc.MC_STATE_SLIP, -tau, delta)
                np.testing.assert_allclose(m.get_pair_contact(1, mc.MC_CONTACT_SLIP_TOTAL), delta, rtol=1e-10)
                self.check_displacements(m, xy1, xy2, tau, delta)
                self.assertEqual(m.get_info(mc.MC_INFO_SLIP_NODES), 6)
                self.assertEqual(m.get_info(mc.MC_INFO_STICK_NODES), 0)
                # the same loads again: a step of nothing from the converged state
                m.solve()
                np.testing.assert_allclose(m.get_pair_contact(1, mc.MC_CONTACT_SLIP), 0.0, atol=1e-10 * delta)
                np.testing.assert_allclose(m.get_pair_contact(1, mc.MC_CONTACT_SLIP_TOTAL), delta, rtol=1e-10)
                self.check_displacements(m, xy1, xy2, tau, delta)
                # forgotten: the whole way from the unloaded state again
                m.reset_history()
                m.solve()
                np.testing.assert_allclose(m.get_pair_contact(1, mc.MC_CONTACT_SLIP), delta, rtol=1e-10)
                np.testing.assert_allclose(m.get_pair_contact(1, mc.MC_CONTACT_SLIP_TOTAL), delta, rtol=1e-10)

    def test_bad_input(self):
        with mc.Model() as m:
            with self.assertRaises(mc.MortarContactError) as cm:
                m.set_friction(1, mc.MC_FRICTION_COULOMB, 0.3)  # no contact pair yet
            self.assertEqual(cm.exception.status, mc.MC_ERROR_STATE)
            self.assertIn("contact pair", cm.exception.message)
            build(m, 0.0)
            for args, status, word in (((1, mc.MC_FRICTION_COULOMB, -0.1), mc.MC_ERROR_ARGUMENT, "mu"),
                                       ((1, mc.MC_FRICTION_TRESCA, -1.0), mc.MC_ERROR_ARGUMENT, "bound"),
                                       ((1, mc.MC_FRICTION_COULOMB, float("inf")), mc.MC_ERROR_ARGUMENT, "mu"),
                                       ((1, 3, 0.3), mc.MC_ERROR_ARGUMENT, "law"),
                                       ((2, mc.MC_FRICTION_COULOMB, 0.3), mc.MC_ERROR_ARGUMENT, "pair"),
                                       ((0, mc.MC_FRICTION_COULOMB, 0.3), mc.MC_ERROR_ARGUMENT, "pair")):
                with self.subTest(args=args):
                    with self.assertRaises(mc.MortarContactError) as cm:
                        m.set_friction(*args)
                    self.assertEqual(cm.exception.status, status)
                    self.assertIn(word, cm.exception.message)
            with self.assertRaises(mc.MortarContactError) as cm:
                m.set_option_int(mc.MC_OPTION_LOAD_STEPS, 0)
            self.assertIn("MC_OPTION_LOAD_STEPS", cm.exception.message)
            with self.assertRaises(mc.MortarContactError) as cm:
                m.set_option_real(mc.MC_OPTION_FRICTION_CT, -1.0)
            self.assertIn("MC_OPTION_FRICTION_CT", cm.exception.message)
            # usable: a frictional solve after the refusals
            m.set_friction(1, mc.MC_FRICTION_COULOMB, 0.3)
            m.solve()
            np.testing.assert_allclose(m.get_pair_contact(1, mc.MC_CONTACT_SHEAR), 0.0, atol=1e-10 * P)
            # the sparse interface path: the same answer
            u = m.get_displacement(1)
            m.set_option_int(mc.MC_OPTION_INTERFACE_SOLVER, mc.MC_INTERFACE_SPARSE)
            m.reset_history()
            m.solve()
            np.testing.assert_allclose(m.get_displacement(1), u, rtol=0, atol=1e-10 * np.abs(u).max())


if __name__ == "__main__":
    unittest.main()
