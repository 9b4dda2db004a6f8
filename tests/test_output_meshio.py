"""mc_write_vtu read back by an independent reader (meshio): the files written for a solved
contact scene hold the mesh and exactly the values the result getters return.

The scene is driven through the Python binding (bindings/python; ctest sets PYTHONPATH and
MORTARCONTACT_LIBRARY): body 1 (P1 triangles) wider than body 2 (Q1 quadrilaterals), so the
file mixes cell types and body 1 has contact nodes that see no mortar surface (written as
gap = initial_gap = -1, contact = 0, as the header documents).

TestWriteVtuQuadratic: second-order cells (T6, Q8, Q9) of two clamped blocks under load, no
contact: meshio must read them as "triangle6", "quad8" and "quad9" (VTK types 22, 23, 28) with
the connectivity given to mc_set_mesh, and its reading of the node order must be the
library's: each mid-edge node lies midway along the side meshio's order gives it, a Q9's
centre at its centre.
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


# meshio's names of the cell types mc_write_vtu writes, by nodes per cell
MESHIO_TYPE = {3: "triangle", 4: "quad", 6: "triangle6", 8: "quad8", 9: "quad9"}


def quadratic_grid(x0, x1, y0, y1, nx, ny, kind):
    """An nx-by-ny block of second-order cells ("T6": two per square, "Q8", "Q9") on the
    (2nx+1)-by-(2ny+1) lattice, sheared (x += 0.2 y) so that no side is axis-parallel, in the
    library's node order. Returns (xy, cells, bottom nodes, top edges as corner pairs); Q8
    drops the unused square centres and renumbers."""
    xy, node = grid(x0, x1, y0, y1, 2 * nx, 2 * ny)
    xy[:, 0] += 0.2 * xy[:, 1]
    i, j = np.meshgrid(2 * np.arange(nx), 2 * np.arange(ny), indexing="ij")
    i, j = i.ravel(), j.ravel()
    c0, c1, c2, c3 = node[i, j], node[i + 2, j], node[i + 2, j + 2], node[i, j + 2]
    m01, m12, m23, m30 = node[i + 1, j], node[i + 2, j + 1], node[i + 1, j + 2], node[i, j + 1]
    centre = node[i + 1, j + 1]
    if kind == "T6":
        cells = np.vstack([np.column_stack([c0, c1, c2, m01, m12, centre]),
                           np.column_stack([c0, c2, c3, centre, m23, m30])])
    elif kind == "Q9":
        cells = np.column_stack([c0, c1, c2, c3, m01, m12, m23, m30, centre])
    else:
        cells = np.column_stack([c0, c1, c2, c3, m01, m12, m23, m30])
    used = np.zeros(len(xy), dtype=bool)
    used[cells.ravel()] = True
    new_id = np.cumsum(used) - 1
    top = node[::2, -1]
    return xy[used], new_id[cells], new_id[node[:, 0]], new_id[np.column_stack([top[1:], top[:-1]])]


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
        cls.nodal_stress = [m.get_nodal_stress(1), m.get_nodal_stress(2)]
        cls.nodes = m.get_contact_nodes()
        cls.pressure = m.get_contact_pressure()
        cls.force = m.get_contact_force()
        cls.gap = m.get_contact_gap()
        cls.gap0 = m.get_contact_initial_gap()
        cls.friction = {name: m.get_pair_contact(1, field) for name, field in (
            ("shear", mc.MC_CONTACT_SHEAR), ("slip", mc.MC_CONTACT_SLIP), ("slip_total", mc.MC_CONTACT_SLIP_TOTAL),
            ("state", mc.MC_CONTACT_STATE))}

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
        for name, values in self.friction.items():  # frictionless: no shear, contact slips or is open
            f[name] = np.zeros(n)
            f[name][self.nodes] = values
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
            for name in ("pressure", "gap", "initial_gap", "active", "contact", "shear", "slip", "slip_total", "state"):
                np.testing.assert_array_equal(point_data[name][p], 0.0, err_msg=name)
        kind = MESHIO_TYPE[conn.shape[1]]
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
        np.testing.assert_array_equal(point_data["nodal_stress"][p], self.nodal_stress[b])

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


class TestWriteVtuQuadratic(unittest.TestCase):
    """Second-order cells: two scenes, (T6 body 1, Q8 body 2) and (Q9 body 1, P1 body 2), each
    body clamped at its bottom and loaded on top and by its weight, without contact."""

    SCENES = {"t6_q8": ("T6", "Q8"), "q9_p1": ("Q9", "P1")}

    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory(prefix="mc_output_quadratic_")
        cls.results = {}
        for name, kinds in cls.SCENES.items():
            with mc.Model() as m:
                meshes = []
                for b, kind in ((1, kinds[0]), (2, kinds[1])):
                    y0 = 0.0 if b == 1 else -0.5
                    if kind == "P1":
                        xy, node = grid(0.0, 1.0, y0, y0 + 0.5, 4, 2)
                        cells, bottom = triangles(node), node[:, 0]
                        top = np.column_stack([node[1:, -1], node[:-1, -1]])
                    else:
                        xy, cells, bottom, top = quadratic_grid(0.0, 1.0, y0, y0 + 0.5, 3, 2, kind)
                    m.set_mesh(b, xy, cells)
                    m.set_material(b, 1.0 + b, 0.3)
                    m.fix(b, bottom, mc.MC_XY)
                    m.add_traction(b, top, np.tile([0.05 * b, -0.1], (len(top), 1)))
                    m.set_body_force(b, 0.0, -0.2)
                    meshes.append((xy, cells))
                m.solve()
                u = [m.get_displacement(1), m.get_displacement(2)]
                stress = [m.get_stress(1), m.get_stress(2)]
                nodal = [m.get_nodal_stress(1), m.get_nodal_stress(2)]
                vtu, pvd = os.path.join(cls.tmp.name, name + ".vtu"), os.path.join(cls.tmp.name, name + ".pvd")
                m.write_vtu(vtu)
                m.write_vtu(pvd)
            cls.results[name] = (meshes, u, stress, nodal, vtu, pvd)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def check_node_order(self, points, kind, cells):
        """meshio's order: corners, then the middles of sides 0-1, 1-2, ..., then a quad9's centre."""
        corners = 3 if kind.startswith("triangle") else 4
        p = points[:, :2]
        for k in range(corners if cells.shape[1] > corners else 0):
            middle = 0.5 * (p[cells[:, k]] + p[cells[:, (k + 1) % corners]])
            np.testing.assert_allclose(p[cells[:, corners + k]], middle, rtol=0, atol=1e-15,
                                       err_msg="%s: node %d is not the middle of side %d" % (kind, corners + k, k))
        if kind == "quad9":
            np.testing.assert_allclose(p[cells[:, 8]], p[cells[:, :4]].mean(axis=1), rtol=0, atol=1e-15)
        # corners counter-clockwise
        x, y = p[cells[:, :corners], 0], p[cells[:, :corners], 1]
        area = 0.5 * np.sum(x * np.roll(y, -1, axis=1) - np.roll(x, -1, axis=1) * y, axis=1)
        self.assertTrue(np.all(area > 0), kind + ": a clockwise cell")

    def check_body(self, name, mesh, b, first_point):
        meshes, u, stress, nodal = self.results[name][:4]
        xy, conn = meshes[b]
        p = slice(first_point, first_point + len(xy))
        kind = MESHIO_TYPE[conn.shape[1]]
        block = [i for i, c in enumerate(mesh.cells) if c.type == kind]
        self.assertEqual(len(block), 1, "%s: one %s block" % (name, kind))
        k = block[0]
        np.testing.assert_array_equal(mesh.cells[k].data, conn + first_point)
        self.check_node_order(mesh.points, kind, mesh.cells[k].data)
        np.testing.assert_array_equal(mesh.points[p, :2], xy)
        # every node, the mid-edge and centre ones too, carries its own values, read back exactly
        np.testing.assert_array_equal(mesh.point_data["displacement"][p, :2], u[b])
        np.testing.assert_array_equal(mesh.point_data["nodal_stress"][p], nodal[b])
        np.testing.assert_array_equal(mesh.cell_data["stress"][k], stress[b])
        np.testing.assert_array_equal(mesh.cell_data["body"][k], b + 1)
        for field in ("pressure", "gap", "initial_gap", "active", "contact", "shear", "slip", "slip_total", "state"):
            np.testing.assert_array_equal(mesh.point_data[field][p], 0.0, err_msg=field)

    def test_scenes_are_loaded(self):
        """The bodies deform and their stress varies (a wrong node order could not hide)."""
        for name, (meshes, u, stress, nodal, _, _) in self.results.items():
            for b in range(2):
                self.assertGreater(np.abs(u[b]).max(), 1e-3, name)
                self.assertGreater(np.ptp(nodal[b][:, 1]), 1e-2, name)

    def test_vtu_cell_types_and_order(self):
        expected = {"t6_q8": ["triangle6", "quad8"], "q9_p1": ["quad9", "triangle"]}
        for name in self.SCENES:
            mesh = meshio.read(self.results[name][4])
            self.assertEqual([c.type for c in mesh.cells], expected[name])
            n1 = len(self.results[name][0][0][0])
            self.check_body(name, mesh, 0, 0)
            self.check_body(name, mesh, 1, n1)
        # the VTK type numbers themselves, as the header documents them
        with open(self.results["t6_q8"][4]) as f:
            text = f.read()
        types = text.split('Name="types" format="ascii">')[1].split("</DataArray>")[0].split()
        self.assertEqual(sorted(set(types)), ["22", "23"])
        with open(self.results["q9_p1"][4]) as f:
            text = f.read()
        types = text.split('Name="types" format="ascii">')[1].split("</DataArray>")[0].split()
        self.assertEqual(sorted(set(types)), ["28", "5"])

    def test_pvd_one_body_per_file(self):
        for name in self.SCENES:
            stem = self.results[name][5][:-4]
            for b in range(2):
                mesh = meshio.read("%s_body%d.vtu" % (stem, b + 1))
                self.assertEqual(len(mesh.cells), 1)
                self.check_body(name, mesh, b, 0)


if __name__ == "__main__":
    unittest.main()
