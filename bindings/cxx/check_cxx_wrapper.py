#!/usr/bin/env python3
"""Every C function and constant of include/mortarcontact.h has its C++ wrapper in
include/mortarcontact.hpp. Both lists come from the header (parsed by bindings/abi/), so a
function or constant added to the header fails this test until the wrapper follows:

- every MC_API function mc_NAME is called (`::mc_NAME(`) by the wrapper, and the wrapper
  defines NAME( (a Model member or a free function), except mc_create and mc_destroy, which
  are Model's constructor and destructor;
- every MC_ constant (`MC_NAME = value` in the header) is named by the wrapper: an
  enumerator's value, `= MC_NAME`.

usage: check_cxx_wrapper.py HEADER CXX_HEADER
"""
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, "abi"))
from check_constants import constants  # noqa: E402
from check_exports import declared_functions  # noqa: E402

LIFECYCLE = {"mc_create": "Model's constructor", "mc_destroy": "Model's destructor"}


def code_of(path):
    """The C++ header without its comments."""
    text = re.sub(r"/\*.*?\*/", " ", open(path).read(), flags=re.S)
    return re.sub(r"//[^\n]*", " ", text)


def problems(header, cxx_header):
    code = code_of(cxx_header)
    found = []
    functions, consts = declared_functions(header), constants(header)
    if len(functions) < 30 or len(consts) < 40:
        found.append("parsed only %d functions and %d constants from %s" % (len(functions), len(consts), header))
    for c_name in sorted(functions):
        if not re.search(r"::%s\s*\(" % c_name, code):
            found.append("%s: never called by the wrapper" % c_name)
        wrapper = c_name[len("mc_"):]
        if c_name not in LIFECYCLE and not re.search(r"\b%s\s*\(" % wrapper, code):
            found.append("%s: no wrapper named %s" % (c_name, wrapper))
    for name in sorted(consts):
        if not re.search(r"=\s*%s\b" % name, code):
            found.append("%s: no enumerator or constant has its value" % name)
    return found


def main():
    header, cxx_header = sys.argv[1], sys.argv[2]
    found = problems(header, cxx_header)
    if found:
        print("%s does not wrap all of %s:" % (cxx_header, header))
        for p in found:
            print("  " + p)
        return 1
    print("%s wraps the %d functions and %d constants of %s" % (
        cxx_header, len(declared_functions(header)), len(constants(header)), header))
    return 0


if __name__ == "__main__":
    sys.exit(main())
