#!/usr/bin/env python3
"""Smoke test of the speed-versus-error report (tests/bench/report.sh): runs
its kernel programs once (DC_REPORT_REPS=1, a few seconds) and checks their
rows: every cost positive and every error finite; in every scene one exact
law, whose error is 0 or rounding (< 1e-9), below every other law's (but
those exact to rounding too); and figures the headers state: the integrator reproduces the linear laws'
exact restitution, the notes' Tsuji coefficient rebounds within 0.06 % of
e, the tabulated GW law is within its stated 1e-4 of the solver, the
solver converges with m, stock superquadric hertz misses the exact force by
more than 10 %, cmd_tangential's turningPoints equals the exact profile on
the shear cycles (constant load, 3 turning points) and stock history's
spring is 30 % of mu F_n off. Then report_table.py merges the rows (without LIGGGHTS
scenes) into table.csv and table.md.

Usage: check_report.py BENCH_BIN_DIR WORK_DIR"""
import csv
import io
import math
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
PROGRAMS = ["superquadric", "rough", "adhesion", "impact", "shear"]
failed = 0


def check(ok, what):
    global failed
    print("%s %s" % ("ok  " if ok else "FAIL", what))
    failed += not ok


def main():
    bin_dir, work = sys.argv[1:3]
    os.makedirs(work, exist_ok=True)
    env = dict(os.environ, DC_REPORT_REPS="1")
    rows, paths = [], []
    for p in PROGRAMS:
        args = [os.path.join(bin_dir, "bench_report_" + p)]
        if p == "impact":
            args.append(os.path.join(work, "calibration.txt"))
        out = subprocess.run(args, env=env, capture_output=True, text=True)
        check(out.returncode == 0, "bench_report_%s runs (%s)" % (p, out.stderr.strip()))
        paths.append(os.path.join(work, "kernels_%s.csv" % p))
        open(paths[-1], "w").write(out.stdout)
        rows += list(csv.DictReader(io.StringIO(out.stdout)))
    law = {(r["scene"], r["law"]): r for r in rows}

    for r in rows:
        ns, err = float(r["ns_per_call"]), float(r["error"])
        check(ns > 0 and math.isfinite(ns) and math.isfinite(err) and err >= 0,
              "%s / %s: ns %g, error %g" % (r["scene"], r["law"], ns, err))
    for scene in dict.fromkeys(r["scene"] for r in rows):
        sel = [r for r in rows if r["scene"] == scene]
        exact = [r for r in sel if r["exact"] == "1"]
        check(len(exact) == 1 and float(exact[0]["error"]) < 1e-9, "%s: one exact law, error < 1e-9" % scene)
        others = [float(r["error"]) for r in sel if r["exact"] != "1"]
        check(exact and all(e > float(exact[0]["error"]) or e < 1e-9 for e in others),
              "%s: every other law errs more (or is exact to rounding too)" % scene)

    impact = "sphere impacts 0.05-2 m/s e = 0.5"
    for name in ("lsd: stiffness duration", "hlsConstant: stiffness overlap"):
        rebound = float(law[(impact, name)]["note"].split(";")[0].split()[1])
        check(rebound < 1e-6, "%s: restitution e exactly (integrator) %g" % (name, rebound))
    tsuji = float(law[(impact, "hertz: tsuji damping")]["note"].split(";")[0].split()[1])
    check(tsuji < 6e-4, "tsuji damping: rebound within 0.06 %% of e (%g)" % tsuji)
    rough = "rough spheres: alpha' -2.5..100 x mu 1..50"
    check(float(law[(rough, "tabulated GW law (gw_rough default)")]["error"]) < 1e-4, "tabulated GW law within 1e-4")
    e5, e10, e20 = (float(law[(rough, "GW solver m = %d" % m)]["error"]) for m in (5, 10, 20))
    check(e5 > e10 > e20, "GW solver error falls with m: %g %g %g" % (e5, e10, e20))
    sq = "superquadric pairs 1.5:2.5:3.5 mm blockiness 2-4"
    check(float(law[(sq, "stock hertz: volume-equivalent radius")]["error_rms"]) > 0.1,
          "stock hertz misses the elliptic force by more than 10 % (rms)")

    shear = "shear cycles 0.5 and 2 slip distances"
    tp = float(law[(shear, "cmd_tangential cmdMemory turningPoints")]["error"])
    spring = float(law[(shear, "springSliding: Mindlin K_t (stock history)")]["error"])
    check(tp < 1e-12, "turningPoints on the shear cycles (3 turning points, constant load): %g mu F_n of the exact law" % tp)
    check(spring > 0.3, "stock history's spring on the shear cycles: %g mu F_n off (> 0.3)" % spring)

    scenes = os.path.join(work, "scenes.csv")
    open(scenes, "w").write("family,scene,law,kernel_law,exact,run_ratio,error,metric,note\n")
    out = subprocess.run([sys.executable, os.path.join(HERE, "report_table.py"), work, scenes] + paths,
                         capture_output=True, text=True)
    table = list(csv.DictReader(open(os.path.join(work, "table.csv")))) if out.returncode == 0 else []
    check(len(table) == len(rows), "report_table.py: %d rows in table.csv (%s)" % (len(table), out.stderr.strip()))
    print("report smoke test: %d failed" % failed)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
