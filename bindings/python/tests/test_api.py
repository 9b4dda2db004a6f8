"""Tests of the Python binding itself: loading, constants, argument checking, errors and the
model's life cycle. None of them needs a working contact solve."""
import gc
import os
import re
import shutil
import subprocess
import sys
import tempfile
import unittest

import numpy as np

import _paths
import mortarcontact as mc

SQUARE_XY = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
SQUARE_TRI = np.array([[0, 1, 2], [0, 2, 3]])


class TestLibrary(unittest.TestCase):
    def test_version(self):
        self.assertEqual(mc.version_string(), mc.MC_VERSION_STRING)
        self.assertEqual(mc.version_number(), mc.MC_VERSION_NUMBER)
        self.assertEqual(mc.__version__, mc.MC_VERSION_STRING)
        self.assertTrue(os.path.exists(mc.library_path()) or "/" not in mc.library_path())

    def test_status_string(self):
        self.assertEqual(mc.status_string(mc.MC_OK), "MC_OK")
        self.assertEqual(mc.status_string(mc.MC_ERROR_MESH), "MC_ERROR_MESH")
        self.assertEqual(mc.status_string(12345), "unknown status")

    def test_constants_match_header(self):
        """Every MC_ constant of the header is mirrored with the same value, and vice versa."""
        with open(_paths.HEADER) as f:
            text = re.sub(r"/\*.*?\*/", "", f.read(), flags=re.S)
        header = {}
        for name, value in re.findall(r"\b(MC_[A-Z0-9_]+)\s*=\s*(-?\d+)", text):
            header[name] = int(value)
        for name in ("MAJOR", "MINOR", "PATCH"):
            header["MC_VERSION_" + name] = int(re.search(r"#define MC_VERSION_%s (\d+)" % name, text).group(1))
        header["MC_VERSION_STRING"] = re.search(r'#define MC_VERSION_STRING "([^"]+)"', text).group(1)
        self.assertGreater(len(header), 40)
        mirrored = {k: getattr(mc.constants, k) for k in dir(mc.constants) if k.startswith("MC_")}
        mirrored.pop("MC_VERSION_NUMBER")  # a macro expression in the header; checked in test_version
        self.assertEqual(mirrored, header)
        for k in mc.constants.INT_OPTIONS | mc.constants.INT_INFOS:
            self.assertIn(k, header.values())

    def test_prototypes_cover_header(self):
        """The ctypes prototypes name exactly the header's functions."""
        with open(_paths.HEADER) as f:
            names = set(re.findall(r"MC_API[^;(]*?\b(mc_\w+)\s*\(", f.read()))
        self.assertEqual(set(mc._library.PROTOTYPES), names)


class TestLibrarySearch(unittest.TestCase):
    """Where the package looks for the library (mortarcontact._library)."""

    def test_environment_variable_is_the_only_candidate(self):
        old = os.environ.get("MORTARCONTACT_LIBRARY")
        os.environ["MORTARCONTACT_LIBRARY"] = "/nowhere/libmortarcontact.so.0"
        try:
            self.assertEqual(list(mc._library._candidates()), ["/nowhere/libmortarcontact.so.0"])
        finally:
            if old is None:
                del os.environ["MORTARCONTACT_LIBRARY"]
            else:
                os.environ["MORTARCONTACT_LIBRARY"] = old

    def test_path_recorded_by_install_is_used(self):
        """A copy of the package with the _installed_library module cmake --install writes,
        pointing at the loaded library's folder, loads that library with no variable set."""
        library = os.path.realpath(mc.library_path())
        with tempfile.TemporaryDirectory() as site:
            package = os.path.join(site, "mortarcontact")
            shutil.copytree(os.path.dirname(mc.__file__), package,
                            ignore=shutil.ignore_patterns("__pycache__", "_installed_library.py"))
            with open(os.path.join(package, "_installed_library.py"), "w") as f:
                f.write("LIBRARY_DIR = %r\n" % os.path.relpath(os.path.dirname(library), package))
            env = {k: v for k, v in os.environ.items() if k not in ("MORTARCONTACT_LIBRARY", "PYTHONPATH")}
            env["PYTHONPATH"] = site
            loaded = subprocess.run(
                [sys.executable, "-c", "import mortarcontact; print(mortarcontact.library_path())"],
                env=env, cwd=site, check=True, capture_output=True, text=True).stdout.strip()
        self.assertEqual(os.path.realpath(loaded), library)
        self.assertEqual(os.path.dirname(loaded), os.path.dirname(library))


class TestModel(unittest.TestCase):
    def test_context_manager_closes(self):
        with mc.Model() as m:
            self.assertFalse(m.closed)
        self.assertTrue(m.closed)
        with self.assertRaises(mc.MortarContactError) as cm:
            m.set_material(1, 1.0, 0.3)
        self.assertEqual(cm.exception.status, mc.MC_ERROR_STATE)
        m.close()  # idempotent

    def test_del_closes(self):
        m = mc.Model()
        m.set_mesh(1, SQUARE_XY, SQUARE_TRI)
        del m
        gc.collect()  # no crash, no leak report under ASan

    def test_library_error_carries_status_and_message(self):
        with mc.Model() as m:
            m.set_mesh(1, SQUARE_XY, SQUARE_TRI)
            with self.assertRaises(mc.MortarContactError) as cm:
                m.set_material(1, -1.0, 0.3)
            self.assertEqual(cm.exception.status, mc.MC_ERROR_MATERIAL)
            self.assertTrue(cm.exception.message)
            self.assertIn(cm.exception.message, str(cm.exception))
            self.assertIn("MC_ERROR_MATERIAL", str(cm.exception))
            m.set_material(1, 1.0, 0.3)  # the model stays usable
            self.assertEqual(m.errmsg, "")

    def test_bad_body(self):
        with mc.Model() as m:
            with self.assertRaises(mc.MortarContactError) as cm:
                m.set_material(3, 1.0, 0.3)
            self.assertEqual(cm.exception.status, mc.MC_ERROR_ARGUMENT)
            with self.assertRaises(mc.ArgumentError):
                m.get_displacement(0)

    def test_bad_mesh_id(self):
        with mc.Model() as m:
            with self.assertRaises(mc.MortarContactError) as cm:
                m.set_mesh(1, SQUARE_XY, [[0, 1, 2], [0, 2, 4]])
            self.assertIn(cm.exception.status, (mc.MC_ERROR_ARGUMENT, mc.MC_ERROR_MESH))

    def test_shape_and_dtype_checks(self):
        with mc.Model() as m:
            for xy, cells in ((SQUARE_XY.T, SQUARE_TRI),              # (2, n)
                              (SQUARE_XY.ravel(), SQUARE_TRI),        # flat
                              (SQUARE_XY.astype(complex), SQUARE_TRI),
                              (SQUARE_XY, SQUARE_TRI.astype(float)),  # float ids
                              (SQUARE_XY, SQUARE_TRI.ravel()),
                              (SQUARE_XY, SQUARE_TRI + 2 ** 40)):
                with self.assertRaises(mc.ArgumentError) as cm:
                    m.set_mesh(1, xy, cells)
                self.assertEqual(cm.exception.status, mc.MC_ERROR_ARGUMENT)
                self.assertIsInstance(cm.exception, ValueError)
            m.set_mesh(1, SQUARE_XY, SQUARE_TRI)
            with self.assertRaises(mc.ArgumentError):
                m.add_traction(1, [[2, 3]], [[0.0, 1.0], [0.0, 1.0]])  # 1 edge, 2 tractions
            with self.assertRaises(mc.ArgumentError):
                m.set_cell_elasticity(1, np.eye(3)[None].repeat(3, axis=0))  # 3 cells, mesh has 2
            with self.assertRaises(mc.ArgumentError):
                m.fix(1, [0, 1], mc.MC_XY, np.zeros((3, 2)))

    def test_conversion_and_noncontiguous_input(self):
        """int coordinates, int64 ids, Fortran-ordered and strided arrays are converted."""
        with mc.Model() as m:
            xy = np.asfortranarray(np.array([[0, 0], [2, 0], [2, 2], [0, 2], [9, 9]])[:4])
            cells = np.array([[0, 1, 2, 9], [0, 2, 3, 9]], dtype=np.int64)[:, :3]
            self.assertFalse(cells.flags.c_contiguous)
            m.set_mesh(1, xy, cells)
            self.assertEqual(m.n_nodes(1), 4)
            self.assertEqual(m.n_cells(1), 2)
            m.set_cell_elasticity(1, np.tile(np.diag([2.0, 2.0, 1.0]).ravel(), (2, 1)))
            m.set_cell_elasticity(1, np.tile(np.diag([2.0, 2.0, 1.0]), (2, 1, 1)))

    def test_state_errors(self):
        with mc.Model() as m:
            with self.assertRaises(mc.MortarContactError) as cm:
                m.get_displacement(1)  # no mesh
            self.assertEqual(cm.exception.status, mc.MC_ERROR_STATE)
            m.set_mesh(1, SQUARE_XY, SQUARE_TRI)
            with self.assertRaises(mc.MortarContactError) as cm:
                m.get_displacement(1)  # no solve yet
            self.assertEqual(cm.exception.status, mc.MC_ERROR_STATE)
            for getter in (m.get_stress, m.get_nodal_stress, m.get_error_indicator):
                with self.assertRaises(mc.MortarContactError) as cm:
                    getter(1)  # no solve yet
                self.assertEqual(cm.exception.status, mc.MC_ERROR_STATE)
                with self.assertRaises(mc.MortarContactError) as cm:
                    getter(2)  # no mesh
                self.assertEqual(cm.exception.status, mc.MC_ERROR_STATE)
            with self.assertRaises(mc.MortarContactError) as cm:
                m.get_info_int(mc.MC_INFO_TIME_TOTAL)  # a real info through the integer call
            self.assertEqual(cm.exception.status, mc.MC_ERROR_ARGUMENT)

    def test_options(self):
        with mc.Model() as m:
            m.set_option(mc.MC_OPTION_METHOD, mc.MC_METHOD_DUAL_MORTAR)
            m.set_option(mc.MC_OPTION_TOLERANCE, 1e-12)
            m.set_option_int(mc.MC_OPTION_MAX_ITERATIONS, 50)
            with self.assertRaises(mc.MortarContactError) as cm:
                m.set_option_int(9999, 1)
            self.assertEqual(cm.exception.status, mc.MC_ERROR_ARGUMENT)
            # the contact geometry's options: the surface (int) and the feature angle (real)
            m.set_option(mc.MC_OPTION_CONTACT_SURFACE, mc.MC_SURFACE_FACETED)
            m.set_option(mc.MC_OPTION_FEATURE_ANGLE, 30.0)
            with self.assertRaises(mc.MortarContactError) as cm:
                m.set_option(mc.MC_OPTION_FEATURE_ANGLE, 180.0)
            self.assertEqual(cm.exception.status, mc.MC_ERROR_ARGUMENT)
            self.assertIn("MC_OPTION_FEATURE_ANGLE", str(cm.exception))
            with self.assertRaises(mc.MortarContactError) as cm:
                m.set_option(mc.MC_OPTION_CONTACT_SURFACE, 2)
            self.assertIn("MC_OPTION_CONTACT_SURFACE", str(cm.exception))
            # the integer options with a few values: each accepted, the rest refused naming the
            # option, and the real-valued call refused (set_option picks the integer call)
            self._check_int_option(m, mc.MC_OPTION_INTERFACE_SOLVER, "MC_OPTION_INTERFACE_SOLVER",
                                   (mc.MC_INTERFACE_AUTO, mc.MC_INTERFACE_CONDENSED, mc.MC_INTERFACE_SPARSE), (3, -1))
            self.assertEqual(m.get_info(mc.MC_INFO_INTERFACE_SOLVER), 0)  # an integer info; no solve yet
            # the error estimate: 1 (default) or 0
            self._check_int_option(m, mc.MC_OPTION_ERROR_ESTIMATE, "MC_OPTION_ERROR_ESTIMATE", (0, 1), (2,))
            self.assertIsInstance(m.get_info(mc.MC_INFO_ERROR_ESTIMATE), float)  # a real info
            # results on demand (0, default) or computed by every solve (1); their time a real info
            self._check_int_option(m, mc.MC_OPTION_EAGER_RESULTS, "MC_OPTION_EAGER_RESULTS", (1, 0), (2, -1))
            self.assertIsInstance(m.get_info(mc.MC_INFO_TIME_RESULTS), float)
            # the multipliers of a quadratic body 1: MC_MULTIPLIER_LINEAR (default) or _QUADRATIC
            self._check_int_option(m, mc.MC_OPTION_MULTIPLIER, "MC_OPTION_MULTIPLIER",
                                   (mc.MC_MULTIPLIER_QUADRATIC, mc.MC_MULTIPLIER_LINEAR), (2, -1))

    def _check_int_option(self, m, option, name, good, bad):
        for value in good:
            m.set_option(option, value)
        for value in bad:
            with self.assertRaises(mc.MortarContactError) as cm:
                m.set_option(option, value)
            self.assertEqual(cm.exception.status, mc.MC_ERROR_ARGUMENT)
            self.assertIn(name, str(cm.exception))
        with self.assertRaises(mc.MortarContactError) as cm:
            m.set_option_real(option, 1.0)
        self.assertEqual(cm.exception.status, mc.MC_ERROR_ARGUMENT)

    def test_single_body_solve_one_based(self):
        """A unit square, bottom clamped, pulled up on top; ids 1-based. No contact."""
        with mc.Model(index_base=1) as m:
            m.set_mesh(1, SQUARE_XY, SQUARE_TRI + 1)
            m.set_material(1, 1.0, 0.3)
            m.fix(1, [1, 2], mc.MC_XY)
            m.add_traction(1, [[3, 4]], (0.0, 1e-3))
            m.solve()
            u = m.get_displacement(1)
            self.assertEqual(u.shape, (4, 2))
            self.assertTrue(np.all(u[2:, 1] > 0))
            np.testing.assert_array_equal(u[:2], 0.0)
            r = m.get_reaction(1)
            self.assertAlmostEqual(r[:, 1].sum(), -1e-3, delta=1e-12)  # reactions balance the load
            s = m.get_stress(1)
            self.assertEqual(s.shape, (2, 4))
            # P1: a node gets the mean of its cells' constant stresses
            sn = m.get_nodal_stress(1)
            self.assertEqual(sn.shape, (4, 4))
            np.testing.assert_allclose(sn[[1, 3]], s, rtol=0, atol=1e-14)  # in one cell each
            np.testing.assert_allclose(sn[[0, 2]], np.tile(s.mean(axis=0), (2, 1)), rtol=0, atol=1e-14)
            self.assertGreater(m.get_info(mc.MC_INFO_DOFS), 0)
            self.assertGreater(m.get_info(mc.MC_INFO_STRAIN_ENERGY), 0.0)

    def test_quadratic_cells(self):
        """T6, Q8 and Q9 cells reach the library (set_mesh takes the cells' width as
        nodes_per_cell): one unit-square cell of each kind on rollers at x = 0 and y = 0, pressed
        with 0.1 on the top edge (named by its corners), is in a uniform stress, which every
        kind reproduces exactly, at its nodes too."""
        q9 = np.array([[0, 0], [1, 0], [1, 1], [0, 1], [0.5, 0], [1, 0.5], [0.5, 1], [0, 0.5], [0.5, 0.5]])
        t6 = np.array([[0, 0], [1, 0], [0, 1], [0.5, 0], [0.5, 0.5], [0, 0.5]])
        cases = ((t6, [0, 5, 2], [0, 3, 1], [1, 2], [-0.1, -0.1]),  # the hypotenuse is pressed
                 (q9[:8], [0, 7, 3], [0, 4, 1], [2, 3], [0.0, -0.1]),
                 (q9, [0, 7, 3], [0, 4, 1], [2, 3], [0.0, -0.1]))
        for xy, left, bottom, top, (sxx, syy) in cases:
            with self.subTest(nodes_per_cell=len(xy)), mc.Model() as m:
                m.set_mesh(1, xy, [list(range(len(xy)))])
                self.assertEqual((m.n_nodes(1), m.n_cells(1)), (len(xy), 1))
                m.set_material(1, 1.0, 0.3)
                m.fix(1, left, mc.MC_X)
                m.fix(1, bottom, mc.MC_Y)
                m.add_pressure(1, [top], 0.1)
                m.solve()
                s, sn = m.get_stress(1), m.get_nodal_stress(1)
                self.assertEqual(s.shape, (1, 4))
                self.assertEqual(sn.shape, (len(xy), 4))
                np.testing.assert_allclose(s[0, :3], [sxx, syy, 0.0], rtol=0, atol=1e-12)
                np.testing.assert_allclose(sn, np.tile(s, (len(xy), 1)), rtol=0, atol=1e-12)

    def test_error_estimate(self):
        """MC_INFO_ERROR_ESTIMATE and get_error_indicator: a 3x3 Q1 block clamped at the bottom
        and sheared on its top has a non-uniform stress, so an estimate in (0, 1), whose square
        the cells' indicators' squares add up to; MC_OPTION_ERROR_ESTIMATE = 0 turns it off."""
        n = 3
        xy = np.array([[i / n, j / n] for j in range(n + 1) for i in range(n + 1)])
        cells = np.array([[a, a + 1, a + n + 2, a + n + 1] for a in (j * (n + 1) + i for j in range(n) for i in range(n))])
        top = np.array([[n * (n + 1) + i, n * (n + 1) + i - 1] for i in range(n, 0, -1)])
        with mc.Model() as m:
            m.set_mesh(1, xy, cells)
            m.set_material(1, 1.0, 0.3)
            m.fix(1, np.arange(n + 1), mc.MC_XY)
            m.add_traction(1, top, (0.1, 0.1))
            m.solve()
            estimate = m.get_info(mc.MC_INFO_ERROR_ESTIMATE)
            self.assertGreater(estimate, 0.0)
            self.assertLess(estimate, 1.0)
            eta = m.get_error_indicator(1)
            self.assertEqual(eta.shape, (n * n,))
            self.assertEqual(eta.dtype, np.float64)
            self.assertTrue(np.all(eta >= 0))
            self.assertAlmostEqual(np.sum(eta ** 2), estimate ** 2, delta=1e-12 * estimate ** 2)
            with self.assertRaises(mc.MortarContactError) as cm:
                m.get_error_indicator(2)  # no mesh
            self.assertEqual(cm.exception.status, mc.MC_ERROR_STATE)
            m.set_option(mc.MC_OPTION_ERROR_ESTIMATE, 0)
            m.solve()
            self.assertEqual(m.get_info(mc.MC_INFO_ERROR_ESTIMATE), 0.0)
            with self.assertRaises(mc.MortarContactError) as cm:
                m.get_error_indicator(1)
            self.assertEqual(cm.exception.status, mc.MC_ERROR_STATE)
            self.assertIn("MC_OPTION_ERROR_ESTIMATE", cm.exception.message)
            m.set_option(mc.MC_OPTION_ERROR_ESTIMATE, 1)
            m.solve()
            self.assertEqual(m.get_info(mc.MC_INFO_ERROR_ESTIMATE), estimate)
            np.testing.assert_array_equal(m.get_error_indicator(1), eta)

    @staticmethod
    def pulled_square(m):
        """The unit square of test_single_body_solve_one_based, 0-based ids."""
        m.set_mesh(1, SQUARE_XY, SQUARE_TRI)
        m.set_material(1, 1.0, 0.3)
        m.fix(1, [0, 1], mc.MC_XY)
        m.add_traction(1, [[2, 3]], (0.0, 1e-3))

    def test_log_callback(self):
        """Phase messages reach a Python callable; no iterations without contact; None removes it;
        an exception in the callable is re-raised by solve() and the model stays usable."""
        with mc.Model() as m:
            self.pulled_square(m)
            messages = []
            m.set_log_callback(lambda level, text: messages.append((level, text)))
            gc.collect()  # the binding keeps the C thunk alive, not the caller
            m.solve()
            levels = {level for level, _ in messages}
            self.assertEqual(levels, {mc.MC_LOG_PHASE})
            text = "\n".join(t for _, t in messages)
            for phase in ("assembly: body 1", "analysis: body 1", "factorization: body 1", "recovery:", "solve: done"):
                self.assertIn(phase, text)
            self.assertTrue(all(isinstance(t, str) and "\n" not in t for _, t in messages))
            count = len(messages)
            m.set_log_callback(None)
            m.solve()
            self.assertEqual(len(messages), count)

            def broken(level, text):
                raise RuntimeError("log failed")
            m.set_log_callback(broken)
            with self.assertRaises(RuntimeError):
                m.solve()
            m.set_log_callback(None)
            m.solve()  # usable, and the solve itself had succeeded
            self.assertGreater(m.get_info(mc.MC_INFO_STRAIN_ENERGY), 0.0)
            with self.assertRaises(mc.ArgumentError):
                m.set_log_callback(42)

    def test_write_vtu(self):
        with mc.Model() as m, tempfile.TemporaryDirectory() as tmp:
            self.pulled_square(m)
            path = os.path.join(tmp, "square.vtu")
            with self.assertRaises(mc.MortarContactError) as cm:
                m.write_vtu(path)  # before a solve
            self.assertEqual(cm.exception.status, mc.MC_ERROR_STATE)
            m.solve()
            m.write_vtu(path)
            with open(path) as f:
                text = f.read()
            self.assertIn('NumberOfPoints="4" NumberOfCells="2"', text)
            with self.assertRaises(mc.MortarContactError) as cm:
                m.write_vtu(os.path.join(tmp, "missing", "square.vtu"))
            self.assertEqual(cm.exception.status, mc.MC_ERROR_ARGUMENT)
            self.assertIn("missing", cm.exception.message)


if __name__ == "__main__":
    unittest.main()
