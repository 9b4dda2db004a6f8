"""Locating and loading libmortarcontact, and the ctypes prototypes of its C API.

Search order (the first hit wins):

1. the environment variable ``MORTARCONTACT_LIBRARY``: the full path of the shared library;
2. the library that ``cmake --install`` installed together with this package: its directory,
   relative to the package's, is recorded in the generated module ``_installed_library``;
3. the install prefix this package sits in (``<prefix>/lib/python3*/{site,dist}-packages/``,
   four levels below ``<prefix>``): its ``lib*/`` and ``lib/<multiarch>/``;
4. a build tree of the source checkout this package sits in: ``<repo>/build*/lib/``;
5. the virtual environment the interpreter runs in, if any (a package installed with pip into
   the prefix the library was installed into): its ``lib*/`` and ``lib/<multiarch>/``;
6. ``ctypes.util.find_library("mortarcontact")`` (the system's library path).
"""

import ctypes
import ctypes.util
import glob
import os
import sys

_SONAME = "libmortarcontact.so.0"
_NAMES = (_SONAME, "libmortarcontact.so")


def _in_prefix(prefix):
    """Candidate paths of the library under an install prefix: ``lib*/`` and ``lib/*/``."""
    for pattern in ("lib*", os.path.join("lib", "*")):
        for d in sorted(glob.glob(os.path.join(prefix, pattern))):
            for name in _NAMES:
                yield os.path.join(d, name)


def _recorded_by_install(here):
    """The library's path recorded by ``cmake --install`` next to this package, if any."""
    try:
        from . import _installed_library
    except ImportError:  # a source checkout or a pip install: nothing was recorded
        return
    for name in _NAMES:
        yield os.path.normpath(os.path.join(here, _installed_library.LIBRARY_DIR, name))


def _up(path, levels):
    """The directory `levels` levels above `path`."""
    return os.path.normpath(os.path.join(path, *([os.pardir] * levels)))


def _candidates():
    """Yields candidate paths of the shared library, in search order."""
    env = os.environ.get("MORTARCONTACT_LIBRARY")
    if env:
        yield env
        return  # an explicit choice is never silently replaced by another copy
    here = os.path.dirname(os.path.abspath(__file__))
    yield from _recorded_by_install(here)
    yield from _in_prefix(_up(here, 4))
    # <repo>/bindings/python/mortarcontact -> <repo>/build*/lib
    for d in sorted(glob.glob(os.path.join(_up(here, 3), "build*", "lib"))):
        for name in _NAMES:
            yield os.path.join(d, name)
    if sys.prefix != sys.base_prefix:  # a virtual environment (pip-installed package)
        yield from _in_prefix(sys.prefix)
    found = ctypes.util.find_library("mortarcontact")
    if found:
        yield found


def load():
    """Loads the library; returns ``(ctypes.CDLL, path)``. Raises OSError if none is found."""
    tried = []
    for path in _candidates():
        is_name = os.sep not in path  # find_library returns a bare soname
        if not is_name and not os.path.isfile(path):
            tried.append(path)
            continue
        try:
            lib = ctypes.CDLL(path)
        except OSError as exc:
            tried.append("%s (%s)" % (path, exc))
            continue
        _prototype(lib)
        return lib, path
    raise OSError("libmortarcontact not found; set MORTARCONTACT_LIBRARY to the full path of "
                  "libmortarcontact.so.0. Tried: " + (", ".join(tried) or "nothing"))


_p = ctypes.c_void_p
_i = ctypes.c_int
_d = ctypes.c_double
_i32 = ctypes.c_int32
_i64 = ctypes.c_int64
_pd = ctypes.POINTER(ctypes.c_double)
_pi32 = ctypes.POINTER(ctypes.c_int32)
_pi64 = ctypes.POINTER(ctypes.c_int64)
_s = ctypes.c_char_p

#: void (*mc_log_fn)(void *user_data, mc_log_level level, const char *message)
LOG_FN = ctypes.CFUNCTYPE(None, ctypes.c_void_p, ctypes.c_int, ctypes.c_char_p)

#: name -> (restype, argtypes); one line per function of mortarcontact.h, in header order.
PROTOTYPES = {
    "mc_create": (_i, [ctypes.POINTER(ctypes.c_void_p)]),
    "mc_destroy": (None, [_p]),
    "mc_errmsg": (_s, [_p]),
    "mc_status_string": (_s, [_i]),
    "mc_version_string": (_s, []),
    "mc_version_number": (_i, []),
    "mc_set_index_base": (_i, [_p, _i]),
    "mc_set_plane": (_i, [_p, _i, _d]),
    "mc_set_mesh": (_i, [_p, _i, _i32, _pd, _i32, _i, _pi32]),
    "mc_set_material": (_i, [_p, _i, _d, _d]),
    "mc_set_cell_elasticity": (_i, [_p, _i, _pd]),
    "mc_fix": (_i, [_p, _i, _i32, _pi32, _i, _pd]),
    "mc_add_traction": (_i, [_p, _i, _i32, _pi32, _pd]),
    "mc_add_pressure": (_i, [_p, _i, _i32, _pi32, _pd]),
    "mc_add_nodal_force": (_i, [_p, _i, _i32, _pi32, _pd]),
    "mc_set_body_force": (_i, [_p, _i, _d, _d]),
    "mc_clear_loads": (_i, [_p, _i]),
    "mc_set_contact": (_i, [_p, _i, _i32, _pi32]),
    "mc_set_gap_offset": (_i, [_p, _i32, _pi32, _pd]),
    "mc_set_body_count": (_i, [_p, _i]),
    "mc_add_contact_pair": (_i, [_p, _i, _i, ctypes.POINTER(ctypes.c_int)]),
    "mc_set_pair_surface": (_i, [_p, _i, _i, _i32, _pi32]),
    "mc_set_pair_surface_curved": (_i, [_p, _i, _i, _i32, _pi32]),
    "mc_set_pair_gap_offset": (_i, [_p, _i, _i32, _pi32, _pd]),
    "mc_get_pair_contact_count": (_i, [_p, _i, _pi32]),
    "mc_get_pair_contact_nodes": (_i, [_p, _i, _pi32]),
    "mc_get_pair_contact": (_i, [_p, _i, _i, _pd]),
    "mc_set_friction": (_i, [_p, _i, _i, _d]),
    "mc_reset_history": (_i, [_p]),
    "mc_set_host_body": (_i, [_p, _i, _i32, _pd, _pi32, _i32]),
    "mc_add_stiffness": (_i, [_p, _i, _i32, _pi32, _pi32, _pd, _i]),
    "mc_add_element_matrices": (_i, [_p, _i, _i32, _pi32, _pi32, _pd]),
    "mc_set_load_vector": (_i, [_p, _i, _i32, _pd]),
    "mc_get_equation_solution": (_i, [_p, _i, _pd]),
    "mc_get_contact_load": (_i, [_p, _i, _pd]),
    "mc_set_contact_curved": (_i, [_p, _i, _i32, _pi32]),
    "mc_set_option_int": (_i, [_p, _i, _i64]),
    "mc_set_option_real": (_i, [_p, _i, _d]),
    "mc_solve": (_i, [_p]),
    "mc_set_log_callback": (_i, [_p, LOG_FN, _p]),
    "mc_get_info_int": (_i, [_p, _i, _pi64]),
    "mc_get_info_real": (_i, [_p, _i, _pd]),
    "mc_get_displacement": (_i, [_p, _i, _pd]),
    "mc_get_stress": (_i, [_p, _i, _pd]),
    "mc_get_nodal_stress": (_i, [_p, _i, _pd]),
    "mc_get_error_indicator": (_i, [_p, _i, _pd]),
    "mc_get_reaction": (_i, [_p, _i, _pd]),
    "mc_get_contact_count": (_i, [_p, _pi32]),
    "mc_get_contact_nodes": (_i, [_p, _pi32]),
    "mc_get_contact_pressure": (_i, [_p, _pd]),
    "mc_get_contact_force": (_i, [_p, _pd]),
    "mc_get_contact_gap": (_i, [_p, _pd]),
    "mc_get_contact_initial_gap": (_i, [_p, _pd]),
    "mc_get_contact_normal": (_i, [_p, _pd]),
    "mc_write_vtu": (_i, [_p, _s]),
}


def _prototype(lib):
    """Sets restype/argtypes of every C function on ``lib``."""
    for name, (restype, argtypes) in PROTOTYPES.items():
        fn = getattr(lib, name)  # AttributeError here means a library older than this package
        fn.restype = restype
        fn.argtypes = argtypes
