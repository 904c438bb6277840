#!/usr/bin/env python3
"""LIGGGHTS scenes of the speed-versus-error report (tests/bench/report.sh).

Runs each configuration below with build/bin/liggghts, all of them
round-robin REPS times (a slow spell of the shared machine hits every one
alike), keeps each one's fastest loop time, and writes a CSV with, for each
law of a family, its whole-run time as a ratio to stock `hertz` (with
stock `tangential history`) on the same scene and, on the settling packing,
its packing density and coordination number against the reference,
hertz_elliptic with cmd_tangential. The normal laws run with `tangential
history`, the tangential laws with hertz_elliptic, as a deck would use them.

Columns: family,scene,law,kernel_law,exact,run_ratio,error,metric,note
scene is empty for a timing entry (its ratio goes to the kernel rows of the
same family and law); the packing rows carry their own error, and
kernel_law names the kernel row whose ns per call they share.
A configuration whose run fails (e.g. a model not in this build) is left
out with a message on stderr.

Usage: report_scenes.py LIGGGHTS CALIBRATION OUT_CSV WORK_DIR REPS
CALIBRATION: the fitted coefficients bench_report_impact wrote."""
import csv
import os
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
SPHERES = os.path.join(HERE, "in.report_spheres")
SUPERQ = os.path.join(HERE, "in.report_superquadrics")
BOX = 0.049          # side of in.report_spheres' box [m]
PACKING = "settling packing (LIGGGHTS; 1352 spheres)"

# run key -> (deck, LIGGGHTS -var pairs); {A} {eta} {S} {vchar} from the
# calibration. The runs that are only timed take 10000 steps (as
# tests/bench/bench_scenes.sh), the packings 15000 (the bed settles).


def timed(deck, **var):
    return deck, dict(var, steps="10000")


def packed(**var):
    return SPHERES, dict(var, steps="15000")


CURVATURE = "curvatureLimitFactor 100 %sCurvature yes"
RUNS = {
    "sq_hertz": timed(SUPERQ, model="hertz"),
    "sq_mean": timed(SUPERQ, model="hertz", settings=CURVATURE % "mean"),
    "sq_gauss": timed(SUPERQ, model="hertz", settings=CURVATURE % "gaussian"),
    "sq_elliptic": timed(SUPERQ, model="hertz_elliptic"),
    # contact distance 1.12: the reach of gw_adhesion, (D + 8) sigma = 8.1 sigma, against walls
    "hertz_112": timed(SPHERES, model="hertz", cdf="1.12"),
    "gw_table": timed(SPHERES, model="gw_rough", cdf="1.12"),
    "gw_feng": timed(SPHERES, model="gw_rough", cdf="1.12", settings="roughSphereLaw feng"),
    "gw_fitted": timed(SPHERES, model="gw_rough", cdf="1.12", settings="roughSphereLaw feng fengFitted on"),
    "gw_closed": timed(SPHERES, model="gw_rough", cdf="1.12", settings="gwElliptic on"),
    "gw_adhesion": timed(SPHERES, model="gw_rough", cdf="1.12", tmodel="history cohesion gw_adhesion",
                         settings="gwElliptic on"),
    "hertz_102": timed(SPHERES, model="hertz", cdf="1.02"),
    "jkr": timed(SPHERES, model="jkr_elliptic", cdf="1.02"),
    "dmt": timed(SPHERES, model="jkr_elliptic", cdf="1.02", settings="tangential_damping on adhesionLaw dmt"),
    "maugis": timed(SPHERES, model="jkr_elliptic", cdf="1.02", settings="tangential_damping on adhesionLaw maugis"),
    "hertz": packed(model="hertz"),
    # the same law on another jittered lattice: the resolution of the packing figures
    "hertz_seed": packed(model="hertz", seed="15485863"),
    "reference": packed(model="hertz_elliptic", tmodel="cmd_tangential"),
    # the reference on another jittered lattice: the packing figures' spread under the exact law
    "reference_seed": packed(model="hertz_elliptic", tmodel="cmd_tangential", seed="15485863"),
    "turning_points": packed(model="hertz_elliptic", tmodel="cmd_tangential",
                             settings="tangential_damping on cmdMemory turningPoints"),
}
for d in ("tsuji", "viscoelastic", "kuwabaraKono", "none"):
    RUNS["damp_" + d] = packed(model="hertz_elliptic", settings="damping " + d, A="{A}", eta="{eta}")
CLASSICAL = [("lsd", "duration"), ("lsd", "overlap"), ("lsd", "energy"),
             ("hlsConstant", "duration"), ("hlsConstant", "overlap"), ("hlsVariable", "overlap")]
for law, k in CLASSICAL:
    RUNS["%s_%s" % (law, k)] = packed(model="classical", settings="classicalNormal %s classicalStiffness %s" % (law, k),
                                      S="{S}", vchar="{vchar}")
# rough tangential: gw_rough gwElliptic on + cmd_tangential with and without the summits' stiffness
RUNS["gw_closed_cmd"] = timed(SPHERES, model="gw_rough", cdf="1.12", tmodel="cmd_tangential", settings="gwElliptic on")
RUNS["gw_closed_rough"] = timed(SPHERES, model="gw_rough", cdf="1.12", tmodel="cmd_tangential",
                                settings="gwElliptic on tangentialRoughness on")
for t in ("springSliding", "diRenzo", "langston", "incremental", "coulomb"):
    RUNS["t_" + t] = packed(model="hertz_elliptic", tmodel="classical", settings="classicalTangential " + t)

# (family, law, kernel law or None for the same, run, baseline run, packing reference run or None);
# the laws are those of the kernel programs' rows
ROWS = [
    ("superquadric", "stock hertz: volume-equivalent radius", None, "sq_hertz", "sq_hertz", None),
    ("superquadric", "stock hertz: mean-curvature radius", None, "sq_mean", "sq_hertz", None),
    ("superquadric", "stock hertz: Gaussian-curvature radius", None, "sq_gauss", "sq_hertz", None),
    ("superquadric", "hertz_elliptic (exact)", None, "sq_elliptic", "sq_hertz", None),
    ("rough", "tabulated GW law (gw_rough default)", None, "gw_table", "hertz_112", None),
    ("rough", "Feng law: table coefficients", None, "gw_feng", "hertz_112", None),
    ("rough", "Feng law: fitted coefficients", None, "gw_fitted", "hertz_112", None),
    ("rough", "GW closed form (Eq. 33; n_asp = 1)", None, "gw_closed", "hertz_112", None),
    ("adhesion", "jkr_elliptic (hint carried)", None, "jkr", "hertz_102", None),
    ("adhesion", "adhesionLaw dmt (DMT)", None, "dmt", "hertz_102", None),
    ("adhesion", "adhesionLaw maugis (Maugis-Dugdale)", None, "maugis", "hertz_102", None),
    ("adhesion", "gw_adhesion table + GW closed form", None, "gw_adhesion", "hertz_112", None),
    ("classical normal", "hertz_elliptic + cmd_tangential (reference)", "hertz: restitution damping", "reference",
     "hertz", "reference"),
    ("classical normal", "hertz: restitution damping", None, "hertz", "hertz", "reference"),
    ("classical normal", "hertz: restitution damping (other jitter seed)", "hertz: restitution damping",
     "hertz_seed", "hertz", "reference"),
    ("classical normal", "hertz: tsuji damping", None, "damp_tsuji", "hertz", "reference"),
    ("classical normal", "hertz: viscoelastic damping (A fitted)", None, "damp_viscoelastic", "hertz", "reference"),
    ("classical normal", "hertz: kuwabaraKono damping (eta fitted)", None, "damp_kuwabaraKono", "hertz", "reference"),
    ("classical normal", "hertz: no damping", None, "damp_none", "hertz", "reference"),
] + [
    ("classical normal", "%s: stiffness %s%s" % (law, k, " (S fitted)" if law == "hlsVariable" else ""), None,
     "%s_%s" % (law, k), "hertz", "reference") for law, k in CLASSICAL
] + [
    ("tangential", "cmd_tangential", None, "reference", "hertz", "reference"),
    ("tangential", "cmd_tangential (other jitter seed)", "cmd_tangential", "reference_seed", "hertz", "reference"),
    ("tangential", "cmd_tangential cmdMemory turningPoints", None, "turning_points", "hertz", "reference"),
    ("tangential", "stock tangential history", "springSliding: Mindlin K_t (stock history)", "hertz", "hertz",
     "reference"),
    ("tangential", "springSliding: Mindlin K_t (stock history)", None, "t_springSliding", "hertz", "reference"),
    ("tangential", "diRenzo", None, "t_diRenzo", "hertz", "reference"),
    ("tangential", "langston", None, "t_langston", "hertz", "reference"),
    ("tangential", "incremental: Mindlin K0", None, "t_incremental", "hertz", "reference"),
    ("tangential", "coulomb", None, "t_coulomb", "hertz", "reference"),
    ("tangential", "cmd_tangential tangentialRoughness on", None, "gw_closed_rough", "hertz_112", None),
    ("tangential", "cmd_tangential (smooth patch)", None, "gw_closed_cmd", "hertz_112", None),
]


def run(lmp, key, deck, variables, work, rep):
    """Loop time of one run [s], or None if it failed (the error on stderr)."""
    d = os.path.join(work, key)
    os.makedirs(d, exist_ok=True)
    cmd = [lmp, "-in", deck, "-var", "out", "packing.dump", "-log", "log"]
    for name, value in variables.items():
        cmd += ["-var", name, value]
    out = subprocess.run(cmd, cwd=d, capture_output=True, text=True)
    loop = [l for l in out.stdout.split("\n") if l.startswith("Loop time of")]
    if out.returncode == 0 and loop:
        return float(loop[0].split()[3])
    err = [l for l in out.stdout.split("\n") if "ERROR" in l]
    why = err[0] if err else "no loop time"
    sys.stderr.write("report_scenes: %s left out (repetition %d): %s\n" % (key, rep + 1, why))
    return None


def packing(dump):
    """Packing density and mean coordination number of the settled bed,
    away from its boundaries: in the box 1 diameter inside the side walls,
    above the floor and below the bed top (the 95th percentile of the
    spheres' tops). Density: the fraction of a 200^3 point grid of that box
    inside a sphere; coordination: the overlapping neighbours (distance <
    r_i + r_j) of the spheres whose centres lie in it."""
    lines = open(dump).read().split("\n")
    start = next(k for k, l in enumerate(lines) if l.startswith("ITEM: ATOMS")) + 1
    a = np.array([[float(v) for v in l.split()] for l in lines[start:] if l.strip()])
    x, r = a[:, 1:4], a[:, 4]
    d = 2.0 * r.max()
    lo = np.array([d, d, d])
    hi = np.array([BOX - d, BOX - d, np.percentile(x[:, 2] + r, 95) - d])
    n = 200
    h = (hi - lo) / n
    mid = [lo[k] + (np.arange(n) + 0.5) * h[k] for k in range(3)]
    inside = np.zeros((n, n, n), bool)
    for c, rad in zip(x, r):
        i0 = np.maximum(np.floor((c - rad - lo) / h).astype(int), 0)
        i1 = np.minimum(np.ceil((c + rad - lo) / h).astype(int), n)
        if np.any(i1 <= i0):
            continue
        X, Y, Z = np.meshgrid(*[mid[k][i0[k]:i1[k]] - c[k] for k in range(3)], indexing="ij")
        inside[i0[0]:i1[0], i0[1]:i1[1], i0[2]:i1[2]] |= X * X + Y * Y + Z * Z <= rad * rad
    dist = np.sqrt(((x[:, None, :] - x[None, :, :]) ** 2).sum(-1))
    np.fill_diagonal(dist, np.inf)
    contacts = (dist < r[:, None] + r[None, :]).sum(1)
    central = np.all((x >= lo) & (x <= hi), axis=1)
    return inside.mean(), contacts[central].mean()


def main():
    lmp, calibration, out_csv, work, reps = sys.argv[1:6]
    cal = dict(l.split() for l in open(calibration) if l.strip())
    subst = {"A": cal["viscoelasticTime"], "eta": cal["kuwabaraKonoDamping"],
             "S": cal["unloadingStiffnessSlope"], "vchar": cal["characteristicVelocity"]}
    runs = {k: (deck, {n: v.format(**subst) for n, v in var.items()}) for k, (deck, var) in RUNS.items()}
    best, failed = {}, set()
    start = time.time()
    for rep in range(int(reps)):
        for key, (deck, var) in runs.items():
            if key in failed:
                continue
            t = run(lmp, key, deck, var, work, rep)
            if t is None:
                failed.add(key)
                best.pop(key, None)
            else:
                best[key] = min(t, best.get(key, t))
        print("report: LIGGGHTS repetition %d of %s done (%.0f s)" % (rep + 1, reps, time.time() - start), flush=True)
    packings = {r[3] for r in ROWS if r[5]} | {r[5] for r in ROWS if r[5]}
    pack = {k: packing(os.path.join(work, k, "packing.dump")) for k in packings if k in best}
    with open(out_csv, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["family", "scene", "law", "kernel_law", "exact", "run_ratio", "error", "metric", "note"])
        for family, law, kernel, key, base, ref in ROWS:
            if key not in best or base not in best:
                continue
            ratio = "%.4g" % (best[key] / best[base])
            w.writerow([family, "", law, kernel or law, 0, ratio, "", "", ""])
            if ref and ref in pack:
                (phi, z), (phi0, z0) = pack[key], pack[ref]
                err = max(abs(phi / phi0 - 1), abs(z / z0 - 1))
                note = "density %.4f (ref. %.4f); coordination %.3f (ref. %.3f)" % (phi, phi0, z, z0)
                w.writerow([family, PACKING, law, kernel or law, int(key == ref), ratio, "%.4g" % err,
                            "max relative error of packing density and coordination number", note])


if __name__ == "__main__":
    main()
