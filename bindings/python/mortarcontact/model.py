"""The :class:`Model` class: one contact scene, a thin wrapper of ``mc_model``."""

import ctypes
import os

import numpy as np

from . import _library
from .constants import (INT_INFOS, INT_OPTIONS, MC_CONTACT_NORMAL, MC_ERROR_ARGUMENT, MC_ERROR_STATE,
                        MC_MATRIX_FULL, MC_OK, MC_XY)

_lib = None
_lib_path = None


def _get_lib():
    """The loaded library (loaded on first use)."""
    global _lib, _lib_path
    if _lib is None:
        _lib, _lib_path = _library.load()
    return _lib


def library_path():
    """The path (or soname) the shared library was loaded from; loads it if needed."""
    _get_lib()
    return _lib_path


def status_string(status):
    """The library's English name of a status code, e.g. ``"MC_ERROR_MESH"``."""
    return _get_lib().mc_status_string(int(status)).decode()


def version_string():
    """The loaded library's version, ``"MAJOR.MINOR.PATCH"``."""
    return _get_lib().mc_version_string().decode()


def version_number():
    """The loaded library's version as ``MAJOR*10000 + MINOR*100 + PATCH``."""
    return int(_get_lib().mc_version_number())


class MortarContactError(Exception):
    """A failed call. ``status`` is the ``mc_status`` code (an ``MC_ERROR_*`` constant) and
    ``message`` the library's message (``mc_errmsg``) or the binding's own."""

    def __init__(self, status, message):
        self.status = int(status)
        self.message = message
        try:
            name = status_string(self.status)
        except OSError:
            name = "status %d" % self.status
        super().__init__("%s: %s" % (name, message))


class ArgumentError(MortarContactError, ValueError):
    """An argument the binding rejected before calling the library (wrong dtype, shape or
    body); ``status`` is ``MC_ERROR_ARGUMENT``. Also a ``ValueError``."""

    def __init__(self, message):
        super().__init__(MC_ERROR_ARGUMENT, message)


_PD = ctypes.POINTER(ctypes.c_double)
_PI32 = ctypes.POINTER(ctypes.c_int32)
_I32 = np.iinfo(np.int32)


def _reals(a, shape, name):
    """``a`` as a C-contiguous float64 array of ``shape`` (None = any length; a trailing
    dimension may be broadcast from a single row). Copies only when needed."""
    arr = np.asarray(a)
    if arr.dtype.kind not in "iuf":
        raise ArgumentError("%s must hold real numbers, got dtype %s" % (name, arr.dtype))
    if arr.ndim != len(shape) or any(w is not None and w != s for w, s in zip(shape, arr.shape)):
        raise ArgumentError("%s must have shape %s, got %s" % (name, _fmt(shape), arr.shape))
    return np.ascontiguousarray(arr, dtype=np.float64)


def _reals_rows(a, n, width, name):
    """``a`` as a C-contiguous float64 array of shape (n, width) (or (n,) if width is None);
    a single row (shape (width,) or a scalar) is repeated n times."""
    arr = np.asarray(a)
    row = () if width is None else (width,)
    if arr.dtype.kind in "iuf" and arr.shape == row:
        arr = np.broadcast_to(arr, (n,) + row)
    return _reals(arr, (n,) + row, name)


def _ids(a, shape, name):
    """``a`` as a C-contiguous int32 array of ``shape``; rejects non-integer dtypes and ids
    that do not fit in 32 bits."""
    arr = np.asarray(a)
    if arr.size == 0 and arr.dtype.kind == "f":
        arr = arr.astype(np.int32)  # np.asarray([]) is float64
    if arr.dtype.kind not in "iu":
        raise ArgumentError("%s must hold integer ids, got dtype %s" % (name, arr.dtype))
    if arr.size == 0 and None not in shape[1:]:
        arr = arr.reshape((0,) + tuple(shape[1:]))  # [] for "no edges"
    if arr.ndim != len(shape) or any(w is not None and w != s for w, s in zip(shape, arr.shape)):
        raise ArgumentError("%s must have shape %s, got %s" % (name, _fmt(shape), arr.shape))
    if arr.size and (arr.min() < _I32.min or arr.max() > _I32.max):
        raise ArgumentError("%s holds ids outside the 32-bit range" % name)
    return np.ascontiguousarray(arr, dtype=np.int32)


def _fmt(shape):
    """A shape for messages: (None, 2) -> "(n, 2)"."""
    return "(" + ", ".join("n" if s is None else str(s) for s in shape) + ("," if len(shape) == 1 else "") + ")"


def _dp(arr):
    """``double *`` to the data of a float64 array."""
    return arr.ctypes.data_as(_PD)


def _ip(arr):
    """``mc_int *`` to the data of an int32 array."""
    return arr.ctypes.data_as(_PI32)


class Model:
    """One contact scene (``mc_model``): 2D bodies numbered 1 (the non-mortar side) and 2, or
    1..N after :meth:`set_body_count`, in contact through pairs (:meth:`add_contact_pair`).

    Use it as a context manager, or call :meth:`close`; it is also freed when garbage
    collected. Every method raises :class:`MortarContactError` on failure; the model stays
    usable after a failed call. Arrays are numpy arrays, one row per node, cell or edge:
    coordinates ``(n, 2)``, cells ``(n_cells, 3, 4, 6, 8 or 9)``, edges ``(n_edges, 2)``; ids use the
    model's index base (0 unless ``index_base=1``).

    >>> with Model() as m:
    ...     m.set_mesh(1, xy, cells)
    """

    def __init__(self, index_base=0):
        """Creates an empty model; ``index_base`` (0 or 1) is the base of all ids in and out."""
        self._handle = None
        self._lib = _get_lib()
        handle = ctypes.c_void_p()
        status = self._lib.mc_create(ctypes.byref(handle))
        if status != MC_OK:
            raise MortarContactError(status, "mc_create failed")
        self._handle = handle
        self._log_callback = None
        self._log_error = None
        self._n_nodes = {}
        self._n_cells = {}      # 0 for a host body
        self._n_equations = {}  # host bodies only
        self._n_bodies = 2      # as set through set_body_count
        self._base = 0
        if index_base != 0:
            self.set_index_base(index_base)

    # ---- lifecycle -------------------------------------------------------------------

    def close(self):
        """Frees the model (``mc_destroy``). Further calls raise MC_ERROR_STATE. Idempotent."""
        if self._handle is not None:
            self._lib.mc_destroy(self._handle)
            self._handle = None

    @property
    def closed(self):
        """True after :meth:`close`."""
        return self._handle is None

    def __enter__(self):
        """Returns the model itself."""
        return self

    def __exit__(self, *exc):
        """Closes the model; exceptions propagate."""
        self.close()
        return False

    def __del__(self):
        """Frees the model if it was not closed."""
        try:
            self.close()
        except Exception:  # interpreter shutdown: never raise from __del__
            pass

    def _h(self):
        """The C handle; MC_ERROR_STATE if the model is closed."""
        if self._handle is None:
            raise MortarContactError(MC_ERROR_STATE, "the model is closed")
        return self._handle

    def _check(self, status):
        """Raises MortarContactError with the library's message unless status is MC_OK."""
        if status != MC_OK:
            raise MortarContactError(status, self._lib.mc_errmsg(self._handle).decode())

    @property
    def errmsg(self):
        """The library's message of the last call on this model (``""`` after a success)."""
        return self._lib.mc_errmsg(self._h()).decode()

    def _body(self, body, what):
        """Checks that body is 1..N (the body count) and has a mesh or is a host body (whose
        sizes size the outputs)."""
        if body not in range(1, self._n_bodies + 1):
            raise ArgumentError("body must be 1 to %d, got %r" % (self._n_bodies, body))
        if body not in self._n_nodes:
            raise MortarContactError(MC_ERROR_STATE, "%s: no mesh or host body set for body %d" % (what, body))

    # ---- the scene -----------------------------------------------------------------

    def set_index_base(self, base):
        """Sets the base (0 or 1) of all node, cell and edge ids, in and out."""
        self._check(self._lib.mc_set_index_base(self._h(), int(base)))
        self._base = int(base)

    def set_body_count(self, n):
        """The number of bodies, ``n >= 2`` (default 2; ``mc_set_body_count``). Growing keeps the
        bodies there are; shrinking drops the last ones (``MC_ERROR_STATE`` while a contact pair
        uses one of them)."""
        self._check(self._lib.mc_set_body_count(self._h(), int(n)))
        self._n_bodies = int(n)
        for sizes in (self._n_nodes, self._n_cells, self._n_equations):
            for body in [b for b in sizes if b > self._n_bodies]:
                del sizes[body]

    @property
    def body_count(self):
        """The number of bodies set through :meth:`set_body_count` (2 by default)."""
        return self._n_bodies

    def set_plane(self, plane, thickness=1.0):
        """``MC_PLANE_STRAIN`` (default), ``MC_PLANE_STRESS`` or ``MC_AXISYMMETRIC``, and the
        thickness (> 0; ignored by ``MC_AXISYMMETRIC``: x is the radius r >= 0, y the axis, every
        integral carries 2 pi r, forces are totals over the turn)."""
        self._check(self._lib.mc_set_plane(self._h(), int(plane), float(thickness)))

    def set_mesh(self, body, xy, cells):
        """Sets the mesh of ``body``: ``xy`` (n_nodes, 2) coordinates and ``cells``
        (n_cells, 3) P1 triangles, (n_cells, 4) Q1 quadrilaterals, (n_cells, 6) T6 triangles,
        (n_cells, 8) Q8 or (n_cells, 9) Q9 quadrilaterals: corners counter-clockwise, then the
        mid-edge nodes (and the Q9 centre), in Gmsh's and VTK's order (``mc_set_mesh``).
        Clears that body's materials, supports, loads and contact surface."""
        xy = _reals(xy, (None, 2), "xy")
        cells = _ids(cells, (None, None), "cells")
        n, nc = xy.shape[0], cells.shape[0]
        self._check(self._lib.mc_set_mesh(self._h(), int(body), n, _dp(xy), nc, cells.shape[1], _ip(cells)))
        self._n_nodes[body] = n
        self._n_cells[body] = nc
        self._n_equations.pop(body, None)

    def n_nodes(self, body):
        """Number of nodes of ``body``'s mesh, or that :meth:`set_host_body` gave."""
        self._body(body, "n_nodes")
        return self._n_nodes[body]

    def n_cells(self, body):
        """Number of cells of ``body``'s mesh (0 for a host body)."""
        self._body(body, "n_cells")
        return self._n_cells[body]

    def n_equations(self, body):
        """Length of ``body``'s equation vectors (:meth:`set_load_vector`,
        :meth:`get_equation_solution`, :meth:`get_contact_load`): a host body's ``n_equations``,
        2 per node for a mesh body."""
        self._body(body, "n_equations")
        return self._n_equations.get(body, 2 * self._n_nodes[body])

    def set_material(self, body, young, poisson):
        """Isotropic material of the whole body: Young's modulus > 0, Poisson's ratio in (-1, 1/2)."""
        self._check(self._lib.mc_set_material(self._h(), int(body), float(young), float(poisson)))

    def set_cell_elasticity(self, body, d):
        """Per-cell in-plane elasticity matrices (Voigt xx, yy, engineering xy): ``d`` of shape
        (n_cells, 3, 3) or (n_cells, 9), symmetric positive definite. Overrides set_material."""
        self._body(body, "set_cell_elasticity")
        nc = self._n_cells[body]
        arr = np.asarray(d)
        if arr.ndim == 3:
            arr = _reals(arr, (nc, 3, 3), "d")
        else:
            arr = _reals(arr, (nc, 9), "d")
        self._check(self._lib.mc_set_cell_elasticity(self._h(), int(body), _dp(arr)))

    def fix(self, body, nodes, components=MC_XY, values=None):
        """Prescribes displacements of ``nodes`` in the components of the mask ``components``
        (``MC_X``, ``MC_Y``, ``MC_XY``). ``values``: (n, 2) or one (2,) row for all nodes;
        None means zero."""
        nodes = _ids(nodes, (None,), "nodes")
        n = nodes.shape[0]
        vals = None if values is None else _reals_rows(values, n, 2, "values")
        self._check(self._lib.mc_fix(self._h(), int(body), n, _ip(nodes), int(components),
                                     None if vals is None else _dp(vals)))

    def add_traction(self, body, edges, traction):
        """Adds a uniform traction (force per unit length, global axes) on boundary ``edges``
        (n_edges, 2); ``traction`` is (n_edges, 2) or one (2,) row for all edges."""
        edges = _ids(edges, (None, 2), "edges")
        t = _reals_rows(traction, edges.shape[0], 2, "traction")
        self._check(self._lib.mc_add_traction(self._h(), int(body), edges.shape[0], _ip(edges), _dp(t)))

    def add_pressure(self, body, edges, pressure):
        """Adds a normal pressure (> 0 pushes into the body) on boundary ``edges`` (n_edges, 2);
        ``pressure`` is (n_edges,) or a scalar for all edges."""
        edges = _ids(edges, (None, 2), "edges")
        p = _reals_rows(pressure, edges.shape[0], None, "pressure")
        self._check(self._lib.mc_add_pressure(self._h(), int(body), edges.shape[0], _ip(edges), _dp(p)))

    def add_nodal_force(self, body, nodes, force):
        """Adds point forces: ``force`` (n, 2) or one (2,) row for all ``nodes``."""
        nodes = _ids(nodes, (None,), "nodes")
        f = _reals_rows(force, nodes.shape[0], 2, "force")
        self._check(self._lib.mc_add_nodal_force(self._h(), int(body), nodes.shape[0], _ip(nodes), _dp(f)))

    def set_body_force(self, body, fx, fy):
        """Sets (replaces) a uniform body force per unit area."""
        self._check(self._lib.mc_set_body_force(self._h(), int(body), float(fx), float(fy)))

    def clear_loads(self, body):
        """Removes every load of ``body`` (supports stay); the next solve reuses the factorization."""
        self._check(self._lib.mc_clear_loads(self._h(), int(body)))

    def set_contact(self, body, edges):
        """Candidate contact surface of ``body``: boundary ``edges`` (n_edges, 2). Body 1 is the
        non-mortar side, body 2 the mortar side; both need one for a contact solve. Acts on
        contact pair 1 (made as (1, 2) if the model has no pair yet)."""
        edges = _ids(edges, (None, 2), "edges")
        self._check(self._lib.mc_set_contact(self._h(), int(body), edges.shape[0], _ip(edges)))

    def set_gap_offset(self, nodes, offset):
        """Adds ``offset`` (a length; > 0 clearance, < 0 interference) to the initial gap of the
        body-1 contact ``nodes``: (n,) or a scalar for all nodes. Replaces earlier offsets.
        Acts on contact pair 1 (:meth:`set_pair_gap_offset` for any pair)."""
        nodes = _ids(nodes, (None,), "nodes")
        off = _reals_rows(offset, nodes.shape[0], None, "offset")
        self._check(self._lib.mc_set_gap_offset(self._h(), nodes.shape[0], _ip(nodes), _dp(off)))

    # ---- assemblies: contact pairs ----------------------------------------------------------

    def add_contact_pair(self, nonmortar_body, mortar_body):
        """Makes a contact pair between two different bodies and returns its number (1, 2, ... in
        the order made, whatever the index base; ``mc_add_contact_pair``). The non-mortar body
        carries the constraint, the mortar body is the surface it is measured against."""
        pair = ctypes.c_int(0)
        self._check(self._lib.mc_add_contact_pair(self._h(), int(nonmortar_body), int(mortar_body),
                                                  ctypes.byref(pair)))
        return pair.value

    def set_pair_surface(self, pair, body, edges):
        """One side of ``pair``: ``body`` (its non-mortar or its mortar body) and boundary
        ``edges`` (n_edges, 2), as :meth:`set_contact`. Replaces that side's earlier edges."""
        edges = _ids(edges, (None, 2), "edges")
        self._check(self._lib.mc_set_pair_surface(self._h(), int(pair), int(body), edges.shape[0], _ip(edges)))

    def set_pair_surface_curved(self, pair, body, edges):
        """One side of ``pair`` of quadratic ``edges`` (n_edges, 3): end, end, middle, as
        :meth:`set_contact_curved`. Replaces that side's earlier edges."""
        edges = _ids(edges, (None, 3), "edges")
        self._check(self._lib.mc_set_pair_surface_curved(self._h(), int(pair), int(body), edges.shape[0],
                                                         _ip(edges)))

    def set_pair_gap_offset(self, pair, nodes, offset):
        """Adds ``offset`` to the initial gap of ``pair``'s non-mortar ``nodes``: (n,) or a scalar
        for all nodes, as :meth:`set_gap_offset` does for pair 1. Replaces earlier offsets."""
        nodes = _ids(nodes, (None,), "nodes")
        off = _reals_rows(offset, nodes.shape[0], None, "offset")
        self._check(self._lib.mc_set_pair_gap_offset(self._h(), int(pair), nodes.shape[0], _ip(nodes), _dp(off)))

    # ---- friction ---------------------------------------------------------------------------

    def set_friction(self, pair, law, value=0.0):
        """The friction law of ``pair`` (1 for the two-body model's pair; ``mc_set_friction``):
        ``MC_FRICTION_COULOMB`` (``value``: mu >= 0), ``MC_FRICTION_TRESCA`` (``value``: the slip
        bound, a shear traction >= 0) or ``MC_FRICTION_NONE`` (the default). Each solve of a model
        with friction is a step from the last converged state (``MC_OPTION_LOAD_STEPS``
        increments); :meth:`reset_history` returns to the unloaded state."""
        self._check(self._lib.mc_set_friction(self._h(), int(pair), int(law), float(value)))

    def reset_history(self):
        """Forgets the converged state: the next solve starts from the unloaded state (u = 0,
        loads 0, accumulated slip 0)."""
        self._check(self._lib.mc_reset_history(self._h()))

    # ---- host bodies: a legacy program's own matrices ---------------------------------------

    def set_host_body(self, body, xy, equations, n_equations):
        """Makes ``body`` a host body (no cells; ``mc_set_host_body``): ``xy`` (n_nodes, 2) the
        coordinates of the nodes the contact surface and the rigid modes need, ``equations``
        (n_nodes, 2) the host's equation number of each node's x and y freedom, counted from the
        index base (a number below the base: no equation, a restrained or absent freedom), and
        ``n_equations`` the size of the host's system. Replaces what the body was."""
        xy = _reals(xy, (None, 2), "xy")
        eq = _ids(equations, (xy.shape[0], 2), "equations")
        n_eq = int(n_equations)
        self._check(self._lib.mc_set_host_body(self._h(), int(body), xy.shape[0], _dp(xy), _ip(eq), n_eq))
        self._n_nodes[body] = xy.shape[0]
        self._n_cells[body] = 0
        self._n_equations[body] = n_eq

    def add_stiffness(self, body, matrix_or_rows, cols=None, values=None, storage=MC_MATRIX_FULL):
        """Adds entries to a host body's stiffness (``mc_add_stiffness``; repeated calls add).

        Either a matrix: a SciPy sparse matrix or array of any format (converted with
        ``tocoo()``; row i is equation i counted from the index base) or a dense 2-D array (its
        non-zero entries); or coordinate arrays ``rows``, ``cols`` (equation numbers counted from
        the index base; below the base: skipped) and ``values``, of one length. Duplicates are
        summed. ``storage``: ``MC_MATRIX_FULL`` (both triangles, symmetric to round-off) or
        ``MC_MATRIX_TRIANGLE`` (one triangle, either, each off-diagonal pair once)."""
        if cols is None and values is None:
            matrix = matrix_or_rows
            if hasattr(matrix, "tocoo"):
                coo = matrix.tocoo()
                shape, r, c, v = coo.shape, coo.row, coo.col, coo.data
            else:
                dense = _reals(matrix, (None, None), "matrix")
                shape = dense.shape
                r, c = np.nonzero(dense)
                v = dense[r, c]
            if len(shape) != 2 or shape[0] != shape[1]:
                raise ArgumentError("the stiffness matrix must be square, got shape %s" % (shape,))
            if body in self._n_equations and shape[0] != self._n_equations[body]:
                raise ArgumentError("the stiffness matrix must have shape (%d, %d) (n_equations of body %d), "
                                    "got %s" % (self._n_equations[body], self._n_equations[body], body, shape))
            if shape[0] > _I32.max - self._base:
                raise ArgumentError("the stiffness matrix has more rows than 32-bit equation numbers count")
            rows = np.asarray(r, dtype=np.int64) + self._base
            cols = np.asarray(c, dtype=np.int64) + self._base
            values = v
        elif cols is None or values is None:
            raise ArgumentError("add_stiffness takes a matrix, or rows, cols and values")
        else:
            rows = matrix_or_rows
        rows = _ids(rows, (None,), "rows")
        n = rows.shape[0]
        cols = _ids(cols, (n,), "cols")
        vals = _reals(values, (n,), "values")
        self._check(self._lib.mc_add_stiffness(self._h(), int(body), n, _ip(rows), _ip(cols), _dp(vals),
                                               int(storage)))

    def add_element_matrices(self, body, eltptr=None, eltvar=None, a_elt=None):
        """Adds element matrices to a host body's stiffness (``mc_add_element_matrices``).

        MUMPS's elemental form: ``eltptr`` (n_elements + 1,) counted from the index base,
        ``eltvar`` the equations of element e at ``eltvar[eltptr[e] - base:eltptr[e + 1] - base]``
        (below the base: restrained, skipped), ``a_elt`` each element's square matrix column by
        column, one after the other (1-D). Or, elements of one size k, with ``eltptr`` None:
        ``eltvar`` (n_elements, k) and ``a_elt`` (n_elements, k, k), ``a_elt[e]`` the matrix of
        element e (Smith and Griffiths' ``g_g`` and ``storkm``, one row per element)."""
        if eltptr is None:
            var = _ids(eltvar, (None, None), "eltvar")
            n_elements, k = var.shape
            a = _reals(a_elt, (n_elements, k, k), "a_elt")
            ptr = np.ascontiguousarray(self._base + k * np.arange(n_elements + 1), dtype=np.int64)
            ptr = _ids(ptr, (n_elements + 1,), "eltptr")
            var = np.ascontiguousarray(var.reshape(-1))
            a = np.ascontiguousarray(a.transpose(0, 2, 1).reshape(-1))  # column by column
        else:
            ptr = _ids(eltptr, (None,), "eltptr")
            if ptr.shape[0] < 1:
                raise ArgumentError("eltptr needs n_elements + 1 entries, got none")
            if ptr[0] != self._base:
                raise ArgumentError("eltptr[0] = %d, expected the index base %d" % (ptr[0], self._base))
            sizes = np.diff(ptr.astype(np.int64))
            if np.any(sizes < 0):
                e = int(np.argmax(sizes < 0))
                raise ArgumentError("eltptr[%d] = %d is below eltptr[%d] = %d" % (e + 1, ptr[e + 1], e, ptr[e]))
            var = _ids(eltvar, (int(ptr[-1]) - self._base,), "eltvar")
            a = _reals(a_elt, (int(np.sum(sizes * sizes)),), "a_elt")
        self._check(self._lib.mc_add_element_matrices(self._h(), int(body), ptr.shape[0] - 1, _ip(ptr), _ip(var),
                                                      _dp(a)))

    def set_load_vector(self, body, f):
        """The load of a host body: ``f`` (n_equations,) in the host's equation order (replaces
        the previous one; :meth:`clear_loads` zeroes it)."""
        f = _reals(f, (None,), "f")
        self._check(self._lib.mc_set_load_vector(self._h(), int(body), f.shape[0], _dp(f)))

    def set_contact_curved(self, body, edges):
        """Candidate contact surface of quadratic edges ``edges`` (n_edges, 3): end, end, middle.
        A host body's edges run with the body on their left; a mesh body's must be boundary edges
        of cells with that middle node. Otherwise as :meth:`set_contact`."""
        edges = _ids(edges, (None, 3), "edges")
        self._check(self._lib.mc_set_contact_curved(self._h(), int(body), edges.shape[0], _ip(edges)))

    # ---- options and solving ---------------------------------------------------------

    def set_option_int(self, option, value):
        """Sets an integer option (``MC_OPTION_METHOD``, ``..._MAX_ITERATIONS``, ...)."""
        self._check(self._lib.mc_set_option_int(self._h(), int(option), int(value)))

    def set_option_real(self, option, value):
        """Sets a real option (``MC_OPTION_TOLERANCE``)."""
        self._check(self._lib.mc_set_option_real(self._h(), int(option), float(value)))

    def set_option(self, option, value):
        """Sets an option with the integer or real call, as the option's type requires."""
        if option in INT_OPTIONS:
            self.set_option_int(option, value)
        else:
            self.set_option_real(option, value)

    def solve(self):
        """Solves the scene (``mc_solve``)."""
        self._log_error = None
        status = self._lib.mc_solve(self._h())
        error, self._log_error = self._log_error, None
        self._check(status)
        if error is not None:
            raise error

    def set_log_callback(self, fn):
        """Installs ``fn(level, message)`` (level ``MC_LOG_PHASE`` or ``MC_LOG_ITERATION``,
        message a one-line str) to receive the progress of :meth:`solve`; ``None`` removes it.
        An exception raised by ``fn`` cannot cross the C library: the first one is kept, the
        callback is not called again during that solve, and :meth:`solve` re-raises it after
        the solve returns."""
        if fn is None:
            self._check(self._lib.mc_set_log_callback(self._h(), _library.LOG_FN(), None))
            self._log_callback = None
            return
        if not callable(fn):
            raise ArgumentError("the log callback must be callable or None, got %r" % (fn,))

        def relay(_user_data, level, message):
            if self._log_error is not None:
                return
            try:
                fn(int(level), message.decode(errors="replace"))
            except BaseException as exc:  # noqa: B902 - must not unwind into C
                self._log_error = exc

        c_fn = _library.LOG_FN(relay)
        self._check(self._lib.mc_set_log_callback(self._h(), c_fn, None))
        self._log_callback = c_fn  # the C library holds only a pointer: keep the thunk alive

    # ---- results ---------------------------------------------------------------------

    def get_info_int(self, info):
        """An integer info (``MC_INFO_DOFS``, ``MC_INFO_ITERATIONS``, ...) of the last solve."""
        v = ctypes.c_int64()
        self._check(self._lib.mc_get_info_int(self._h(), int(info), ctypes.byref(v)))
        return v.value

    def get_info_real(self, info):
        """A real info (``MC_INFO_TIME_*``, ``MC_INFO_STRAIN_ENERGY``, ...) of the last solve."""
        v = ctypes.c_double()
        self._check(self._lib.mc_get_info_real(self._h(), int(info), ctypes.byref(v)))
        return v.value

    def get_info(self, info):
        """An info with the integer or real call, as the info's type requires."""
        return self.get_info_int(info) if info in INT_INFOS else self.get_info_real(info)

    def _per_body(self, fn, body, per_node, width, what):
        """Calls a per-node or per-cell getter into a new (n, width) float64 array."""
        self._body(body, what)
        n = self._n_nodes[body] if per_node else self._n_cells[body]
        out = np.empty((n, width), dtype=np.float64)
        self._check(fn(self._h(), int(body), _dp(out)))
        return out

    def get_displacement(self, body):
        """Displacements of ``body``: (n_nodes, 2)."""
        return self._per_body(self._lib.mc_get_displacement, body, True, 2, "get_displacement")

    def get_stress(self, body):
        """Cell-averaged stresses of ``body``: (n_cells, 4) as xx, yy, xy, zz."""
        return self._per_body(self._lib.mc_get_stress, body, False, 4, "get_stress")

    def get_nodal_stress(self, body):
        """Stresses of ``body`` at its nodes: (n_nodes, 4) as xx, yy, xy, zz; each cell's stress
        evaluated at its nodes, averaged over the cells sharing a node."""
        return self._per_body(self._lib.mc_get_nodal_stress, body, True, 4, "get_nodal_stress")

    def get_error_indicator(self, body):
        """Error indicators of ``body``'s cells: (n_cells,), relative like
        ``MC_INFO_ERROR_ESTIMATE``, whose squares over both bodies add up to its square (refine
        where they are large). ``MC_ERROR_STATE`` before a solve, for a host body, or when
        ``MC_OPTION_ERROR_ESTIMATE`` is 0."""
        return self._per_body(self._lib.mc_get_error_indicator, body, False, 1, "get_error_indicator").reshape(-1)

    def get_reaction(self, body):
        """Support reactions of ``body``: (n_nodes, 2), zero at free components."""
        return self._per_body(self._lib.mc_get_reaction, body, True, 2, "get_reaction")

    def _equation_vector(self, fn, body, what):
        """Calls an equation-order getter into a new (n_equations(body),) float64 array."""
        self._body(body, what)
        out = np.empty(self.n_equations(body), dtype=np.float64)
        self._check(fn(self._h(), int(body), _dp(out)))
        return out

    def get_equation_solution(self, body):
        """The displacements in equation order: (n_equations,) for a host body (the host's
        numbering), (2 n_nodes,) x, y per node for a mesh body."""
        return self._equation_vector(self._lib.mc_get_equation_solution, body, "get_equation_solution")

    def get_contact_load(self, body):
        """The contact forces on ``body`` as a load vector in its equation order (sized as
        :meth:`get_equation_solution`): what a host adds to its residual or reaction output;
        K u = f + r on the free equations."""
        return self._equation_vector(self._lib.mc_get_contact_load, body, "get_contact_load")

    def get_contact_count(self):
        """Number of body-1 contact-surface nodes (the length of the contact arrays)."""
        n = ctypes.c_int32()
        self._check(self._lib.mc_get_contact_count(self._h(), ctypes.byref(n)))
        return n.value

    def _contact(self, fn, width):
        """Calls a contact getter into a new (m,) or (m, width) float64 array."""
        m = self.get_contact_count()
        out = np.empty((m,) if width == 1 else (m, width), dtype=np.float64)
        self._check(fn(self._h(), _dp(out)))
        return out

    def get_contact_nodes(self):
        """Ids of the body-1 contact nodes, in order along each chain: (m,) int32."""
        m = self.get_contact_count()
        out = np.empty(m, dtype=np.int32)
        self._check(self._lib.mc_get_contact_nodes(self._h(), _ip(out)))
        return out

    def get_contact_pressure(self):
        """Contact pressure (>= 0) at the contact nodes, lumped recovery: (m,)."""
        return self._contact(self._lib.mc_get_contact_pressure, 1)

    def get_contact_force(self):
        """Nodal multipliers lambda_j >= 0, total normal force at each contact node: (m,)."""
        return self._contact(self._lib.mc_get_contact_force, 1)

    def get_contact_gap(self):
        """Discrete gap after the solve (>= 0; +inf where no mortar surface is seen): (m,)."""
        return self._contact(self._lib.mc_get_contact_gap, 1)

    def get_contact_initial_gap(self):
        """Initial normal gap g0 (negative: interference; +inf where no mortar surface): (m,)."""
        return self._contact(self._lib.mc_get_contact_initial_gap, 1)

    def get_contact_normal(self):
        """Unit outward normals of body 1 at the contact nodes: (m, 2)."""
        return self._contact(self._lib.mc_get_contact_normal, 2)

    def get_pair_contact_count(self, pair):
        """After a solve: the number of ``pair``'s contact positions (its non-mortar surface's
        nodes, a corner once per face): the length of its contact arrays."""
        n = ctypes.c_int32()
        self._check(self._lib.mc_get_pair_contact_count(self._h(), int(pair), ctypes.byref(n)))
        return n.value

    def get_pair_contact_nodes(self, pair):
        """Ids of ``pair``'s contact positions on its non-mortar body (index base applies): (m,)
        int32."""
        m = self.get_pair_contact_count(pair)
        out = np.empty(m, dtype=np.int32)
        self._check(self._lib.mc_get_pair_contact_nodes(self._h(), int(pair), _ip(out)))
        return out

    def get_pair_contact(self, pair, field):
        """A field of ``pair``'s contact positions (``mc_get_pair_contact``): ``MC_CONTACT_PRESSURE``,
        ``MC_CONTACT_FORCE``, ``MC_CONTACT_GAP``, ``MC_CONTACT_INITIAL_GAP`` as (m,), as the
        ``get_contact_*`` getter of the same name; ``MC_CONTACT_NORMAL`` as (m, 2); friction:
        ``MC_CONTACT_SHEAR``, ``MC_CONTACT_SLIP``, ``MC_CONTACT_SLIP_TOTAL`` and
        ``MC_CONTACT_STATE`` (``MC_STATE_OPEN``, ``_STICK`` or ``_SLIP`` as floats) as (m,)."""
        m = self.get_pair_contact_count(pair)
        out = np.empty((m, 2) if field == MC_CONTACT_NORMAL else (m,), dtype=np.float64)
        self._check(self._lib.mc_get_pair_contact(self._h(), int(pair), int(field), _dp(out)))
        return out

    # ---- output --------------------------------------------------------------------------

    def write_vtu(self, path):
        """Writes the solved scene for ParaView: ``path`` ending in ``.pvd`` gives a collection
        plus ``<stem>_body1.vtu`` and ``<stem>_body2.vtu``; any other path one .vtu with both
        bodies. ``path`` is a str or os.PathLike (encoded with the file-system encoding)."""
        encoded = os.fsencode(path)
        if b"\0" in encoded:
            raise ArgumentError("path contains a NUL character")
        self._check(self._lib.mc_write_vtu(self._h(), encoded))
