"""Shared set-up of the Python tests: import path of the package and the repository paths."""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.normpath(os.path.join(HERE, os.pardir, os.pardir, os.pardir))
HEADER = os.path.join(REPO, "include", "mortarcontact.h")
EXAMPLES = os.path.join(REPO, "examples", "python")

# The package next to these tests, unless PYTHONPATH already points at another copy.
try:
    import mortarcontact  # noqa: F401
except ImportError:
    sys.path.insert(0, os.path.join(REPO, "bindings", "python"))
