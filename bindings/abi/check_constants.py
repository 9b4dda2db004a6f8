#!/usr/bin/env python3
"""ABI guard (c): the header's constants against the committed baseline abi/constants.txt.

The options, infos, methods and other values are anonymous enums that never appear in a
function's type, so abidiff cannot see them; they are frozen all the same (docs/abi.md).
Every constant of the baseline must still exist with the same value; new ones may be added.
MC_VERSION_* are exempt (they change with every release).

usage: check_constants.py HEADER BASELINE            check
       check_constants.py HEADER BASELINE --write    (re)write the baseline (at a release only)
"""
import re
import sys


def constants(header):
    text = re.sub(r"/\*.*?\*/", " ", open(header).read(), flags=re.S)
    return {k: int(v) for k, v in re.findall(r"\b(MC_[A-Z0-9_]+)\s*=\s*(-?\d+)", text)}


def main():
    header, baseline = sys.argv[1], sys.argv[2]
    now = constants(header)
    if len(sys.argv) > 3 and sys.argv[3] == "--write":
        with open(baseline, "w") as f:
            f.write("# Constants of mortarcontact.h frozen by the ABI (bindings/abi/check_constants.py)\n")
            for k in sorted(now, key=lambda k: (k.rsplit("_", 1)[0], now[k], k)):
                f.write("%s %d\n" % (k, now[k]))
        print("wrote %d constants to %s" % (len(now), baseline))
        return 0
    base = {}
    for line in open(baseline):
        if line.strip() and not line.startswith("#"):
            k, v = line.split()
            base[k] = int(v)
    bad = ["%s: was %d, now %s" % (k, v, now.get(k, "removed")) for k, v in sorted(base.items()) if now.get(k) != v]
    added = sorted(set(now) - set(base))
    if bad:
        print("frozen constants of %s changed:" % header)
        for b in bad:
            print("  " + b)
        return 1
    print("%d frozen constants unchanged%s" % (len(base), "; added: " + ", ".join(added) if added else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main())
