#!/usr/bin/env python3
"""Draws the meshes of an adaptive run of mortarcontact-run (docs/tutorial_adaptive.md).

Reads the collection <stem>_steps.pvd the runner writes with "adaptive" and an output .pvd or
.vtu, and draws every step's mesh twice: the whole scene and a window around the first contact
point, each cell coloured by its error indicator (cell data "error_indicator", log scale) and
the cells' straight corner-to-corner sides drawn (a quadratic cell's curved sides and mid-edge
nodes are not). Needs matplotlib only: the VTU files are the library's ASCII ones.

usage: /usr/bin/python3 plot_steps.py STEPS.pvd OUT.png [--window XMIN XMAX YMIN YMAX] [--dpi 80]
"""
import argparse
import math
import os
import re

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402
from matplotlib.colors import LogNorm  # noqa: E402

CORNERS = {5: 3, 22: 3, 9: 4, 23: 4, 28: 4}  # VTK cell type -> corners (P1, T6, Q1, Q8, Q9)


def array(text, name):
    m = re.search(r'Name="%s"[^>]*>(.*?)</DataArray>' % name, text, re.S)
    if not m:
        raise SystemExit("no array %s" % name)
    return m.group(1).split()


def read_vtu(path):
    """(cells as lists of (x, y) corners, error indicators, number of points)."""
    text = open(path).read()
    xyz = [float(v) for v in array(text, "coordinates")]
    conn = [int(v) for v in array(text, "connectivity")]
    offsets = [int(v) for v in array(text, "offsets")]
    types = [int(v) for v in array(text, "types")]
    eta = [float(v) for v in array(text, "error_indicator")]
    cells, start = [], 0
    for end, t in zip(offsets, types):
        cells.append([(xyz[3 * i], xyz[3 * i + 1]) for i in conn[start:start + CORNERS[t]]])
        start = end
    return cells, eta, len(xyz) // 3


def read_steps(pvd):
    """[(step, [vtu paths])] in step order."""
    steps = {}
    for m in re.finditer(r'timestep="(\d+)"[^>]*file="([^"]+)"', open(pvd).read()):
        steps.setdefault(int(m.group(1)), []).append(os.path.join(os.path.dirname(pvd), m.group(2)))
    return sorted(steps.items())


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("steps")
    parser.add_argument("png")
    parser.add_argument("--dpi", type=int, default=80)
    parser.add_argument("--window", type=float, nargs=4, default=[-0.35, 0.35, -0.2, 0.2],
                        metavar=("XMIN", "XMAX", "YMIN", "YMAX"))
    args = parser.parse_args()
    steps = read_steps(args.steps)
    if not steps:
        raise SystemExit("%s lists no step" % args.steps)
    data = []
    for step, files in steps:
        cells, eta, points = [], [], 0
        for f in files:
            c, e, n = read_vtu(f)
            cells += c
            eta += e
            points += n
        data.append((step, cells, eta, points))
    positive = [e for _, _, eta, _ in data for e in eta if e > 0]
    norm = LogNorm(vmin=max(min(positive), max(positive) * 1e-6), vmax=max(positive))
    fig, axes = plt.subplots(len(data), 2, figsize=(9, 2.3 * len(data)), squeeze=False, constrained_layout=True)
    for row, (step, cells, eta, points) in zip(axes, data):
        estimate = math.sqrt(sum(e * e for e in eta))
        for ax, window in zip(row, (None, args.window)):
            if window is None:
                keep = range(len(cells))
            else:  # the cells with a corner in (or just around) the window
                x0, x1, y0, y1 = window[0] - 0.1, window[1] + 0.1, window[2] - 0.1, window[3] + 0.1
                keep = [k for k, c in enumerate(cells) if any(x0 <= x <= x1 and y0 <= y <= y1 for x, y in c)]
            shown = [cells[k] for k in keep]
            values = [max(eta[k], norm.vmin) for k in keep]
            collection = PolyCollection(shown, array=values, cmap="viridis", norm=norm, edgecolors="k",
                                        linewidths=0.1 if window is None else 0.3)
            ax.add_collection(collection)
            ax.set_aspect("equal")
            if window is None:
                xs = [x for c in cells for x, _ in c]
                ys = [y for c in cells for _, y in c]
                ax.set_xlim(min(xs), max(xs))
                ax.set_ylim(min(ys), max(ys))
                ax.set_title("step %d: %d cells, %d nodes, estimate %.3g %%" % (step, len(cells), points,
                                                                                 100 * estimate), fontsize=9)
            else:
                ax.set_xlim(window[0], window[1])
                ax.set_ylim(window[2], window[3])
                ax.set_title("step %d near the contact" % step, fontsize=9)
            ax.tick_params(labelsize=7)
    fig.colorbar(collection, ax=axes[:, 1].tolist(), label="error indicator of the cell", shrink=0.6)
    fig.savefig(args.png, dpi=args.dpi)
    print("wrote %s (%d steps)" % (args.png, len(data)))


if __name__ == "__main__":
    main()
