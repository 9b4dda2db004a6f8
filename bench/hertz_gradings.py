#!/usr/bin/env python3
"""hertz_gradings.py - each cell kind at its best mesh: the plane-strain Hertz p0 against DOFs
over a grid of mesh gradings (docs/benchmarks.md, "Each kind at its best grading").

bench/hertz_quadratic solves the Hertz scene on structured graded meshes: uniformly fine
(cells of h1) in a zone of half-width `fine` about the contact point, growing by `growth` per
cell outside it. Which grading is best differs between the cell kinds (quadratic cells are
accurate with larger cells far from the contact), so comparing them on one grading can favour
one kind. This runs hertz_quadratic once per (growth, fine) pair with a dense sampling of h1
(n sizes from h1_max to h1_min, geometrically spaced: "from which DOFs on p0 stays within a
level" then does not depend on where a few sizes happen to fall) and reports, for every kind
and error level, the fewest DOFs from which the error stays within the level on each grading,
and the best over all of them: for p0 (the peak pressure), a (the contact half-width by
bench/hertz_sweep.c's estimator) and a_moment (the half-width from the contact forces' second
moment).

  /usr/bin/python3 bench/hertz_gradings.py [--program build/bench/hertz_quadratic]
        [--growth 1.15,1.3,1.5,2,3] [--fine 0.4,0.3,0.25,0.2,0.15] [--gradings g:w,...] [--sizes 29] [--repeat 1] [--out DIR]
        [--kinds P1,T6,Q8] [--no-run] [--time-best ROUNDS] [--quick]

Each (growth, fine) pair runs twice: --method dual (P1 with the paper's mortar; T6 and Q8 by
dual mortar, the quadratic trace's dual basis) and --multiplier quadratic (T6 and Q8). With the
defaults: 25 pairs, 2 to 4 minutes each on 2 cores (every run solves the Q9 reference first).
The per-run JSON files are kept in --out (default hertz_gradings/). Exit status 1 if a run
failed.

--kinds runs only some kinds (their JSON files are tagged with them; --no-run merges every
file in --out). --time-best ROUNDS then times the best mesh of every kind at each p0 level again,
all in this one run (ROUNDS rounds over the meshes, each solve --repeat 5, the median of the
rounds' medians, against a coarse reference since only the times are wanted): the sweep's own
times come from runs minutes apart, and with --no-run from several sweeps.

"From which on": the DOFs of the smallest mesh of that kind and grading such that it and every
larger mesh have |p0 - p0_ref| <= level ('-': the finest mesh run is still outside). The time
is that mesh's wall time (hertz_quadratic --repeat, default 1 here: read times to +-30 %).
"""
import argparse
import json
import os
import statistics
import subprocess
import sys


def run(program, args, json_path, log_path):
    cmd = [program] + args + ["--json", json_path]
    with open(log_path, "w") as log:
        rc = subprocess.call(cmd, stdout=log, stderr=subprocess.STDOUT)
    if rc != 0:
        sys.stderr.write("failed (%d): %s\n" % (rc, " ".join(cmd)))
    return rc == 0


def stays_within(rows, level, key="err_p0"):
    """The row of the smallest mesh from which on |error| <= level, or None."""
    rows = sorted(rows, key=lambda r: r["dofs"])
    last_bad = -1
    for i, r in enumerate(rows):
        if abs(r[key]) > level:
            last_bad = i
    if last_bad == len(rows) - 1:
        return None
    return rows[last_bad + 1]


# (JSON key, what it is, levels): p0 the measure; a the contact half-width by
# bench/hertz_sweep.c's estimator (contact_half_width); a_moment from the contact forces' moment.
MEASURES = [("err_p0", "p0", [0.003, 0.001, 0.0003, 0.0001]),
            ("err_a", "a (contact_half_width)", [0.03, 0.01, 0.005]),
            ("err_a_moment", "a_moment", [0.01, 0.003, 0.001])]


def report(results, labels, gradings, key, title, levels):
    """Per kind and grading, then the best grading per kind: the DOFs from which on |error| <= level."""
    print("\n## %s within a level from this mesh on: DOFs (time s), per grading\n" % title)
    print("| kind | grading | " + " | ".join("%g %%" % (100 * l) for l in levels) + " |")
    print("|---|---|" + "---|" * len(levels))
    best = {}  # (label, level) -> (dofs, time, grading, row)
    for label in labels:
        for gr in gradings:
            rows = results.get((label, gr))
            if not rows:
                continue
            cells = []
            for l in levels:
                r = stays_within(rows, l, key)
                cells.append("%d (%.3f)" % (r["dofs"], r["time"]) if r else "-")
                if r and (best.get((label, l)) is None or r["dofs"] < best[(label, l)][0]):
                    best[(label, l)] = (r["dofs"], r["time"], gr, r)
            print("| %s | %s | %s |" % (label, gr, " | ".join(cells)))
    print("\nBest grading per kind and level (%s): DOFs (time s) [ratio to P1's best DOFs, time], grading\n" % title)
    print("| level | " + " | ".join(labels) + " |")
    print("|---|" + "---|" * len(labels))
    for l in levels:
        ref = best.get(("P1", l))
        cells = []
        for label in labels:
            b = best.get((label, l))
            if not b:
                cells.append("-")
            elif label == "P1" or not ref:
                cells.append("%d (%.3f), %s" % b[:3])
            else:
                cells.append("%d (%.3f) [%.2f, %.2f], %s" % (b[0], b[1], b[0] / ref[0], b[1] / ref[1], b[2]))
        print("| %g %% | %s |" % (100 * l, " | ".join(cells)))
    return best


def time_best(program, best, levels, title, rounds, repeat, out):
    """Times the best mesh of every kind and level again, all in this one run: `rounds` rounds
    over the meshes, each solve --repeat `repeat` times (hertz_quadratic's median); a mesh's time
    is the median of its rounds' medians. The meshes alternate within a round, so that a change
    of the machine's load reaches them alike. A coarse reference (--ref Q8:0.05): the errors are
    the sweep's, only the times are wanted here."""
    meshes = {}  # (label, grading, h1) -> list of times
    for (label, l), b in best.items():
        if l in levels:
            meshes.setdefault((label, b[2], b[3]["h1"]), [])
    order = sorted(meshes)
    for k in range(rounds):
        for label, gr, h1 in order:
            kind, variant = (label.split(" ", 1) + [""])[:2]
            g, w = [x.split()[1] for x in gr.split(", ")]
            vopts = ["--multiplier", "quadratic"] if variant.startswith("quadratic") else ["--method", "dual"]
            path = os.path.join(out, "time_%s.json" % "_".join([kind, variant.split(" ")[0] or "linear", g, w, "%.6g" % h1]))
            args = vopts + ["--repeat", str(repeat), "--ref", "Q8:0.05", "--growth", "%s:%s" % (kind, g),
                            "--fine", "%s:%s" % (kind, w), "%s:%.17g" % (kind, h1)]
            if run(program, args, path, path[:-5] + ".txt"):
                rows = [r for r in json.load(open(path)) if r["kind"] == kind and r.get("time")]
                meshes[(label, gr, h1)] += [rows[-1]["time"]]
    print("\nTimes of the best meshes (%s), timed again in one run: median of %d rounds of --repeat %d, ms "
          "[ratio to P1's DOFs, time]\n" % (title, rounds, repeat))
    labels = sorted(set(k for k, _ in best), key=lambda s: (s != "P1", s))
    print("| level | " + " | ".join(labels) + " |")
    print("|---|" + "---|" * len(labels))
    for l in levels:
        ref = best.get(("P1", l))
        t_ref = statistics.median(meshes[("P1", ref[2], ref[3]["h1"])]) if ref and meshes.get(("P1", ref[2], ref[3]["h1"])) else None
        cells = []
        for label in labels:
            b = best.get((label, l))
            t = meshes.get((label, b[2], b[3]["h1"])) if b else None
            if not b or not t:
                cells.append("-")
            elif label == "P1" or not t_ref:
                cells.append("%d, %.2f" % (b[0], 1e3 * statistics.median(t)))
            else:
                cells.append("%d, %.2f [%.2f, %.2f]" % (b[0], 1e3 * statistics.median(t), b[0] / ref[0], statistics.median(t) / t_ref))
        print("| %g %% | %s |" % (100 * l, " | ".join(cells)))


def add_rows(results, rows, variant, growth, fine):
    """A run's rows into results[(kind label, grading)]. P1 and Q1 ignore the variant's options,
    so only the dual mortar run's (which has them) count."""
    grading = "growth %g, fine %g" % (float(growth), float(fine))
    for r in rows:
        linear = r["kind"] in ("P1", "Q1")
        if r.get("err_p0") is None or (linear and variant != "dual"):
            continue
        label = r["kind"] if linear else "%s %s" % (r["kind"], variant)
        results.setdefault((label, grading), []).append(r)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--program", default="build/bench/hertz_quadratic")
    ap.add_argument("--growth", default="1.15,1.3,1.5,2,3")
    ap.add_argument("--fine", default="0.4,0.3,0.25,0.2,0.15")
    ap.add_argument("--gradings", help="growth:fine pairs, e.g. 2:0.25,1.3:0.15 (instead of the grid)")
    ap.add_argument("--sizes", type=int, default=29)
    ap.add_argument("--repeat", type=int, default=1)
    ap.add_argument("--out", default="hertz_gradings")
    ap.add_argument("--no-run", action="store_true",
                    help="run nothing: report on every run's JSON already in --out (e.g. several sweeps' merged)")
    ap.add_argument("--kinds", default="P1,T6,Q8", help="the kinds to run (P1, T6, Q8); --no-run reads whatever is in --out")
    ap.add_argument("--time-best", type=int, default=0, metavar="ROUNDS",
                    help="afterwards time the best mesh of every kind at each p0 level again, in ROUNDS rounds "
                         "of --repeat 5 (medians of medians; ratios to P1's from this one run)")
    ap.add_argument("--quick", action="store_true",
                    help="one grading, 3 coarse sizes per kind, a coarse reference: that it runs (ctest)")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    pairs = [(g, w) for g in a.growth.split(",") for w in a.fine.split(",")]
    if a.gradings:  # explicit pairs instead of the grid
        pairs = [tuple(p.split(":")) for p in a.gradings.split(",")]
    n = a.sizes
    kinds = a.kinds.split(",")
    p1 = ["P1:0.03..0.0025/%d" % n] if "P1" in kinds else []
    quad = ["%s:0.06..0.005/%d" % (k, n) for k in ("T6", "Q8") if k in kinds]
    extra = ["--repeat", str(a.repeat)]
    if a.quick:
        pairs = pairs[:1]
        p1 = ["P1:0.1..0.05/3"] if "P1" in kinds else []
        quad = ["%s:0.14..0.1/3" % k for k in ("T6", "Q8") if k in kinds]
        extra += ["--ref", "Q8:0.05", "--check", "Q8:0.07"]
    ok = True
    results = {}  # (kind label, grading) -> rows
    if a.no_run:  # the tags written below: {dual,quad}_g<growth>_w<fine>.json
        for name in sorted(os.listdir(a.out)):
            if not name.endswith(".json") or not name.startswith(("dual_", "quad_")) or "_w" not in name:
                continue
            variant = "dual" if name.startswith("dual_") else "quadratic multipliers"
            g, w = name[:-5].split("_g", 1)[1].split("_w")
            w = w.split("_")[0]  # (a --kinds run's tag ends in its kinds)
            try:
                rows = json.load(open(os.path.join(a.out, name)))
            except ValueError:  # a run still writing it, or one that failed
                sys.stderr.write("skipped %s: not complete JSON\n" % name)
                continue
            add_rows(results, rows, variant, g, w)
        pairs = []
    for g, w in pairs:
        opts = []
        for kind in ("P1", "T6", "Q8"):
            opts += ["--growth", "%s:%s" % (kind, g), "--fine", "%s:%s" % (kind, w)]
        for variant, vopts, sizes in (("dual", ["--method", "dual"], p1 + quad),
                                      ("quadratic multipliers", ["--multiplier", "quadratic"], quad)):
            if not sizes:
                continue
            tag = "%s_g%s_w%s" % ("dual" if variant == "dual" else "quad", g, w)
            if kinds != ["P1", "T6", "Q8"]:
                tag += "_" + "".join(kinds)
            path = os.path.join(a.out, tag + ".json")
            if not run(a.program, extra + vopts + opts + sizes, path, os.path.join(a.out, tag + ".txt")):
                ok = False
                continue
            add_rows(results, json.load(open(path)), variant, g, w)
    labels = sorted(set(k for k, _ in results), key=lambda s: (s != "P1", s))
    gradings = sorted(set(gr for _, gr in results))
    for key, title, levels in MEASURES:
        if a.quick and key == "err_p0":
            levels = [0.5, 0.1]  # (coarse sizes against a coarse reference: only that it all runs)
        best = report(results, labels, gradings, key, title, levels)
        if key == "err_p0" and a.time_best > 0:
            time_best(a.program, best, levels, title, a.time_best, 5 if not a.quick else 1, a.out)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
