#!/usr/bin/env python3
"""Checks that lib/'s layers include only downward (the ctest lib_layers).

lib/ holds one folder per layer, top to bottom (docs/architecture.md):
    capi     the C layer: argument checks, the index base, messages; no exception crosses it
    results  what a solved model reports (VTU output, the error estimate)
    solve    the scene (Model) and the solve's strategy (the two interface paths)
    contact  contact geometry and the mortar operators     } side by side: neither includes
    linalg   CHOLMOD, the active-set QP, the coupled solve } the other
    bodies   one body: cells, integrals, stiffness, rigid modes, stresses
    support  what every layer uses (errors, logs, timing, LAPACK, BLAS threads)
A file may include its own folder and any folder below its own; nothing may sit in lib/ itself
but the CMake list and the symbol map.

Usage: check_layers.py LIBDIR
"""
import os
import re
import sys

LAYERS = [["capi"], ["results"], ["solve"], ["contact", "linalg"], ["bodies"], ["support"]]
LEVEL = {folder: level for level, folders in enumerate(LAYERS) for folder in folders}


def main(libdir):
    problems = []
    count = 0
    for name in sorted(os.listdir(libdir)):
        path = os.path.join(libdir, name)
        if os.path.isfile(path) and name.endswith((".cpp", ".hpp", ".h")):
            problems.append("lib/%s: a source file outside the layers' folders" % name)
        elif os.path.isdir(path) and name not in LEVEL:
            problems.append("lib/%s/: not a layer (%s)" % (name, ", ".join(LEVEL)))
    for folder in sorted(LEVEL):
        directory = os.path.join(libdir, folder)
        if not os.path.isdir(directory):
            continue
        for name in sorted(os.listdir(directory)):
            text = open(os.path.join(directory, name), encoding="utf-8").read()
            for target in re.findall(r'^#include "([^"]+)"', text, flags=re.M):
                count += 1
                if target == "mortarcontact.h":  # the public header: every layer may use its types
                    continue
                parts = target.split("/")
                if len(parts) != 2 or parts[0] not in LEVEL:
                    problems.append("lib/%s/%s includes \"%s\": name its layer (folder/file)" % (folder, name, target))
                    continue
                if not os.path.exists(os.path.join(libdir, target)):
                    problems.append("lib/%s/%s includes \"%s\", which does not exist" % (folder, name, target))
                elif LEVEL[parts[0]] < LEVEL[folder] or (LEVEL[parts[0]] == LEVEL[folder] and parts[0] != folder):
                    problems.append("lib/%s/%s includes \"%s\": %s is not below %s" % (folder, name, target, parts[0], folder))
    for p in problems:
        print(p)
    print("%d includes checked, %d problems" % (count, len(problems)))
    return 1 if problems else 0


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1]))
