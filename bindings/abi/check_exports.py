#!/usr/bin/env python3
"""ABI guard (a): the dynamic symbols a shared library defines are exactly the functions
declared MC_API in the header, all in the version node MORTARCONTACT_<major> (plus that node's
own marker symbol). Anything else exported - a C++ symbol, a helper, libstdc++ pulled in by
-static-libstdc++ - is an ABI leak; a missing function is a broken promise.

usage: check_exports.py HEADER LIBRARY [NM]
"""
import re
import subprocess
import sys


def header_text(header):
    """The header without its comments."""
    return re.sub(r"/\*.*?\*/", " ", open(header).read(), flags=re.S)


def declared_functions(header):
    """The names of the functions the header declares MC_API."""
    return set(re.findall(r"MC_API[^;(]*?\b(mc_\w+)\s*\(", header_text(header)))


def main():
    header, lib = sys.argv[1], sys.argv[2]
    nm = sys.argv[3] if len(sys.argv) > 3 else "nm"
    declared = declared_functions(header)
    major = re.search(r"#define MC_VERSION_MAJOR (\d+)", header_text(header)).group(1)
    node = "MORTARCONTACT_" + major
    out = subprocess.run([nm, "-D", "--defined-only", lib], check=True, capture_output=True, text=True).stdout
    exported, problems = set(), []
    for line in out.splitlines():
        fields = line.split()
        if len(fields) < 3:
            continue
        kind, sym = fields[1], fields[2]
        if kind == "A" and sym == node:
            continue  # the version node itself
        name, _, version = sym.partition("@")
        version = version.lstrip("@")
        if kind != "T":
            problems.append("%s: exported with type %s, not a function (T)" % (sym, kind))
        if version != node:
            problems.append("%s: version node %r, expected %s" % (sym, version or "(none)", node))
        exported.add(name)
    for name in sorted(exported - declared):
        problems.append("%s: exported but not declared in the header" % name)
    for name in sorted(declared - exported):
        problems.append("%s: declared in the header but not exported" % name)
    if len(declared) < 30:
        problems.append("parsed only %d functions from the header" % len(declared))
    if problems:
        print("exported symbols of %s do not match %s:" % (lib, header))
        for p in problems:
            print("  " + p)
        return 1
    print("%s exports exactly the %d functions of %s, all at %s" % (lib, len(declared), header, node))
    return 0


if __name__ == "__main__":
    sys.exit(main())
