"""The two engines side by side: run a scene's LIGGGHTS deck (in.liggghts,
the project's plugin models) and its LAMMPS deck (in.lammps, the project's
GRANULAR sub-models), each writing the same columns every step into
out.txt, and compare them row by row. Used by the check_<scene>.py beside
it; the regression helpers (tests/regression/regress.py) do the checks'
bookkeeping."""
import math
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "regression"))
import regress  # noqa: E402  (Checks, start, table)

ROOT = regress.ROOT
LIGGGHTS = regress.LIGGGHTS
LMP = os.environ.get("DC_LMP", os.path.join(ROOT, "build", "lammps", "lmp"))
start, table, Checks = regress.start, regress.table, regress.Checks


def run(engine, deck, workdir, ranks=1, variables=None, tag="run", expect_error=False):
    """Runs deck (a path, or a name under tests/engines) with engine
    ('liggghts' or 'lammps') in workdir/tag; returns (the folder, the log
    text), or with expect_error (exit code, screen output + log)."""
    d = os.path.join(workdir, tag)
    os.makedirs(d, exist_ok=True)
    deck_path = deck if os.path.isabs(deck) else os.path.join(HERE, deck)
    exe = LIGGGHTS if engine == "liggghts" else LMP
    cmd = [exe, "-in", deck_path, "-log", "log.run"]
    if engine == "lammps":
        cmd += ["-nocite"]
    for k, v in (variables or {}).items():
        cmd += ["-var", k, str(v)]
    if ranks > 1:
        extra = ["--oversubscribe"] if (os.cpu_count() or 1) < ranks else []
        cmd = ["mpirun", "-np", str(ranks)] + extra + cmd
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    p = subprocess.run(cmd, cwd=d, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                       errors="replace")
    log_path = os.path.join(d, "log.run")
    log = open(log_path, errors="replace").read() if os.path.exists(log_path) else ""
    if expect_error:
        return p.returncode, p.stdout + log
    if p.returncode != 0:
        print(p.stdout[-3000:])
        raise SystemExit("FAIL %s exited with %d (%s)" % (engine, p.returncode, " ".join(cmd)))
    return d, log


def out(folder, name="out.txt"):
    """A run's rows (first column the time). LAMMPS' fix print also writes
    each run's set-up row, LIGGGHTS' does not: rows at time 0 and a second
    row of the same time (a later run's set-up) are left out."""
    seen, rows = {0.0}, []
    for r in table(os.path.join(folder, name)):
        if r[0] not in seen:
            seen.add(r[0])
            rows.append(r)
    return rows


def dump(folder, natoms, name="forces.dump"):
    """The snapshots of a `dump custom` whose first column is the atom id
    (sorted by id): per snapshot, the natoms rows without the id."""
    steps, lines = [], open(os.path.join(folder, name)).read().split("\n")
    for k, line in enumerate(lines):
        if line.startswith("ITEM: ATOMS"):
            steps.append([[float(x) for x in a.split()[1:]] for a in lines[k + 1:k + 1 + natoms]])
    return steps


def compare(checks, got, want, what, tol=1e-10, floor=1e-6, columns=None, names=None):
    """Row by row: |got - want| <= tol max(|want|, floor max|want column|)
    in every column (or the listed ones): per step relative, with a floor
    where a column passes through zero. Reports the worst row."""
    if len(got) != len(want) or not want:
        checks.true(False, "%s: %d rows, the other engine %d" % (what, len(got), len(want)))
        return
    cols = columns if columns is not None else range(len(want[0]))
    worst, where = 0.0, None
    for c in cols:
        big = max(abs(r[c]) for r in want)
        for k, (g, w) in enumerate(zip(got, want)):
            scale = max(abs(w[c]), floor * big) or 1.0
            e = abs(g[c] - w[c]) / scale
            if not math.isfinite(g[c]) or e > worst:
                worst, where = (math.inf if not math.isfinite(g[c]) else e), (k, c)
    label = "" if where is None else " (row %d, column %s)" % (where[0], names[where[1]] if names else where[1])
    checks.true(worst <= tol, "%s: worst per-step relative difference %.3g%s (tol %.3g, %d rows)"
                % (what, worst, label, tol, len(want)))
    return worst


def side_by_side(checks, scene, workdir, lig, lmp, tag, what, **kw):
    """Runs scene/in.liggghts with the variables lig and scene/in.lammps
    with lmp (folders liggghts_TAG, lammps_TAG) and compares their out.txt
    (compare's keywords); returns (the LIGGGHTS rows, the LAMMPS rows, the
    worst difference)."""
    dg, _ = run("liggghts", scene + "/in.liggghts", workdir, variables=lig, tag="liggghts_" + tag)
    dl, _ = run("lammps", scene + "/in.lammps", workdir, variables=lmp, tag="lammps_" + tag)
    g, l = out(dg), out(dl)
    return g, l, compare(checks, l, g, what, **kw)
