#!/usr/bin/env python3
"""Plots of the speed-versus-error report (tests/bench/report.sh): for each
family of table.csv one PNG, <family>.png, of error against cost, one
numbered point per law and scene (the numbers listed beside the plot), the
Pareto front of each scene drawn as a step line through the laws that no
cheaper law beats in error. Left: ns per kernel call; right (where LIGGGHTS
runs exist): whole-run time as a ratio to stock hertz. Both axes
logarithmic. Errors more than a decade below the smallest error above 1e-9
(the exact law: 0 or rounding) sit on a floor line, marked by a
down-pointing triangle.

Usage: report_plot.py OUT_DIR (reads OUT_DIR/table.csv)"""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after the backend)
import matplotlib.ticker  # noqa: E402

STYLES = [("tab:blue", "o"), ("tab:orange", "s"), ("tab:green", "D"), ("tab:red", "^")]


def pareto(points):
    """The points (cost, error) that no cheaper-or-equal point beats in error."""
    front, best = [], float("inf")
    for c, e in sorted(points):
        if e < best:
            front.append((c, e))
            best = e
    return front


def panel(ax, rows, number, cost_key, xlabel, floor):
    scenes = list(dict.fromkeys(r["scene"] for r in rows if r[cost_key]))
    for (colour, marker), scene in zip(STYLES, scenes):
        sel = [r for r in rows if r["scene"] == scene and r[cost_key]]
        pts = [(float(r[cost_key]), max(float(r["error"]), floor)) for r in sel]
        for r, (c, e) in zip(sel, pts):
            low = float(r["error"]) < floor
            ax.scatter([c], [e], color=colour, marker="v" if low else marker, s=36, zorder=3,
                       edgecolors="black" if r["exact"] == "1" else "none")
            ax.annotate(str(number[r["law"]]), (c, e), xytext=(4, 3), textcoords="offset points", fontsize=8)
        front = pareto(pts)
        xs, ys = [front[0][0]], [front[0][1]]
        for c, e in front[1:]:
            xs += [c, c]
            ys += [ys[-1], e]
        ax.plot(xs, ys, color=colour, lw=1.2, alpha=0.8)
        ax.plot([], [], color=colour, marker=marker, label=scene + " (line: Pareto front)")
    ax.axhline(floor, color="0.5", lw=0.8, ls=":", label="floor: error below %.0e (exact law)" % floor)
    ax.set_xscale("log")
    ax.set_yscale("log")
    plain = matplotlib.ticker.FuncFormatter(lambda v, _: "%g" % v)
    ax.xaxis.set_major_formatter(plain)
    lo, hi = ax.get_xlim()
    # label the minor ticks only when the axis spans less than two decades
    ax.xaxis.set_minor_formatter(plain if hi < 100 * lo else matplotlib.ticker.NullFormatter())
    ax.set_xlabel(xlabel)
    ax.set_ylabel("error (metric per scene: table.md)")
    ax.grid(True, which="major", alpha=0.3)
    ax.legend(fontsize=7.5, loc="upper center", bbox_to_anchor=(0.5, -0.13))


def main():
    out_dir = sys.argv[1]
    with open(out_dir + "/table.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    for family in dict.fromkeys(r["family"] for r in rows):
        sel = [r for r in rows if r["family"] == family]
        number = {law: k + 1 for k, law in enumerate(dict.fromkeys(r["law"] for r in sel))}
        meaningful = [float(r["error"]) for r in sel if float(r["error"]) > 1e-9]
        floor = 10.0 ** (math.floor(math.log10(min(meaningful))) - 1) if meaningful else 1e-10
        timed = any(r["run_ratio"] for r in sel)
        ncol = 2 if timed else 1
        fig, axes = plt.subplots(1, ncol, figsize=(6.2 * ncol + 4.3, 6.4), squeeze=False)
        panel(axes[0][0], sel, number, "ns_per_call", "cost: ns per kernel call (c_core)", floor)
        if timed:
            panel(axes[0][1], sel, number, "run_ratio", "cost: LIGGGHTS whole-run time / stock hertz", floor)
        laws = "\n".join("%2d  %s" % (n, law) for law, n in number.items())
        fig.text(1.0 - 4.1 / (6.2 * ncol + 4.3), 0.9, "laws (edged: exact law)\n\n" + laws, fontsize=8,
                 va="top", family="monospace")
        fig.suptitle("speed against error: %s" % family)
        fig.tight_layout(rect=(0, 0, 1.0 - 4.2 / (6.2 * ncol + 4.3), 0.96))
        fig.savefig("%s/%s.png" % (out_dir, family.replace(" ", "_")), dpi=100)
        plt.close(fig)


if __name__ == "__main__":
    main()
