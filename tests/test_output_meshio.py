"""mc_write_vtu read back by an independent reader (meshio): the files written for a solved
contact scene hold the mesh and exactly the values the result getters return.

The scene is driven through the Python binding (bindings/python; ctest sets PYTHONPATH and
MORTARCONTACT_LIBRARY): body 1 (P1 triangles) wider than body 2 (Q1 quadrilaterals), so the
file mixes cell types and body 1 has contact nodes that see no mortar surface (written as
gap = initial_gap = -1, contact = 0, as the header documents).
"""
import os
import tempfile
import unittest
import xml.etree.ElementTree as ET

import meshio
import numpy as np

import mortarcontact as mc


def grid(x0, x1, y0, y1, nx, ny):
    """Nodes of an nx-by-ny grid, node (i, j) numbered i*(ny+1) + j, and that numbering."""
    X, Y = np.meshgrid(np.linspace(x0, x1, nx + 1), np.linspace(y0, y1, ny + 1), indexing="ij")
    return np.column_stack([X.ravel(), Y.ravel()]), np.arange((nx + 1) * (ny + 1)).reshape(nx + 1, ny + 1)


def quads(node):
    return np.column_stack([node[:-1, :-1].ravel(), node[1:, :-1].ravel(), node[1:, 1:].ravel(),
                            node[:-1, 1:].ravel()])


def triangles(node):
    q = quads(node)
    return np.vstack([q[:, [0, 1, 2]], q[:, [0, 2, 3]]])


def chain(nodes):
    return np.column_stack([nodes[:-1], nodes[1:]])


def build(m):
    """Body 1 = [-0.25, 1.25] x [0, 0.5] on body 2 = [0, 1] x [-0.5, 0], pushed down by a body
    force, with a parabolic clearance so that only the middle touches."""
    xy1, n1 = grid(-0.25, 1.25, 0.0, 0.5, 12, 4)
    xy2, n2 = grid(0.0, 1.0, -0.5, 0.0, 7, 3)
    m.set_mesh(1, xy1, triangles(n1))
    m.set_mesh(2, xy2, quads(n2))
    m.set_material(1, 1.0, 0.3)
    m.set_material(2, 2.0, 0.25)
    m.fix(1, n1[0, :], mc.MC_X)
    m.fix(2, n2[0, :], mc.MC_X)
    m.fix(2, n2[:, 0], mc.MC_Y)
    m.set_contact(1, chain(n1[:, 0]))
    m.set_contact(2, chain(n2[:, -1]))
    m.set_body_force(1, 0.0, -0.05)
    bottom = n1[:, 0]
    m.set_gap_offset(bottom, 1.0 * (xy1[bottom, 0] - 0.5) ** 2)
    return (xy1, triangles(n1)), (xy2, quads(n2))


class TestWriteVtu(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory(prefix="mc_output_")
        cls.m = mc.Model()
        cls.meshes = build(cls.m)
        cls.m.solve()
        m = cls.m
        cls.u = [m.get_displacement(1), m.get_displacement(2)]
        cls.stress = [m.get_stress(1), m.get_stress(2)]
        cls.nodes = m.get_contact_nodes()
        cls.pressure = m.get_contact_pressure()
        cls.force = m.get_contact_force()
        cls.gap = m.get_contact_gap()
        cls.gap0 = m.get_contact_initial_gap()

    @classmethod
    def tearDownClass(cls):
        cls.m.close()
        cls.tmp.cleanup()

    def path(self, name):
        return os.path.join(self.tmp.name, name)

    def expected_contact_fields(self):
        """Body 1's nodal contact fields as the header documents them."""
        n = len(self.meshes[0][0])
        f = {k: np.zeros(n) for k in ("pressure", "gap", "initial_gap", "active", "contact")}
        seen = np.isfinite(self.gap)
        f["pressure"][self.nodes] = self.pressure
        f["gap"][self.nodes] = np.where(seen, self.gap, -1.0)
        f["initial_gap"][self.nodes] = np.where(seen, self.gap0, -1.0)
        f["active"][self.nodes] = self.force > 0
        f["contact"][self.nodes] = seen
        return f

    def check_body(self, mesh, b, points, cells, point_data, cell_data):
        """Checks the part of a meshio mesh holding body b (0-based): points [p0, p1), cells in
        the given blocks and rows."""
        xy, conn = self.meshes[b]
        n = len(xy)
        p = slice(points, points + n)
        np.testing.assert_array_equal(mesh.points[p, :2], xy)
        np.testing.assert_array_equal(mesh.points[p, 2], 0.0)
        # exact: the file holds 17 significant digits
        np.testing.assert_array_equal(point_data["displacement"][p, :2], self.u[b])
        np.testing.assert_array_equal(point_data["displacement"][p, 2], 0.0)
        if b == 0:
            for name, values in self.expected_contact_fields().items():
                np.testing.assert_array_equal(point_data[name][p], values, err_msg=name)
        else:
            for name in ("pressure", "gap", "initial_gap", "active", "contact"):
                np.testing.assert_array_equal(point_data[name][p], 0.0, err_msg=name)
        kind = "triangle" if conn.shape[1] == 3 else "quad"
        block = [i for i, c in enumerate(mesh.cells) if c.type == kind]
        self.assertEqual(len(block), 1, "one %s block" % kind)
        k = block[0]
        np.testing.assert_array_equal(mesh.cells[k].data, conn + points)
        np.testing.assert_array_equal(cell_data["stress"][k], self.stress[b])
        s = self.stress[b]
        vm = np.sqrt(0.5 * ((s[:, 0] - s[:, 1]) ** 2 + (s[:, 1] - s[:, 3]) ** 2 + (s[:, 3] - s[:, 0]) ** 2)
                     + 3 * s[:, 2] ** 2)
        np.testing.assert_allclose(cell_data["von_mises"][k], vm, rtol=1e-14, atol=0)
        np.testing.assert_array_equal(cell_data["body"][k], b + 1)

    def test_scene_exercises_every_case(self):
        seen = np.isfinite(self.gap)
        self.assertGreaterEqual(np.sum(~seen), 2)   # nodes that see no mortar surface
        self.assertGreaterEqual(np.sum(self.force > 0), 2)
        self.assertGreaterEqual(np.sum(seen & (self.force == 0)), 2)

    def test_vtu_both_bodies(self):
        path = self.path("scene.vtu")
        self.m.write_vtu(path)
        mesh = meshio.read(path)
        n1, n2 = len(self.meshes[0][0]), len(self.meshes[1][0])
        self.assertEqual(len(mesh.points), n1 + n2)
        self.assertEqual(sum(len(c.data) for c in mesh.cells), len(self.meshes[0][1]) + len(self.meshes[1][1]))
        self.assertEqual([c.type for c in mesh.cells], ["triangle", "quad"])
        self.check_body(mesh, 0, 0, None, mesh.point_data, mesh.cell_data)
        self.check_body(mesh, 1, n1, None, mesh.point_data, mesh.cell_data)
        for name, values in mesh.point_data.items():
            self.assertTrue(np.all(np.isfinite(values)), name)

    def test_pvd_collection(self):
        path = self.path("scene.pvd")
        self.m.write_vtu(path)
        root = ET.parse(path).getroot()
        self.assertEqual(root.get("type"), "Collection")
        files = [d.get("file") for d in root.iter("DataSet")]
        self.assertEqual(files, ["scene_body1.vtu", "scene_body2.vtu"])
        for b, name in enumerate(files):
            mesh = meshio.read(self.path(name))
            self.assertEqual(len(mesh.points), len(self.meshes[b][0]))
            self.assertEqual(len(mesh.cells), 1)
            self.check_body(mesh, b, 0, None, mesh.point_data, mesh.cell_data)

    def test_errors(self):
        with self.assertRaises(mc.MortarContactError) as cm:
            self.m.write_vtu(self.path("no-such-dir/scene.vtu"))
        self.assertEqual(cm.exception.status, mc.MC_ERROR_ARGUMENT)
        self.assertIn("no-such-dir/scene.vtu", cm.exception.message)
        with mc.Model() as fresh:
            build(fresh)
            with self.assertRaises(mc.MortarContactError) as cm:
                fresh.write_vtu(self.path("unsolved.vtu"))
            self.assertEqual(cm.exception.status, mc.MC_ERROR_STATE)
            self.assertFalse(os.path.exists(self.path("unsolved.vtu")))


if __name__ == "__main__":
    unittest.main()
