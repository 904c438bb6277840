#!/usr/bin/env python3
"""Draws dclaw tables against overlap (or displacement, creepage) into a PNG; `dclaw plot` (plot.c) runs
it with, on stdin, for each law a line '# <law> <keys>' and then the CSV table
`dclaw <law> <keys>` prints.

A curve is a column named after its quantity, alone or with a suffix naming
the variant (gw_rough: force_feng_table), drawn against the column delta
(cmd_tangential: u, kalker: xi) in row order (jamari_ep's load-unload-reload
cycle and cmd_tangential's loop stay cycles). Each curve
keeps its colour in every panel and its law's line style; the legend names
the law, its keys and the variant."""
import argparse
import collections
import csv
import sys

# quantity: the column names that hold it (gw_rough calls its stiffness kn),
# and its axis label
QUANTITIES = {
    "force": (("force",), "normal force F [N]"),
    "area": (("area",), "contact area A [m$^2$]"),
    "stiffness": (("stiffness", "kn"), r"normal stiffness dF/d$\delta$ [N/m]"),
    "tangential": (("Ft",), "tangential force F$_t$ [N]"),
    "creep": (("Fx",), "longitudinal creep force F$_x$ [N]"),
}
# the column a table is drawn against (the first its header has), and its axis label
X_COLUMNS = (("delta", r"overlap $\delta$ [m]"), ("u", "tangential displacement u [m]"),
             ("xi", r"longitudinal creepage $\xi$ [-]"))
LINE_STYLES = ("-", "--", ":", "-.")
# one column of one law's table against its delta column; law is the law's index
Curve = collections.namedtuple("Curve", "quantity label column x y law")


def fail(message):
    """Reports a dclaw plot error and exits 2, as dclaw does on bad input."""
    print("dclaw plot: " + message, file=sys.stderr)
    sys.exit(2)


def read_tables(lines):
    """[(law and keys, header, rows of floats)] of the stream dclaw plot writes."""
    tables = []
    for line in lines:
        if line.startswith("#"):
            tables.append((line[1:].strip(), None, []))
        elif tables[-1][1] is None:
            tables[-1] = (tables[-1][0], line.strip().split(","), [])
        else:
            tables[-1][2].append([float(x) for x in line.split(",")])
    return tables


def variant(column, names):
    """'' if column is one of names, the suffix if it is <name>_<suffix>, else None."""
    for name in names:
        if column == name:
            return ""
        if column.startswith(name + "_"):
            return column[len(name) + 1:]
    return None


def x_column(law, header):
    """The column a table is drawn against."""
    for name, _ in X_COLUMNS:
        if name in header:
            return name
    fail("%s: its table has no %s column to plot against (%s)" % (law, ", ".join(n for n, _ in X_COLUMNS),
                                                                   ",".join(header)))


def curves(tables, quantities):
    """The Curves of quantities in the tables, and the column they are drawn against."""
    out, xs = [], set()
    for index, (law, header, rows) in enumerate(tables):
        xname = x_column(law, header)
        xs.add(xname)
        if len(xs) > 1:
            fail("the laws' tables are drawn against different columns (%s): plot them apart" % ", ".join(sorted(xs)))
        x = [r[header.index(xname)] for r in rows]
        found = 0
        for q in quantities:
            for j, column in enumerate(header):
                v = variant(column, QUANTITIES[q][0])
                if v is not None:
                    label = "%s (%s)" % (law, v) if v else law
                    out.append(Curve(q, label, column, x, [r[j] for r in rows], index))
                    found += 1
        if not found:
            fail("%s: its table has no %s column (%s)" % (law, " or ".join(quantities), ",".join(header)))
    return out, xs.pop()


def load_pyplot():
    """matplotlib's pyplot on the file-only Agg backend, or an error naming the Debian package."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError as e:
        fail("%s has no matplotlib (%s): install the Debian package python3-matplotlib" % (sys.executable, e))
    return plt


def draw(plt, series, quantities, xname):
    """The figure, one panel per quantity drawn sharing the axis of column
    xname and one legend below, and [(label, column, line)] of the lines."""
    quantities = [q for q in quantities if any(c.quantity == q for c in series)]
    fig, axes = plt.subplots(len(quantities), 1, sharex=True, squeeze=False, figsize=(7.5, 0.8 + 2.6 * len(quantities)))
    colours, drawn = {}, []
    for ax, q in zip(axes[:, 0], quantities):
        for c in series:
            if c.quantity == q:
                colour = colours.setdefault(c.label, "C%d" % (len(colours) % 10))
                line, = ax.plot(c.x, c.y, LINE_STYLES[c.law % len(LINE_STYLES)], color=colour,
                                marker="o" if len(c.x) == 1 else None)
                drawn.append((c.label, c.column, line))
        ax.set_ylabel(QUANTITIES[q][1])
        ax.grid(True, alpha=0.3)
    axes[-1, 0].set_xlabel(dict(X_COLUMNS)[xname])
    handles = {}
    for label, _, line in drawn:
        handles.setdefault(label, line)
    fig.tight_layout()
    fig.legend(handles.values(), handles.keys(), loc="upper center", bbox_to_anchor=(0.5, 0.0), fontsize="small")
    return fig, drawn


def write_csv(path, drawn, xname):
    """The data of the lines drawn, as label,column,<x column>,value rows."""
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["label", "column", xname, "value"])
        for label, column, line in drawn:
            w.writerows([label, column, repr(float(x)), repr(float(y))] for x, y in zip(line.get_xdata(), line.get_ydata()))


def written(path, write):
    """Runs write(path); an OSError becomes an error naming path."""
    try:
        write(path)
    except OSError as e:
        fail("cannot write %s: %s" % (path, e.strerror or e))


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--png", required=True)
    p.add_argument("--y", choices=list(QUANTITIES) + ["all"], default="all")
    p.add_argument("--csv")
    a = p.parse_args()
    quantities = list(QUANTITIES) if a.y == "all" else [a.y]
    plt = load_pyplot()
    series, xname = curves(read_tables(sys.stdin), quantities)
    fig, drawn = draw(plt, series, quantities, xname)
    if a.csv:
        written(a.csv, lambda path: write_csv(path, drawn, xname))
    written(a.png, lambda path: fig.savefig(path, format="png", dpi=100, bbox_inches="tight"))


main()
