#!/usr/bin/env python3
"""The C test programs of a build (ctest label `memcheck`), for the sanitizer and valgrind steps
of `tools/bootstrap.sh test`.

  memcheck_tests.py targets BUILD_DIR
      prints the CMake targets that build those programs (one per line), so that a lean
      sanitizer build compiles only them. Works right after configuring. Convention: a memcheck
      test has the name of the executable target it runs (as mc_add_check_test does).
  memcheck_tests.py run BUILD_DIR [--exclude NAME[,NAME...]] -- WRAPPER...
      runs each test's command (its arguments and working directory as ctest has them) under
      WRAPPER (e.g. valgrind --error-exitcode=1 ...), one after the other, prints its time and
      a summary, and exits 1 if any failed. --exclude leaves tests out by name; they are listed
      in the summary as excluded, never silently.

The test list comes from `ctest --show-only=json-v1 -L memcheck`; Check programs get the label
from mc_add_check_test (tests/CMakeLists.txt), other C programs from input_tests.cmake.
"""
import json
import os
import subprocess
import sys
import time


def memcheck_tests(build):
    out = subprocess.run(["ctest", "--test-dir", build, "--show-only=json-v1", "-L", "memcheck"],
                         check=True, capture_output=True, text=True).stdout
    tests = []
    for t in json.loads(out)["tests"]:
        cwd = None
        for p in t.get("properties", []):
            if p["name"] == "WORKING_DIRECTORY":
                cwd = p["value"]
        tests.append({"name": t["name"], "command": t.get("command"), "cwd": cwd or build})
    return tests


def main(argv):
    if len(argv) < 3 or argv[1] not in ("targets", "run"):
        print(__doc__, file=sys.stderr)
        return 2
    mode, build = argv[1], argv[2]
    tests = memcheck_tests(build)
    if not tests:
        print(f"no tests labelled memcheck in {build}", file=sys.stderr)
        return 1
    if mode == "targets":
        for name in sorted(t["name"] for t in tests):
            print(name)
        return 0
    rest = argv[3:]
    excluded = set()
    if rest[:1] == ["--exclude"]:
        excluded = {n for n in rest[1].split(",") if n}
        rest = rest[2:]
    if rest[:1] != ["--"] or len(rest) < 2:
        print("usage: memcheck_tests.py run BUILD_DIR [--exclude A,B] -- WRAPPER...", file=sys.stderr)
        return 2
    wrapper = rest[1:]
    unknown = excluded - {t["name"] for t in tests}
    if unknown:  # a stale name (renamed test): say so, the other exclusions still apply
        print(f"warning: --exclude names no memcheck test: {', '.join(sorted(unknown))}", flush=True)
    failed, results = [], []
    for t in tests:
        if t["name"] in excluded:
            results.append((t["name"], "excluded", 0.0))
            continue
        if not t["command"]:
            print(f"=== {t['name']}: not built", flush=True)
            failed.append(t["name"])
            results.append((t["name"], "NOT BUILT", 0.0))
            continue
        print(f"=== {t['name']}: {' '.join(wrapper + t['command'])}", flush=True)
        start = time.monotonic()
        rc = subprocess.run(wrapper + t["command"], cwd=t["cwd"]).returncode
        elapsed = time.monotonic() - start
        status = "passed" if rc == 0 else f"FAILED (exit {rc})"
        if rc != 0:
            failed.append(t["name"])
        results.append((t["name"], status, elapsed))
        print(f"=== {t['name']}: {status} in {elapsed:.1f} s", flush=True)
    print("\nsummary:")
    for name, status, elapsed in results:
        print(f"  {name:32s} {status:18s} {elapsed:8.1f} s")
    if failed:
        print(f"{len(failed)} of {len(tests)} failed: {', '.join(failed)}")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
