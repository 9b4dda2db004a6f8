"""Python bindings (ctypes + numpy) of mortarcontact: 2D contact between linear-elastic bodies,
frictionless or with Tresca or Coulomb friction, by the mortar finite element method.

>>> import mortarcontact as mc
>>> with mc.Model() as m:
...     m.set_mesh(1, xy1, cells1); m.set_material(1, 1.0, 0.3)
...     ...
...     m.solve()
...     u = m.get_displacement(1)

The shared library is found through ``MORTARCONTACT_LIBRARY`` (full path), the path
``cmake --install`` recorded next to the package, the install prefix, a build tree next to the
sources, a virtual environment's prefix, then the system path: see ``_library``.
"""

from .constants import *  # noqa: F401,F403  (the MC_* constants of mortarcontact.h)
from .constants import MC_VERSION_STRING
from .model import (ArgumentError, Model, MortarContactError, library_path, status_string,
                    version_number, version_string)

#: Version of these bindings (equal to the header version they mirror).
__version__ = MC_VERSION_STRING
