#!/usr/bin/env python3
"""ABI guard (b): compares a build of the library against the committed baseline
abi/libmortarcontact.abi with libabigail's abidiff and fails on an incompatible change.

abidiff's exit status is a bit field: 1 error, 2 usage error, 4 ABI change, 8 incompatible ABI
change. Bits 1, 2 and 8 fail. Bit 4 alone means "changed, review needed": the report's summary
lines are then read, and the change passes only if it is purely additive - functions or
variables added, nothing removed or changed (harmless changes such as enumerators appended to
an enum are already filtered out by abidiff). See docs/abi.md.

usage: check_abi.py BASELINE LIBRARY PUBLIC_HEADERS_DIR [ABIDIFF]
"""
import re
import subprocess
import sys


def main():
    baseline, lib, headers = sys.argv[1:4]
    abidiff = sys.argv[4] if len(sys.argv) > 4 else "abidiff"
    cmd = [abidiff, "--no-show-locs", "--headers-dir2", headers, baseline, lib]
    proc = subprocess.run(cmd, capture_output=True, text=True)
    report = proc.stdout + proc.stderr
    rc = proc.returncode
    print("$ " + " ".join(cmd))
    print(report.rstrip() or "(no differences)")
    print("abidiff exit status %d" % rc)
    if rc & 3:
        print("FAIL: abidiff could not compare (error bits %d)" % (rc & 3))
        return 1
    if rc & 8:
        print("FAIL: incompatible ABI change (removed symbols or similar)")
        return 1
    if rc & 4:
        bad = []
        for m in re.finditer(r"(Functions|Variables) changes summary: (\d+) Removed, (\d+) Changed[^,]*, (\d+) Added", report):
            if int(m.group(2)) or int(m.group(3)):
                bad.append(m.group(0))
        for m in re.finditer(r"(Function|Variable) symbols changes summary: (\d+) Removed", report):
            if int(m.group(2)):
                bad.append(m.group(0))
        if not re.search(r"changes summary", report):
            bad.append("no summary found in the report: cannot tell whether the change is additive")
        if bad:
            print("FAIL: the ABI changed in a way that is not purely additive:")
            for b in bad:
                print("  " + b)
            return 1
        print("OK: additive ABI change only (compatible). Refresh the baseline at the next release.")
        return 0
    print("OK: no ABI change against %s" % baseline)
    return 0


if __name__ == "__main__":
    sys.exit(main())
