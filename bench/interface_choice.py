#!/usr/bin/python3
"""The automatic choice of the interface solver (MC_OPTION_INTERFACE_SOLVER), estimate against
measurement, on every benchmark scene (docs/benchmarks.md, "The automatic choice, estimate
against measurement"; issue 34).

For each scene and size it runs the scene's benchmark program three ways, the option not set
(auto) and each path forced (condensed, sparse), and collects
  - the automatic choice's estimate of both paths (its log line "interface solver: X
    (automatic: ...; condensed estimated F flops ..., sparse ...)"), in Gflop;
  - each path's measured wall time (the median of the program's repeats) and, from the sparse
    path's log, its factorizations, low-rank factor updates and Krylov steps;
  - which path auto took, and auto's time against the faster path's (flagged above 1.10: the
    goal is that auto is never more than 10 % slower than the faster path);
  - seconds per estimated Gflop, per path: if one constant converted the estimates into times
    on every scene, this column would be one number.
The programs (build/bench): hertz_sweep (Hertz, two bodies, a small contact zone), long_interface
(two strips in contact along their whole length), westergaard (a wavy contact, a hundred
patches), chain (N bodies stacked), cattaneo --cost (Hertz with Coulomb friction, one solve).
Each program prints its log on stderr when asked (--log, or HERTZ_SWEEP_LOG, WESTERGAARD_LOG,
CHAIN_LOG, CATTANEO_LOG set).

usage: /usr/bin/python3 bench/interface_choice.py [--build build] [--repeat 3] [--quick]
       [--scenes hertz,strips,westergaard,chain,cattaneo] [--update-docs] [--json file]
(--quick: the smaller size of each scene only, repeat 1: a smoke run.)
"""
import argparse
import datetime
import json
import os
import re
import statistics
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
DOC = os.path.join(ROOT, "docs", "benchmarks.md")
BEGIN, END = "<!-- interface-choice:begin -->", "<!-- interface-choice:end -->"
SHORT_PREFIX = "| The automatic choice of the interface solver against both paths forced"
PATHS = ("auto", "condensed", "sparse")
FLAG = 1.10

# The automatic choice's log line (lib/solve/sparse_contact_path.cpp, choose_interface_solver).
CHOICE = re.compile(r"interface solver: (\w+) \(automatic: [^;]*; condensed estimated ([0-9.e+-]+) flops .*?"
                    r"sparse (?:estimated )?(?:([0-9.]+) x )?([0-9.e+-]+) flops.*?for (\d+) contact rows")
# What it expects of the sparse path (factorizations, Krylov steps).
EXPECTED = re.compile(r"\(([0-9.]+) factorizations of [0-9.e+-]+ flops, (\d+) Krylov steps")
# The sparse path's work (its frictionless and its frictional log lines).
SPARSE_WORK = re.compile(r"active-set solve \(sparse\): \w+(?: \w+)?, (\d+) iterations, (\d+) factorizations, "
                         r"(\d+) factor updates, (\d+) conjugate-gradient steps")
FRICTION_WORK = re.compile(r"sparse friction solve: (\d+) factorizations, (\d+) factor updates, (\d+) Krylov steps")

# The scenes and sizes. Each size runs in well under a minute per path on an idle 2-core machine;
# the condensed path is not forced where it is known to be huge (strips beyond 4000 cells: 3.7
# GiB and 200 plain solves at 4001 contact nodes, tens of GiB at 16001), so those sizes are not
# in the table.
SCENES = {
    "hertz": [0.008, 0.004],          # h1: 2.6e4 and 1.0e5 DOFs
    "strips": [1000, 2000],           # nx: 1001 and 2001 contact nodes
    "westergaard": [25, 100],         # wavelengths: 1001 and 4001 contact nodes
    "chain": [4, 16],                 # bodies of 5.05e4 unknowns each (--cells 158)
    "cattaneo": [20, 40],             # h = a/20 and a/40, Coulomb mu = 0.3, one solve
}


def run(cmd, env=None, timeout=1800):
    print("+", " ".join(cmd), file=sys.stderr, flush=True)
    full_env = dict(os.environ)
    full_env.update(env or {})
    p = subprocess.run(cmd, capture_output=True, text=True, env=full_env, timeout=timeout)
    if p.returncode != 0:
        sys.stderr.write(p.stdout[-2000:] + p.stderr[-4000:])
        raise RuntimeError("%s failed (exit %d)" % (cmd[0], p.returncode))
    return p.stdout, p.stderr


def table_rows(text, first_cell=None):
    """The cells of the Markdown table rows of `text` (header and rule lines included)."""
    rows = []
    for line in text.splitlines():
        if line.startswith("|") and not line.startswith("|---"):
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            if first_cell is None or cells[0] == first_cell:
                rows.append(cells)
    return rows


def choice_of(log):
    """(path auto took, condensed Gflop, sparse Gflop, contact rows) from the first automatic-choice line."""
    m = CHOICE.search(log)
    if not m:
        return None
    factor = float(m.group(3)) if m.group(3) else 1.0
    expected = EXPECTED.search(log)
    # "clear without analysing": bounds, not estimates (a lower one on the condensed path, an
    # upper one on the sparse path; sparse_path_clear_unanalysed)
    bounds = "clear without analysing" in m.group(0)
    return (m.group(1), float(m.group(2)) / 1e9, factor * float(m.group(4)) / 1e9, int(m.group(5)),
            "%s, %s" % expected.groups() if expected else "%g, -" % factor, bounds)


def is_bound(choice):
    """The choice's figures are bounds (older --json files have no such field)."""
    return bool(choice and len(choice) > 5 and choice[5])


def sparse_work(log):
    """'factorizations, updates, Krylov steps' of the sparse path's first solve in `log`."""
    m = SPARSE_WORK.search(log)
    if m:
        return "%s, %s, %s" % (m.group(2), m.group(3), m.group(4))
    m = FRICTION_WORK.search(log)
    if m:
        return "%s, %s, %s" % m.groups()
    return "-"


def logs_by_path(stderr, marker):
    """Split a program's stderr at its per-path markers: {path: log text}."""
    out, current = {}, None
    for line in stderr.splitlines():
        m = marker(line)
        if m:
            current = m
            out.setdefault(current, "")
        elif current:
            out[current] += line + "\n"
    return out


def hertz(build, h1, repeat):
    js = "/tmp/interface_choice_hertz_%d.json" % os.getpid()
    _, err = run([os.path.join(build, "hertz_sweep"), "--cases", "plain,mortar", "--solvers", "auto,condensed,sparse",
                  "--repeat", str(repeat), "--json", js, str(h1)], env={"HERTZ_SWEEP_LOG": "1"})
    rows = json.load(open(js))
    os.unlink(js)
    out = {"size": "h1 = %g" % h1, "time": {}, "plain": None}
    for r in rows:
        if r["case"] == "plain":
            out["plain"] = r["time"]
        else:
            out["time"][r["solver"]] = r["time"]
            out["dofs"] = r["dofs"]
    # the children run in the order auto, condensed, sparse; each logs its solves (the last
    # repeat also a re-solve): auto's choice is the first automatic line, the sparse path's work
    # the first sparse active-set line (auto took condensed) or the one after the last
    # "interface solver: condensed (asked for)" line
    out["choice"] = choice_of(err)
    tail = err[err.rfind("interface solver: condensed (asked for)"):]
    out["work"] = sparse_work(tail)
    return out


def strips(build, nx, repeat):
    text, err = run([os.path.join(build, "long_interface"), "--solver", "all", "--log", "--repeat", str(repeat),
                     "--condensed-max", str(nx), str(nx)])
    out = {"size": "nx = %d" % nx, "time": {}, "plain": None}
    for cells in table_rows(text, str(nx)):
        if len(cells) > 20 and cells[3] in PATHS:
            out["time"][cells[3]] = float(cells[10])
            out["plain"] = float(cells[17])
            out["dofs"] = int(cells[2])
    # the children run auto, condensed, sparse in that order, each after its plain solve
    order = iter(PATHS)
    logs = {}
    current = None
    for line in err.splitlines():
        if re.match(r"  nx \d+, solve 1 of", line):
            current = next(order)
            logs[current] = ""
        if current:
            logs[current] += line + "\n"
    out["choice"] = choice_of(logs.get("auto", ""))
    out["work"] = sparse_work(logs.get("sparse", ""))
    return out


def westergaard(build, n_waves, repeat):
    out = {"size": "N = %d" % n_waves, "time": {}, "plain": None}
    logs = {}
    for path in PATHS:
        text, err = run([os.path.join(build, "westergaard"), "-N", str(n_waves), "-s", path, "-r", str(repeat)],
                        env={"WESTERGAARD_LOG": "1"})
        for cells in table_rows(text, path):
            out["time"][path] = float(cells[16])
            out["plain"] = float(cells[21])
            out["dofs"] = int(cells[4])
        logs[path] = err
    out["choice"] = choice_of(logs["auto"])
    out["work"] = sparse_work(logs["sparse"])
    return out


def chain(build, n, repeat):
    # every path in one run: its rounds interleave them, so that the load of a shared machine
    # falls on all of them alike
    out = {"size": "N = %d" % n, "time": {}, "plain": None}
    text, err = run([os.path.join(build, "chain"), "--solvers", "plain,condensed,sparse,auto", "--repeat", str(repeat),
                     str(n)], env={"CHAIN_LOG": "1"})
    for cells in table_rows(text, str(n)):
        path = cells[1].split(":")[0] if len(cells) > 10 else None
        if path == "plain":
            out["plain"] = float(cells[8])
        elif path in PATHS:
            out["time"][path] = float(cells[8])
            out["dofs"] = int(cells[2])
    # only auto's solves log an automatic choice; the sparse path's work is the same whichever
    # of its runs logged it first
    out["choice"] = choice_of(err)
    out["work"] = sparse_work(err)
    return out


def cattaneo(build, n, repeat):
    out = {"size": "h = a/%d" % n, "time": {}, "plain": None}
    logs = {}
    for path in PATHS:
        text, err = run([os.path.join(build, "cattaneo"), "--cost", "--h-over-a", str(n), "--repeat", str(repeat),
                         "--history", "0", "--solver", path], env={"CATTANEO_LOG": "1"})
        for cells in table_rows(text, "1/%d" % n):
            out["time"][path] = float(cells[3])  # the Coulomb solve
            out["dofs"] = int(cells[1])
        # the first timed Coulomb model's log (the secant before it runs on auto, untimed)
        logs[path] = logs_by_path(err, lambda line: line if line.startswith("timed solves: mu 0.3, 1 steps") else None)
        logs[path] = next(iter(logs[path].values()), "")
    out["choice"] = choice_of(logs["auto"])
    out["work"] = sparse_work(logs["sparse"])
    return out


RUNNERS = {"hertz": hertz, "strips": strips, "westergaard": westergaard, "chain": chain, "cattaneo": cattaneo}
TITLES = {"hertz": "Hertz", "strips": "long strips", "westergaard": "Westergaard", "chain": "chain",
          "cattaneo": "Cattaneo (μ = 0.3)"}


def fmt(x, digits=3):
    if x is None:
        return "—"
    if x == 0:
        return "0"
    return "%.*g" % (digits, x)


def markdown(results):
    head = ("| scene | size | DOFs | contact rows | auto took | estimate condensed Gflop | estimate sparse Gflop | "
            "estimate c/s | plain s | condensed s | sparse s | measured c/s | auto took the faster path | auto s | auto / faster | "
            "condensed s/Gflop | sparse s/Gflop | sparse expected: factorizations, Krylov steps | "
            "sparse measured: factorizations, updates, Krylov steps |")
    lines = [head, "|" + "---|" * head.count(" | ") + "---|"]
    for r in results:
        t = r["time"]
        ran, c_est, s_est, q, expected = r["choice"][:5] if r["choice"] else ("?", None, None, None, "-")
        bound = is_bound(r["choice"])
        c, s, a = t.get("condensed"), t.get("sparse"), t.get("auto")
        faster = min(x for x in (c, s) if x) if (c or s) else None
        ratio = a / faster if a and faster else None
        flag = "**%.2f**" % ratio if ratio and ratio > FLAG else fmt(ratio, 3)
        if c and s:
            better = "condensed" if c < s else "sparse"
            right = ("yes" if ran == better else "either (within 10 %)" if max(c, s) <= FLAG * min(c, s)
                     else "**no** (%.2f ×)" % (max(c, s) / min(c, s)))
        else:
            right = "—"
        lines.append("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            TITLES[r["scene"]], r["size"], r.get("dofs", "—"), q if q is not None else "—", ran,
            ("≥ " if bound else "") + fmt(c_est), ("≤ " if bound else "") + fmt(s_est),
            ("≥ " if bound else "") + fmt(c_est / s_est if c_est and s_est else None), fmt(r["plain"]), fmt(c), fmt(s),
            fmt(c / s if c and s else None), right, fmt(a), flag,
            fmt(c / c_est if c and c_est and not bound else None),
            fmt(s / s_est if s and s_est and not bound else None), expected, r["work"]))
    return "\n".join(lines)


def summary(results):
    """The facts the prose and the short table need, computed from the rows."""
    worst = None
    wrong = []
    per_path = {"condensed": [], "sparse": []}
    for r in results:
        t, ch = r["time"], r["choice"]
        if not ch or "condensed" not in t or "sparse" not in t or "auto" not in t:
            continue
        faster = min(t["condensed"], t["sparse"])
        ratio = t["auto"] / faster
        if worst is None or ratio > worst[0]:
            worst = (ratio, r)
        better = "condensed" if t["condensed"] < t["sparse"] else "sparse"
        if ch[0] != better and max(t["condensed"], t["sparse"]) > FLAG * faster:
            wrong.append(r)
        for path, est in (("condensed", ch[1]), ("sparse", ch[2])):
            if est > 0 and not is_bound(ch):
                per_path[path].append(t[path] / est)
    spread = {p: (min(v), max(v)) for p, v in per_path.items() if v}
    return worst, wrong, spread


def update_docs(results, meta, command):
    text = open(DOC).read()
    worst, wrong, spread = summary(results)
    scene_list = ", ".join("%s (%s)" % (TITLES[s], ", ".join(str(x) for x in sizes)) for s, sizes in meta["scenes"].items())
    body = [BEGIN,
            "",
            "Run started %s, commit %s, load average %s at the start (%s), %d s in all; wall-time medians of %d repeats per "
            "path. Scenes (sizes): %s." % (meta["date"], meta["commit"], meta["load"], meta["note"], meta.get("seconds", 0),
                                           meta["repeat"], scene_list),
            "",
            markdown(results),
            "",
            END]
    block = "\n".join(body)
    if BEGIN in text:
        text = text[:text.index(BEGIN)] + block + text[text.index(END) + len(END):]
    else:
        raise SystemExit("docs/benchmarks.md has no %s marker: add the section first" % BEGIN)
    if worst:
        r = worst[1]
        if wrong:
            verdict = "**not met**: the slower path on " + ", ".join("%s %s" % (TITLES[w["scene"]], w["size"]) for w in wrong)
        elif worst[0] > FLAG:
            verdict = ("met on the choice (the faster path, or one within 10 %%, everywhere); auto's own time up to "
                       "%.2f × that same path forced%s" % (worst[0], ": the loaded machine's noise, **not settled** "
                                                           "until an idle run" if meta["loaded"] else ""))
        else:
            verdict = "met"
        short = (SHORT_PREFIX + ", every benchmark scene (Hertz, strips, Westergaard, chain, Cattaneo), two sizes "
                 "each | auto took the faster path (or one within 10 %%) on %d of %d; auto at most %.2f × the faster "
                 "path (%s, %s); seconds per estimated Gflop %s (before the new estimate: 0.042 to 0.86 and 0.017 to "
                 "2.2, and the slower path on Westergaard at 25 wavelengths) | never more than 10 %% slower: %s | "
                 "[Automatic choice](#the-automatic-choice-estimate-against-measurement), %s, commit %s%s |" % (
                     len(results) - len(wrong), len(results), worst[0], TITLES[r["scene"]], r["size"],
                     ", ".join("%s %.2g to %.2g" % (p, lo, hi) for p, (lo, hi) in spread.items()), verdict,
                     meta["date"], meta["commit"], ", loaded machine" if meta["loaded"] else ", idle machine"))
        # the row of the "In short" table: replaced, or added after its last row (a marker
        # line inside a Markdown table would end the table)
        lines = text.split("\n")
        mine = [i for i, l in enumerate(lines) if l.startswith(SHORT_PREFIX)]
        if mine:
            lines[mine[0]] = short
        else:
            head = next(i for i, l in enumerate(lines) if l.startswith("| what was measured"))
            end = next(i for i in range(head, len(lines)) if not lines[i].startswith("|"))
            lines.insert(end, short)
        text = "\n".join(lines)
    open(DOC, "w").write(text)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--scenes", default=",".join(SCENES))
    ap.add_argument("--update-docs", action="store_true")
    ap.add_argument("--loaded", action="store_true", help="say in the docs that the machine was loaded")
    ap.add_argument("--json", help="write the results here too")
    ap.add_argument("--from-json", help="no run: the results of an earlier --json (for --update-docs)")
    args = ap.parse_args()
    bench = os.path.join(args.build, "bench")
    repeat = 1 if args.quick else args.repeat
    chosen = {s: (SCENES[s][:1] if args.quick else SCENES[s]) for s in args.scenes.split(",")}
    load = os.getloadavg()[0]
    start, started = time.time(), datetime.datetime.utcnow()
    results = []
    saved = json.load(open(args.from_json)) if args.from_json else None
    if saved:
        results = saved["results"]
    for scene, sizes in ({} if saved else chosen).items():
        for size in sizes:
            t0 = time.time()
            r = RUNNERS[scene](bench, size, repeat)
            r["scene"] = scene
            results.append(r)
            print("  %s %s: %.0f s" % (scene, size, time.time() - t0), file=sys.stderr, flush=True)
    table = markdown(results)
    print(table)
    worst, wrong, spread = summary(results)
    if worst:
        print("\nauto at most %.2f x the faster path (%s %s); picks the slower path by more than 10 %% on: %s"
              % (worst[0], worst[1]["scene"], worst[1]["size"],
                 ", ".join("%s %s" % (w["scene"], w["size"]) for w in wrong) or "none"))
        print("seconds per estimated Gflop: " + ", ".join("%s %.3g to %.3g" % (p, lo, hi) for p, (lo, hi) in spread.items()))
    print("whole run %.0f s" % (time.time() - start), file=sys.stderr)
    commit = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"], capture_output=True, text=True).stdout.strip()
    meta = saved["meta"] if saved else {
        "date": started.strftime("%Y-%m-%d %H:%M UTC"), "commit": commit, "load": "%.1f" % load,
        "loaded": args.loaded, "note": "shared, loaded machine" if args.loaded else "idle machine", "repeat": repeat,
        "scenes": chosen, "seconds": round(time.time() - start)}
    if args.json:
        json.dump({"meta": meta, "results": results}, open(args.json, "w"), indent=1)
    if args.update_docs:
        update_docs(results, meta, " ".join(sys.argv))
    return 1 if worst and worst[0] > FLAG else 0


if __name__ == "__main__":
    sys.exit(main())
