#!/usr/bin/python3
"""Speed against error on the Hertz scene: mortarcontact (plain solve, mortar, dual mortar,
node-to-segment) and GetFEM (nodal brick, integral Alart-Curnier in GWFL), one run, same meshes.

Runs build/bench/hertz_sweep (one child process per size and case: phase times, peak RSS,
p0, a, H1 norm, re-solve time) and bench/getfem_hertz.py (same meshes, bit for bit), then
  - prints and writes a Markdown report (tables, ratios, fitted exponents),
  - draws |error of p0| against time for both codes into a PNG,
  - with --update-docs, replaces the generated section of docs/benchmarks.md.

usage: /usr/bin/python3 bench/hertz_benchmark.py [--build build] [--quick] [--update-docs]
       [--no-getfem] [--getfem-from-json] [--repeat 3] [--from-json]
       [--solvers auto,condensed,sparse] [--cases plain,mortar,dual,nts] [--sizes h1 ...]
(--quick: three small sizes, for a smoke run; the documented numbers come from the default.)
--solvers: the interface solvers (MC_OPTION_INTERFACE_SOLVER) each contact case runs with:
  auto (the option not set, the library's choice: the default, the only one before the option
  existed), condensed, sparse (forced). Rows of a forced solver are named "mortar (sparse)"
  etc.; every contact row says which solver ran (MC_INFO_INTERFACE_SOLVER), and with more than
  one solver the report adds a table of the solvers side by side per case and size (time,
  contact/plain, peak RSS/plain, re-solve, which one auto picked). The plot and the GetFEM
  comparison use the auto rows (or the first solver given).
--cases: the cases of hertz_sweep (default all four; e.g. plain,mortar for the solver tables).
--sizes: h1 values instead of the default list (the finest is the reference of H1 and p0).
Needs python3-matplotlib and, for the peer, python3-getfem (Debian).
"""
import argparse
import json
import math
import os
import statistics
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
# h1 of body 1's fine zone; h2 = 1.37 h1. From ~1.5e3 to ~1.8e6 DOFs; the finest is the reference
# of the H1 norm and of the converged p0.
OUR_SIZES = [0.1, 0.05, 0.025, 0.012, 0.006, 0.004, 0.0025, 0.0017, 0.00125, 0.00107, 0.0008]
GETFEM_SIZES = [0.1, 0.05, 0.025, 0.012, 0.006, 0.004, 0.0025, 0.002]
QUICK_SIZES = [0.1, 0.05, 0.025]
BEGIN, END = "<!-- hertz-benchmark:begin -->", "<!-- hertz-benchmark:end -->"


def run(cmd, **kw):
    print("+", " ".join(cmd), flush=True)
    return subprocess.run(cmd, check=True, **kw)


def fit_exponent(dofs, times):
    """Least-squares slope of log(time) against log(DOFs)."""
    x = [math.log(d) for d in dofs]
    y = [math.log(t) for t in times]
    mx, my = statistics.fmean(x), statistics.fmean(y)
    return sum((a - mx) * (b - my) for a, b in zip(x, y)) / sum((a - mx) ** 2 for a in x)


def time_to_reach(rows, err_key, target):
    """Time of the coarsest mesh from which on every finer mesh stays within |error| <= target
    (None if none): a coarse mesh whose error is small by a lucky cancellation does not count."""
    rows = sorted(rows, key=lambda r: r["dofs"])
    for i, r in enumerate(rows):
        if all(abs(x[err_key]) <= target for x in rows[i:]):
            return r["time"]
    return None


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--out", default=os.path.join(HERE, "out"))
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--no-getfem", action="store_true")
    ap.add_argument("--getfem-from-json", action="store_true",
                    help="reuse GetFEM's numbers from the last run's JSON (its code did not change), run ours")
    ap.add_argument("--update-docs", action="store_true")
    ap.add_argument("--solvers", default="auto",
                    help="comma list of auto, condensed, sparse: MC_OPTION_INTERFACE_SOLVER of the contact cases")
    ap.add_argument("--cases", default="plain,mortar,dual,nts", help="comma list of plain, mortar, dual, nts")
    ap.add_argument("--sizes", type=float, nargs="+", help="h1 values (default: the documented list)")
    ap.add_argument("--from-json", action="store_true",
                    help="rebuild the report and the plot from the JSON files of the last run (no solving)")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    ours_sizes = args.sizes or (QUICK_SIZES if args.quick else OUR_SIZES)
    peer_sizes = QUICK_SIZES if args.quick else GETFEM_SIZES
    solvers = [x for x in ("auto", "condensed", "sparse") if x in args.solvers.split(",")]
    if not solvers:
        ap.error("--solvers: a comma list of auto, condensed, sparse")

    # 1. Our sweep (MC_NORMAL_MORTAR: the gap measured along body 2's normal, as both GetFEM
    #    formulations measure it, so that both codes discretise the same problem).
    ours_json = os.path.join(args.out, "hertz_ours.json")
    if not args.from_json:
        run([os.path.join(args.build, "bench", "hertz_sweep"), "--normal", "mortar", "--repeat", str(args.repeat),
             "--cases", args.cases, "--solvers", ",".join(solvers), "--json", ours_json] + [str(h) for h in ours_sizes])
    ours = json.load(open(ours_json))
    # Rows of a forced interface solver are cases of their own ("mortar (sparse)"); the auto rows
    # (and the rows of a JSON from before the option, which have no "solver") keep the case name.
    for r in ours:
        r.setdefault("solver", "auto")
        r["label"] = r["case"] if r["case"] == "plain" or r["solver"] == "auto" else "%s (%s)" % (r["case"], r["solver"])
    main_solver = "auto" if any(r["solver"] == "auto" for r in ours if r["case"] != "plain") else solvers[0]
    ran_names = {1: "condensed", 2: "sparse"}

    # 2. GetFEM on the same meshes (one measurement per size: the large ones take minutes).
    peer = []
    if not args.no_getfem:
        peer_json = os.path.join(args.out, "hertz_getfem.json")
        if not args.from_json and not args.getfem_from_json:
            run(["/usr/bin/python3", os.path.join(HERE, "getfem_hertz.py"), "--json", peer_json, "--h1"]
                + [str(h) for h in peer_sizes])
        peer = json.load(open(peer_json))

    # 3. Derived numbers.
    by_case = {}  # by label
    for r in ours:
        by_case.setdefault(r["label"], []).append(r)
    # the main rows of each case: auto, or the first solver given
    main_label = {c: c if main_solver == "auto" else "%s (%s)" % (c, main_solver) for c in ("mortar", "dual", "nts")}
    mortar_rows = by_case.get(main_label["mortar"]) or next(rs for l, rs in by_case.items() if l != "plain")
    finest = max(mortar_rows, key=lambda r: r["dofs"])
    p0_ref, h1_ref = finest["p0"], {l: max(rs, key=lambda r: r["dofs"])["h1_norm"] for l, rs in by_case.items()}
    for r in ours:
        r["err_p0"] = r["p0"] / r["p0_hertz"] - 1 if r["case"] != "plain" else float("nan")
        r["err_a"] = r["a"] / r["a_hertz"] - 1 if r["case"] != "plain" else float("nan")
        r["err_a_moment"] = r["a_moment"] / r["a_hertz"] - 1 if r["case"] != "plain" else float("nan")
        r["err_p0_ref"] = r["p0"] / p0_ref - 1 if r["case"] != "plain" else float("nan")
        r["err_h1"] = r["h1_norm"] / h1_ref[r["label"]] - 1
    for r in peer:
        r["err_p0_ref"] = r["p0"] / p0_ref - 1
    plain = {r["h1"]: r for r in by_case.get("plain", [])}
    labels = ["plain"] + [c if s == "auto" else "%s (%s)" % (c, s) for c in ("mortar", "dual", "nts") for s in solvers]

    lines = []
    out = lines.append
    env_threads = os.environ.get("OPENBLAS_NUM_THREADS", "unset")
    out(BEGIN)
    flags = "".join([" --solvers " + ",".join(solvers) if solvers != ["auto"] else "",
                     " --cases " + args.cases if args.cases != "plain,mortar,dual,nts" else "",
                     " --sizes " + " ".join("%g" % h for h in args.sizes) if args.sizes else ""])
    out("Generated by `/usr/bin/python3 bench/hertz_benchmark.py --update-docs%s` (%s; %d cores; "
        "OPENBLAS_NUM_THREADS=%s; our wall times are medians of %d runs, GetFEM's single runs)."
        % (flags, "quick run" if args.quick else "full run", os.cpu_count(), env_threads, args.repeat))
    out("")
    out("Hertz scene, P1, graded meshes, h2 = 1.37 h1; our solves use `MC_NORMAL_MORTAR` (the gap along body 2's "
        "normal, as GetFEM measures it). Time = wall time from `mc_create` to the results read back; phase times "
        "are the library's infos. `err` columns are relative errors against Hertz; `H1` is the relative difference "
        "of the H1 norm from the finest solution of the same case (h1 = %g, %d DOFs)." % (finest["h1"], finest["dofs"]))
    out("")
    out("| case | interface solver | h1 | DOFs | contact nodes | active | it | assembly s | analysis s | factor s "
        "| contact s | time s | contact/plain | re-solve s | first/re-solve | peak RSS MiB | RSS/plain | err p0 | err a "
        "| err a_moment | H1 |")
    out("|" + "---|" * 21)

    def solver_cell(r):
        """The solver asked for, and the one that ran (MC_INFO_INTERFACE_SOLVER)."""
        if r["case"] == "plain":
            return "-"
        ran = ran_names.get(r.get("solver_ran"), "?")
        return "%s: %s" % (r["solver"], ran) if r["solver"] == "auto" else (
            r["solver"] if ran == r["solver"] else "%s (ran: %s)" % (r["solver"], ran))

    for label in labels:
        for r in by_case.get(label, []):
            base = plain.get(r["h1"])
            contact = r["case"] != "plain"
            out("| %s | %s | %g | %d | %s | %s | %s | %.3f | %.3f | %.3f | %s | %.3f | %s | %s | %s | %.0f | %s | %s | %s | %s | %+.1e |" % (
                label, solver_cell(r), r["h1"], r["dofs"], r["contact_nodes"] if contact else "-", r["active_nodes"] if contact else "-",
                r["iterations"] if contact else "-", r["time_assembly"], r["time_analysis"], r["time_factorization"],
                "%.3f" % r["time_contact"] if contact else "-", r["time"],
                "%.2f" % (r["time"] / base["time"]) if contact and base else "-",
                "%.4f" % r["time_resolve"] if contact else "-",
                "%.0f" % (r["time"] / r["time_resolve"]) if contact and r["time_resolve"] > 0 else "-",
                r["peak_rss_mib"], "%.2f" % (r["peak_rss_mib"] / base["peak_rss_mib"]) if contact and base else "-",
                "%+.2e" % r["err_p0"] if contact else "-", "%+.2e" % r["err_a"] if contact else "-",
                "%+.2e" % r["err_a_moment"] if contact else "-", r["err_h1"]))
    out("")
    # the interface solvers side by side, per case and size
    if len(solvers) > 1:
        out("Interface solvers side by side (`MC_OPTION_INTERFACE_SOLVER`; auto = the option not set; "
            "\"auto ran\" = `MC_INFO_INTERFACE_SOLVER` of the auto solve):")
        out("")
        hdr = ["case", "h1", "DOFs", "contact nodes", "plain s"] + ["%s s" % x for x in solvers] \
            + ["%s/plain" % x for x in solvers] + ["%s RSS/plain" % x for x in solvers] \
            + ["%s re-solve s" % x for x in solvers] + (["auto ran"] if "auto" in solvers else [])
        out("| " + " | ".join(hdr) + " |")
        out("|" + "---|" * len(hdr))
        for case in ("mortar", "dual", "nts"):
            rows = {}
            for r in ours:
                if r["case"] == case:
                    rows.setdefault(r["h1"], {})[r["solver"]] = r
            for h1 in sorted(rows, reverse=True):
                got, base = rows[h1], plain.get(h1)
                any_row = next(iter(got.values()))
                cells = [case, "%g" % h1, "%d" % any_row["dofs"], "%d" % any_row["contact_nodes"],
                         "%.3f" % base["time"] if base else "-"]
                cells += ["%.3f" % got[x]["time"] if x in got else "-" for x in solvers]
                cells += ["%.2f" % (got[x]["time"] / base["time"]) if x in got and base else "-" for x in solvers]
                cells += ["%.2f" % (got[x]["peak_rss_mib"] / base["peak_rss_mib"]) if x in got and base else "-"
                          for x in solvers]
                cells += ["%.4f" % got[x]["time_resolve"] if x in got else "-" for x in solvers]
                if "auto" in solvers:
                    cells.append(ran_names.get(got["auto"].get("solver_ran"), "?") if "auto" in got else "-")
                out("| " + " | ".join(cells) + " |")
        out("")
    # headline figures
    for solver in solvers:
        label = main_label["mortar"] if solver == main_solver else "mortar (%s)" % solver
        big = [r for r in by_case.get(label, []) if r["dofs"] > 1e5 and r["h1"] in plain]
        if not big:
            continue
        tag = "mortar" if label == "mortar" else label
        ratios = [r["time"] / plain[r["h1"]]["time"] for r in big]
        mem = [r["peak_rss_mib"] / plain[r["h1"]]["peak_rss_mib"] for r in big]
        resolve = [r["time"] / r["time_resolve"] for r in big]
        out("- **Contact/plain time (%s), above 10^5 DOFs:** %s (goal <= 1.5)." % (tag, ", ".join("%.2f" % x for x in ratios)))
        out("- **Peak memory contact/plain (%s), above 10^5 DOFs:** %s (goal <= 1.3)." % (tag, ", ".join("%.2f" % x for x in mem)))
        out("- **First solve / re-solve after a load change (%s), above 10^5 DOFs:** %s (goal >= 10); the "
            "re-solve does %s factorizations." % (tag, ", ".join("%.0f" % x for x in resolve),
                                                   sorted({r["resolve_factorizations"] for r in big})))
    for label in labels:
        rs = [r for r in by_case.get(label, []) if r["dofs"] >= 1e4]
        if len(rs) >= 3:
            out("- Time grows like DOFs^%.2f for %s (least squares over %d sizes from 10^4 DOFs)."
                % (fit_exponent([r["dofs"] for r in rs], [r["time"] for r in rs]), label, len(rs)))
    out("")
    if peer:
        out("GetFEM 5.4 (Debian `python3-getfem`, MUMPS, Newton; time = model setup + solve) on the same meshes:")
        out("")
        for form in ("nodal", "gwfl"):
            rs = [r for r in peer if r["formulation"] == form and r["dofs"] >= 1e4]
            if len(rs) >= 3:
                out("- GetFEM %s: time grows like DOFs^%.2f (least squares over %d sizes from 10^4 DOFs)."
                    % (form, fit_exponent([r["dofs"] for r in rs], [r["time"] for r in rs]), len(rs)))
        out("")
        out("| formulation | h1 | DOFs | Newton it | time s | err p0 | err p0 vs converged | err a_moment | force balance |")
        out("|---|---|---|---|---|---|---|---|---|")
        for r in peer:
            out("| %s | %g | %d | %d | %.2f | %+.2e | %+.2e | %+.2e | %.1e |" % (
                r["formulation"], r["h1"], r["dofs"], r["newton_iterations"], r["time"], r["err_p0"], r["err_p0_ref"],
                r["err_a_moment"], r["force_balance"]))
        out("")
        out("Speed at equal error on p0: the time GetFEM took for its error, against the time of our mortar solve on "
            "the coarsest mesh from which on our error stays at or below it (errors against the converged p0 = %.6g, "
            "our finest mortar solution, which is %+.2f %% from Hertz's half-space formula):"
            % (p0_ref, 100 * (p0_ref / finest["p0_hertz"] - 1)))
        out("")
        out("| GetFEM formulation | DOFs | its error | its time s | our time s | speed-up |")
        out("|---|---|---|---|---|---|")
        for r in peer:
            mine = time_to_reach(mortar_rows, "err_p0_ref", abs(r["err_p0_ref"]))
            out("| %s | %d | %.2e | %.2f | %s | %s |" % (r["formulation"], r["dofs"], abs(r["err_p0_ref"]), r["time"],
                                                       "%.3f" % mine if mine else "not reached",
                                                       "%.0f" % (r["time"] / mine) if mine else "-"))
        out("")
    png = os.path.join(ROOT, "docs", "img", "hertz_speed_error.png")
    out("![p0 error against time](img/hertz_speed_error.png)")
    out(END)
    report = "\n".join(lines) + "\n"
    with open(os.path.join(args.out, "hertz_benchmark.md"), "w") as fh:
        fh.write(report)
    print(report)

    # 4. The plot: |error of p0| against time, both codes, against Hertz and against the converged p0.
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.8))
    styles = {"mortar": "o-", "dual": "s-", "nts": "^-", "nodal": "v--", "gwfl": "D--"}
    for ax, key, title in ((axes[0], "err_p0", "against Hertz"), (axes[1], "err_p0_ref", "against the converged p0")):
        for case in ("mortar", "dual", "nts"):
            rs = sorted(by_case.get(main_label[case], []), key=lambda r: r["dofs"])
            if not rs:
                continue
            if case == "mortar" and key == "err_p0_ref":
                rs = rs[:-1]  # the reference itself
            ax.loglog([r["time"] for r in rs], [max(abs(r[key]), 1e-7) for r in rs], styles[case],
                      label="mortarcontact " + case)
        for form in ("nodal", "gwfl"):
            rs = sorted([r for r in peer if r["formulation"] == form], key=lambda r: r["dofs"])
            if rs:
                ax.loglog([r["time"] for r in rs], [max(abs(r[key]), 1e-7) for r in rs], styles[form],
                          label="GetFEM " + form)
        ax.set_xlabel("wall time [s]")
        ax.set_ylabel("|relative error of p0|")
        ax.set_title("Hertz scene: p0 error %s" % title)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    os.makedirs(os.path.dirname(png), exist_ok=True)
    fig.savefig(png, dpi=110)
    print("plot written to", png)

    if args.update_docs:
        path = os.path.join(ROOT, "docs", "benchmarks.md")
        text = open(path).read()
        if BEGIN in text and END in text:
            text = text[:text.index(BEGIN)] + report.rstrip("\n") + text[text.index(END) + len(END):]
        else:
            text = text.rstrip("\n") + "\n\n" + report
        open(path, "w").write(text)
        print("updated", path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
