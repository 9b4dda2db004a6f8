#!/usr/bin/env python3
"""The README's example in Python: a unit square pressed onto a clamped one, P1, plane strain.
Prints the contact pressure, 0.1 at both nodes (the contact patch test). Run by ctest
(example_readme_python) and, with the installed package, by the install_consumer test."""
import numpy as np

import mortarcontact as mc

xy1 = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], dtype=float)
xy2 = xy1 - [0, 1]
tri = np.array([[0, 1, 2], [0, 2, 3]])
with mc.Model() as m:
    m.set_mesh(1, xy1, tri)
    m.set_mesh(2, xy2, tri)
    m.set_material(1, 1.0, 0.3)
    m.set_material(2, 1.0, 0.3)
    m.fix(1, [0, 3], mc.MC_X)  # on rollers
    m.fix(2, [0, 3], mc.MC_X)
    m.fix(2, [0, 1], mc.MC_Y)
    m.add_pressure(1, [[2, 3]], 0.1)  # on the top edge
    m.set_contact(1, [[0, 1]])
    m.set_contact(2, [[2, 3]])
    m.solve()
    for j, p in enumerate(m.get_contact_pressure()):
        print("p[%d] = %g" % (j, p))
