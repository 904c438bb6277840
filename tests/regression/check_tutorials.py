#!/usr/bin/env python3
"""LIGGGHTS' own tutorial decks (examples/LIGGGHTS/Tutorials_public of the
LIGGGHTS source the build fetches), which this project did not write, run
unmodified apart from shortened `run` commands, with stock models and with
the project's models substituted on every pair_style gran and wall/gran
line (hertz -> hertz_elliptic with cmd_tangential, and with cmd_tangential
and rolling_friction kalker; the deck's cohesion model stays). Each must
complete (every `run`, several per deck), with `dump custom/vtk` writing
files that VTK reads (legacy .vtk), finite thermo output, no lost atoms
beyond stock's, and end kinetic and rotational energies within a factor
FACTOR of stock's (the models differ in physics: Mindlin's tangential
stiffness, and Kalker's creep force on rolling contacts, so the energies
of a shortened, unsettled run differ; a NaN, a blow-up or a bed left
moving by chatter is orders of magnitude off).
Usage: check_tutorials.py WORKDIR"""
import math
import os
import re
import shutil
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from regress import ROOT, run, start  # noqa: E402

work, _, c = start()
TUT = os.path.join(ROOT, ".deps", "liggghts-3.8.0", "examples", "LIGGGHTS", "Tutorials_public")
FACTOR = 4.0
# tutorial folder, deck, steps of each shortened run (after the first `run 1`)
TUTORIALS = [("packing", "in.packing", 3000), ("cohesion", "in.cohesion", 12000),
             ("heatTransfer_1", "in.heatGran", 3000), ("conveyor", "in.conveyor", 30000)]
# the replacement of `model hertz tangential history [cohesion X]` (\1: the cohesion part)
VARIANTS = [("stock", None),
            ("hertz_elliptic + cmd_tangential", r"model hertz_elliptic tangential cmd_tangential\1"),
            ("hertz_elliptic + cmd_tangential + kalker",
             r"model hertz_elliptic tangential cmd_tangential\1 rolling_friction kalker")]


def prepare(folder, deck, steps, model, dest):
    """The tutorial copied to dest with its runs shortened and, for model,
    `model hertz tangential history` replaced; returns the deck's name."""
    if os.path.exists(dest):
        shutil.rmtree(dest)
    shutil.copytree(os.path.join(TUT, folder), dest)
    text = open(os.path.join(dest, deck)).read()
    # run N [upto] -> run min(N, steps): every run of the deck stays, shorter
    text = re.sub(r"^(\s*run\s+)(\S+)(\s+upto)?", lambda m: m.group(1) + ("1" if m.group(2) == "1" else str(steps)),
                  text, flags=re.M)
    if model:
        text, n = re.subn(r"model\s+hertz\s+tangential\s+history((?:\s+cohesion\s+\S+)?)", model, text)
        assert n > 0, "no stock model line in %s" % deck
    open(os.path.join(dest, deck), "w").write(text)
    os.makedirs(os.path.join(dest, "post"), exist_ok=True)
    return deck


def thermo(log):
    """The thermo rows (step atoms ke c_rke ...) of a log, as floats."""
    rows = []
    for line in log.splitlines():
        w = line.split()
        if len(w) >= 4 and re.fullmatch(r"\d+", w[0]) and re.fullmatch(r"\d+", w[1]):
            try:
                rows.append([float(x) for x in w])
            except ValueError:
                pass
    return rows


def vtk_files_read(post):
    """Number of legacy VTK files in post and whether each parses: header,
    POINTS n, n coordinate triples, POINT_DATA n."""
    files = [f for f in os.listdir(post) if f.endswith(".vtk")]
    good = 0
    for f in files:
        lines = open(os.path.join(post, f)).read().split("\n")
        try:
            n = int(lines[4].split()[1])
            pts = [float(v) for l in lines[5:5 + n] for v in l.split()]
            good += lines[0].startswith("# vtk DataFile") and len(pts) == 3 * n and \
                all(math.isfinite(v) for v in pts) and ("POINT_DATA %d" % n) in lines
        except (IndexError, ValueError):
            pass
    return len(files), good


for folder, deck, steps in TUTORIALS:
    ref = None
    for name, model in VARIANTS:
        dest = os.path.join(work, folder, re.sub(r"\W+", "_", name))
        prepare(folder, deck, steps, model, dest)
        code, out = run(os.path.join(dest, deck), dest, tag="run", expect_error=True)
        log = open(os.path.join(dest, "log.run"), errors="replace").read() if os.path.exists(
            os.path.join(dest, "log.run")) else ""
        rows = thermo(log)
        what = "%s (%s)" % (folder, name)
        nruns = len(re.findall(r"^\s*run\s", open(os.path.join(dest, deck)).read(), re.M))
        done = log.count("Loop time of")
        ok = code == 0 and done == nruns and rows
        if not ok:
            print(out[-2000:])
        c.true(ok, "%s: completes, %d of %d runs (exit %d)" % (what, done, nruns, code))
        if not ok:
            continue
        finite = all(math.isfinite(v) for r in rows for v in r)
        nfiles, good = vtk_files_read(os.path.join(dest, "post"))
        c.true(finite and nfiles > 0 and good == nfiles,
               "%s: finite thermo output (%d rows); dump custom/vtk wrote %d files, %d read back"
               % (what, len(rows), nfiles, good))
        end = rows[-1]
        if ref is None:
            ref = end
            print("     %s: end of stock run: step %d, %d atoms, ke %.4g, rotational %.4g"
                  % (folder, end[0], end[1], end[2], end[3]))
            continue
        ratios = [end[k] / ref[k] if ref[k] > 0 else (1.0 if end[k] == 0 else math.inf) for k in (2, 3)]
        c.true(end[1] >= ref[1] and all(1 / FACTOR <= r <= FACTOR for r in ratios),
               "%s: end energies kinetic %.4g, rotational %.4g: %.3g and %.3g of stock's (within a factor %g), "
               "%d atoms (stock %d)" % (what, end[2], end[3], ratios[0], ratios[1], FACTOR, end[1], ref[1]))
c.finish()
