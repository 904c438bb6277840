#!/usr/bin/env bash
# Side-by-side check of jkr_elliptic / hertz_elliptic (our LIGGGHTS build)
# against LAMMPS's pair_style granular (jkr, hertz/material): two spheres
# head-on (in.liggghts, in.lammps), no damping, several impact speeds
# around the critical sticking speed; then one restitution-damped case.
# Prints the comparison table (doc/peers.md explains it).
# Not part of the test suite (tests/engines holds the checks of the two
# engines). LAMMPS: the project's build (build/lammps/lmp, plugin/setup.sh)
# or LMP; without either the LAMMPS columns are skipped.
# Usage: run.sh [WORKDIR]   (default: a temporary folder)
# Env: DC_LIGGGHTS (default build/bin/liggghts), LMP (default build/lammps/lmp, else lmp).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../.." && pwd)
export DC_LIGGGHTS=${DC_LIGGGHTS:-$root/build/bin/liggghts}
default_lmp=lmp
[ -x "$root/build/lammps/lmp" ] && default_lmp=$root/build/lammps/lmp
export LMP=${LMP:-$default_lmp}
[ -x "$DC_LIGGGHTS" ] || { echo "run.sh: no LIGGGHTS at $DC_LIGGGHTS (run plugin/setup.sh)" >&2; exit 1; }
if ! command -v "$LMP" >/dev/null 2>&1; then
  echo "run.sh: '$LMP' not found: LAMMPS not built (plugin/setup.sh), its columns are skipped"
  export LMP=""
fi
work=${1:-$(mktemp -d)}
mkdir -p "$work"
echo "run.sh: runs in $work"
exec python3 - "$here" "$work" <<'PY'
import math, os, subprocess, sys

here, work = sys.argv[1], sys.argv[2]
LIG, LMP = os.environ["DC_LIGGGHTS"], os.environ["LMP"]

# the scene (both decks)
r, rho, Y, nu, w = 1e-3, 2500.0, 5e6, 0.3, 0.05
R = r / 2
Es = 1.0 / (2.0 * (1 - nu ** 2) / Y)             # E* (LAMMPS: E_eff)
ms = rho * 4.0 / 3.0 * math.pi * r ** 3 / 2       # m* (LAMMPS: m_eff)
Fc = 1.5 * math.pi * w * R                        # load-controlled pull-off force

# classical JKR in parametric form (contact radius a)
F = lambda a: 4 * Es * a ** 3 / (3 * R) - math.sqrt(8 * math.pi * w * Es * a ** 3)
ddel = lambda a: 2 * a / R - 0.5 * math.sqrt(2 * math.pi * w / (Es * a))
dlt = lambda a: a * a / R - math.sqrt(2 * math.pi * w * a / Es)
a0 = (2 * math.pi * w * R ** 2 / Es) ** (1 / 3)        # delta = 0
ab = (math.pi * w * R ** 2 / (8 * Es)) ** (1 / 3)      # vertical tangent: overlap-control separation
ap = (9 * math.pi * w * R ** 2 / (8 * Es)) ** (1 / 3)  # force minimum -Fc: where LAMMPS's jkr lets go


def work_on(lo, hi, n=20000):
    """integral of F d(delta) from a = lo to hi (Simpson)"""
    h = (hi - lo) / n
    return sum((1 if k in (0, n) else 4 if k % 2 else 2) * F(lo + k * h) * ddel(lo + k * h) for k in range(n + 1)) * h / 3


vs = math.sqrt(-2 * work_on(ab, a0) / ms)     # ours: W from delta = 0 to delta_break
vsL = math.sqrt(-2 * work_on(ap, a0) / ms)    # LAMMPS: W from delta = 0 to delta_pulloff


def jkr_dmax(v):
    """largest overlap of the JKR impact at relative speed v (energy balance from delta = 0)"""
    lo, hi = a0, 10 * a0
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if work_on(a0, mid, 2000) < 0.5 * ms * v * v else (lo, mid)
    return dlt(0.5 * (lo + hi))


hertz_dmax = lambda v: (15 * ms * v * v / (16 * Es * math.sqrt(R))) ** 0.4


def run(code, v, wv, model, damp=None, n=40000):
    """One run; returns (rows of time x1 x2 vx1 vx2 fx1) or None if the code is missing."""
    tag = "%s_%s_v%.9g_w%g%s" % (code, model.replace("/", "-"), v, wv, "" if damp is None else "_%s%.6g" % damp)
    d = os.path.join(work, tag)
    os.makedirs(d, exist_ok=True)
    if code == "ours":
        cmd = [LIG, "-in", os.path.join(here, "in.liggghts"), "-var", "model", model,
               "-var", "w", repr(wv), "-var", "e", "1.0" if damp is None else repr(damp[1])]
    else:
        if not LMP:
            return None
        cmd = [LMP, "-in", os.path.join(here, "in.lammps"), "-var", "model", model, "-var", "g", repr(wv / 2)]
        if damp is not None:
            cmd += ["-var", "dmodel", damp[0], "-var", "damp", repr(damp[1])]
    cmd += ["-var", "v", repr(v), "-var", "n", str(n), "-log", "log.run"]
    p = subprocess.run(cmd, cwd=d, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, errors="replace")
    if p.returncode != 0:
        sys.exit("%s failed (%s):\n%s" % (code, " ".join(cmd), p.stdout[-2000:]))
    rows = []
    with open(os.path.join(d, "out.txt")) as f:
        for line in f:
            if line.strip() and not line.startswith("#"):
                rows.append([float(x) for x in line.split()])
    return rows


def measure(rows, v):
    """e (rebound speed / v, 0 if stuck), stuck, largest tension, tension at the last contact step, largest overlap"""
    if rows is None:
        return None
    last = rows[-1]
    stuck = last[5] != 0.0
    vout = last[4] - last[3]                 # vx2 - vx1 > 0: separating (pair on the x axis)
    tens = max(rw[5] for rw in rows)        # fx1 > 0: pulling particle 1 (left) to the right
    lastc = [rw[5] for rw in rows if rw[5] != 0.0]
    dmax = max(2 * r - (rw[2] - rw[1]) for rw in rows)
    return dict(e=0.0 if stuck else vout / v, stuck=stuck, tmax=tens, tlast=lastc[-1] if lastc else 0.0, dmax=dmax)


def crit(code):
    """critical sticking speed by bisection between 0.3 v_s (sticks) and 1.25 v_s (rebounds)"""
    lo, hi = 0.3 * vs, 1.25 * vs
    if code == "lmp" and not LMP:
        return None
    for _ in range(12):
        mid = 0.5 * (lo + hi)
        m = measure(run(code, mid, w, "jkr_elliptic" if code == "ours" else "jkr", n=60000), mid)
        lo, hi = (mid, hi) if m["stuck"] else (lo, mid)
    return 0.5 * (lo + hi)


rel = lambda a, b: (a - b) / b if b else float("nan")
fmt = lambda x: "-" if x is None else ("%.6g" % x)
na = lambda m, k: None if m is None else m[k]

print("scene: r = %g m, rho = %g, E = %g, nu = %g, w = %g J/m^2 (LAMMPS gamma = w/2 = %g), dt = 1e-7 s"
      % (r, rho, Y, nu, w, w / 2))
print("E* = %.6g Pa, R = %g m, m* = %.6g kg, F_c = 3/2 pi w R = %.6g N, 5/6 pi w R = %.6g N"
      % (Es, R, ms, Fc, 5 / 9 * Fc))
print("theory v_s (from delta = 0 to delta_break, jkr_elliptic's breakage) = %.6g m/s" % vs)
print("theory v_s (from delta = 0 to delta_pulloff, LAMMPS jkr's breakage)  = %.6g m/s (%.4f v_s)" % (vsL, vsL / vs))
print("delta_break = %.6g m, delta_pulloff = %.6g m" % (dlt(ab), dlt(ap)))
print()
print("1. JKR, no damping (ours: jkr_elliptic, coefficientRestitution 1; LAMMPS: jkr, damping velocity 0.0)")
print("%6s %10s | %9s %9s %9s %9s | %9s %9s %9s | %10s %10s | %10s %10s | %11s %11s %11s"
      % ("v/v_s", "v [m/s]", "e ours", "e LAMMPS", "e th.ours", "e th.LMP", "rel ours", "rel LMP", "L-o / o",
         "Tmax o/Fc", "Tmax L/Fc", "Tlast o/Fc", "Tlast L/Fc", "dmax ours", "dmax LAMMPS", "dmax theory"))
res = {}
for k in (0.5, 0.8, 1.0, 1.25, 2.0, 4.0):
    v = k * vs
    o = measure(run("ours", v, w, "jkr_elliptic"), v)
    L = measure(run("lmp", v, w, "jkr"), v)
    res[k] = (o, L)
    tho = math.sqrt(1 - (vs / v) ** 2) if v > vs else 0.0
    thL = math.sqrt(1 - (vsL / v) ** 2) if v > vsL else 0.0
    dth = jkr_dmax(v)
    es = lambda m: None if m is None else ("stick" if m["stuck"] else "%.6f" % m["e"])
    tl = lambda m: "-" if (m is None or m["stuck"]) else "%.7f" % (m["tlast"] / Fc)
    print("%6.2f %10.4g | %9s %9s %9.6f %9.6f | %9s %9s %9s | %10.7f %10s | %10s %10s | %11.5g %11s %11.5g"
          % (k, v, es(o), es(L) or "-", tho, thL,
             "%.2e" % rel(o["e"], tho) if tho else "-",
             "%.2e" % rel(L["e"], thL) if (L and thL) else "-",
             "%.2e" % rel(L["e"], o["e"]) if (L and o["e"]) else "-",
             o["tmax"] / Fc, ("%.7f" % (L["tmax"] / Fc) if L else "-"), tl(o), tl(L),
             o["dmax"], fmt(na(L, "dmax")), dth))
print("  (Tmax: largest tension; Tlast: tension at the last step in contact (rebounds only), over F_c = 3/2 pi w R;")
print("   overlap-control separation theory 5/6 pi w R = 0.5556 F_c; LAMMPS lets go at the minimum, F_c)")
print("  rel. difference of the largest overlap LAMMPS vs ours / ours vs theory:",
      ", ".join("%.2e/%.2e" % (rel(res[k][1]["dmax"], res[k][0]["dmax"]) if res[k][1] else float("nan"),
                               rel(res[k][0]["dmax"], jkr_dmax(k * vs))) for k in res))
print()
print("2. critical sticking speed (bisection, 12 halvings between 0.3 and 1.25 v_s; energy from the rebound at 2 v_s)")
co, cL = crit("ours"), crit("lmp")
en = lambda m, v: math.sqrt(v * v - (m["e"] * v) ** 2)
print("   ours:   bisection %.6g m/s (%.3e vs theory %.6g); from rebound at 2 v_s %.6g m/s (%.3e)"
      % (co, rel(co, vs), vs, en(res[2.0][0], 2 * vs), rel(en(res[2.0][0], 2 * vs), vs)))
if cL is not None:
    print("   LAMMPS: bisection %.6g m/s (%.3e vs its theory %.6g); from rebound at 2 v_s %.6g m/s (%.3e)"
          % (cL, rel(cL, vsL), vsL, en(res[2.0][1], 2 * vs), rel(en(res[2.0][1], 2 * vs), vsL)))
    print("   LAMMPS / ours: %.4f (theory %.4f)" % (cL / co, vsL / vs))
print()
print("3. w = 0, no damping (ours: hertz_elliptic and jkr_elliptic w = 0; LAMMPS: hertz/material and jkr gamma = 0)")
print("%10s | %11s %11s %11s %11s %11s | %10s %10s %10s | %9s %9s %9s %9s"
      % ("v [m/s]", "dmax th.", "hertz_ell.", "jkr_ell. 0", "LMP hertz", "LMP jkr 0", "rel o", "rel L", "rel L jkr",
         "e ours", "e jkr0", "e LMP", "e LMPjkr0"))
for k in (0.5, 1.25, 4.0):
    v = k * vs
    oh = measure(run("ours", v, 0.0, "hertz_elliptic"), v)
    oj = measure(run("ours", v, 0.0, "jkr_elliptic"), v)
    Lh = measure(run("lmp", v, 0.0, "hertz/material"), v)
    Lj = measure(run("lmp", v, 0.0, "jkr"), v)
    th = hertz_dmax(v)
    print("%10.4g | %11.6g %11.6g %11.6g %11s %11s | %10.2e %10s %10s | %9.6f %9.6f %9s %9s"
          % (v, th, oh["dmax"], oj["dmax"], fmt(na(Lh, "dmax")), fmt(na(Lj, "dmax")), rel(oh["dmax"], th),
             "%.2e" % rel(Lh["dmax"], th) if Lh else "-", "%.2e" % rel(Lj["dmax"], th) if Lj else "-",
             oh["e"], oj["e"], fmt(na(Lh, "e")), fmt(na(Lj, "e"))))
print()
# Our restitution damping gamma = 2 (5/6)^1/2 |beta| (S m*)^1/2, S = 2 E* a, is LAMMPS's tsuji form
# alpha (m_eff 4/3 E a)^1/2 with alpha = 5^1/2 |beta|: LAMMPS's e that gives that alpha in its fit
e_o = 0.5
beta = math.log(e_o) / math.sqrt(math.log(e_o) ** 2 + math.pi ** 2)
alpha_t = math.sqrt(5) * abs(beta)
alpha_L = lambda e: 1.2728 - 4.2783 * e + 11.087 * e ** 2 - 22.348 * e ** 3 + 27.467 * e ** 4 - 18.022 * e ** 5 + 4.8218 * e ** 6
lo, hi = 0.0, 1.0
for _ in range(60):
    mid = 0.5 * (lo + hi)
    lo, hi = (mid, hi) if alpha_L(mid) > alpha_t else (lo, mid)
e_L = 0.5 * (lo + hi)
print("4. restitution damping: ours coefficientRestitution %g (alpha = 5^1/2 |beta| = %.6f);" % (e_o, alpha_t))
print("   LAMMPS damping tsuji with e = %.6f (the same alpha in its fit) and with e = %g (alpha = %.6f)" % (e_L, e_o, alpha_L(e_o)))
print("%8s %10s | %9s %12s %12s | %10s" % ("w", "v [m/s]", "e ours", "LMP matched", "LMP e=0.5", "L-o / o"))
for wv, k in ((0.0, 4.0), (w, 4.0), (w, 10.0)):
    v = k * vs
    mo = "jkr_elliptic" if wv else "hertz_elliptic"
    ml = "jkr" if wv else "hertz/material"
    o = measure(run("ours", v, wv, mo, damp=("restitution", e_o)), v)
    # LAMMPS 4 Feb 2025 refuses tsuji damping with its cohesive jkr
    Lm = measure(run("lmp", v, wv, ml, damp=("tsuji", e_L)), v) if wv == 0.0 else None
    Ln = measure(run("lmp", v, wv, ml, damp=("tsuji", e_o)), v) if wv == 0.0 else None
    print("%8g %10.4g | %9s %12s %12s | %10s" % (wv, v, "stick" if o["stuck"] else "%.6f" % o["e"],
                                                fmt(na(Lm, "e")), fmt(na(Ln, "e")),
                                                "%.2e" % rel(Lm["e"], o["e"]) if (Lm and o["e"]) else "-"))
PY
