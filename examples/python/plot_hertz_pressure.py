#!/usr/bin/python3
"""Plots the contact pressure that mortarcontact-run wrote (its pressure CSV: x, y, pressure,
gap per body-1 contact node) against Hertz's p(x) = p0 sqrt(1 - x^2/a^2), into a PNG.

    /usr/bin/python3 examples/python/plot_hertz_pressure.py hertz_pressure.csv hertz_pressure.png
        [--radius 1] [--load 0.01] [--young 1] [--poisson 0.3] [--plane strain|stress]

The defaults are the Hertz scene of examples/runner/hertz/hertz.json (method.md): two equal
bodies, E = 1, nu = 0.3, plane strain, R = 1, P = 0.01 per unit thickness. x is measured from
the contact point. Needs matplotlib (Debian: python3-matplotlib); draws without a display.
"""

import argparse
import csv
import math

import matplotlib

matplotlib.use("Agg")  # no display needed
import matplotlib.pyplot as plt  # noqa: E402 (after the backend is chosen)


def hertz(radius, load, young, poisson, plane):
    """(a, p0) of a cylinder on a half-plane of the same material, per unit thickness."""
    modulus = young / (1.0 - poisson ** 2) if plane == "strain" else young
    e_star = modulus / 2.0  # 1/E* = 1/E'1 + 1/E'2, equal bodies
    a = math.sqrt(4.0 * load * radius / (math.pi * e_star))
    return a, 2.0 * load / (math.pi * a)


def read_pressure(path):
    with open(path, newline="") as f:
        rows = [(float(r["x"]), float(r["pressure"])) for r in csv.DictReader(f)]
    return sorted(rows)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("csv", help="pressure CSV written by mortarcontact-run")
    parser.add_argument("png", help="the plot to write")
    parser.add_argument("--radius", type=float, default=1.0)
    parser.add_argument("--load", type=float, default=0.01, help="force per unit thickness")
    parser.add_argument("--young", type=float, default=1.0)
    parser.add_argument("--poisson", type=float, default=0.3)
    parser.add_argument("--plane", choices=("strain", "stress"), default="strain")
    args = parser.parse_args()

    rows = read_pressure(args.csv)
    if not rows:
        parser.error("%s has no contact nodes" % args.csv)
    a, p0 = hertz(args.radius, args.load, args.young, args.poisson, args.plane)
    window = 1.6 * a
    shown = [(x, p) for x, p in rows if abs(x) <= window]
    xs = [window * (k / 200.0 - 1.0) for k in range(401)]
    analytic = [p0 * math.sqrt(max(0.0, 1.0 - x * x / (a * a))) for x in xs]
    p0_computed = max(p for _, p in rows)

    fig, ax = plt.subplots(figsize=(7, 4.2))
    ax.plot(xs, analytic, "-", color="black", label="Hertz: $p_0$ = %.5g, a = %.4g" % (p0, a))
    ax.plot([x for x, _ in shown], [p for _, p in shown], "o", markersize=3.5, color="tab:red",
            label="mortarcontact: $p_0$ = %.5g (%+.2f %%)" % (p0_computed, 100 * (p0_computed / p0 - 1)))
    ax.set_xlabel("x")
    ax.set_ylabel("contact pressure")
    ax.set_xlim(-window, window)
    ax.set_ylim(0, 1.15 * max(p0, p0_computed))
    ax.grid(True, alpha=0.3)
    ax.legend(loc="upper right", fontsize="small")
    ax.set_title("Contact pressure against Hertz (R = %g, P = %g, plane %s)" % (args.radius, args.load, args.plane))
    fig.tight_layout()
    fig.savefig(args.png, dpi=120)
    print("wrote %s" % args.png)


if __name__ == "__main__":
    main()
