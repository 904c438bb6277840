#!/usr/bin/env python3
"""Reference for the rolling decks (inputs/rolling_creep,
tests/regression/check_rolling_creep.py): the rolling law of
dc/rolling_kalker.h evaluated independently of c_core, for contacts whose
normal is +z (a body on the plane z = 0, or an upper body i on a lower
body j).

- Contact patch: elliptic Hertz from the relative curvature K_i + K_j
  (regress.elliptic_contact: bisection on review Eq. 13, its own AGM
  elliptic integrals), the major axis along the smaller relative curvature.
- Kinematics (the header's derivation): s = tangential part of the
  relative velocity of the material points at the contact, the rolling
  velocity Vbar = (K_i + K_j)^-1 [dw x n + (K_i - K_j) s / 2], creepages
  xi = s.ex / V, eta = s.ey / V, phi = dw.n / V (ey = n x ex).
- Creep coefficients c11, c22, c23, c33: Kalker's linear theory solved by
  gen_kalker.py at the axis ratio of each deck contact (not interpolated:
  rolling_creep_coef.csv, written by this script with --coefficients),
  and at a/b = 1 its node row of kalker.csv. Rolling off the patch's axes:
  the law's effective axis ratio h(alpha) / h(alpha + 90 deg) with c33
  times h(alpha) h(alpha + 90 deg) / (a b) (the rule the header states).
- Forces (Eqs. 86-88, c = (a b)^1/2): F_x = -G c^2 c11 xi,
  F_y = -G c^2 (c22 eta + c c23 phi), M_z = G c^3 (c23 eta - c c33 phi);
  Vermeulen-Johnson: F = F_L [1 - (1 - beta/3)^3] / beta (beta = |F_L| /
  (mu F_n) < 3), mu F_n F_L/|F_L| beyond, M_z times the same factor;
  linear Kalker: F_L scaled back onto |F| = mu F_n; both with
  |M_z| <= 3/8 mu F_n a E(e^2).
Standard library only (the check runs it); --coefficients needs numpy
(gen_kalker.py).

Usage:
    python3 gen_rolling_creep.py --coefficients   # writes rolling_creep_coef.csv (about a minute)
"""
import csv
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "regression"))
from regress import elliptic_contact, ellipke  # noqa: E402

NU = 0.25          # the decks' Poisson ratio (a node of kalker.csv)
COEF_CSV = os.path.join(HERE, "rolling_creep_coef.csv")
# the decks' disc (oblate spheroid A, A, C on its rim): relative radii A and
# C^2/A on a plane, A/2 and C^2/(2A) for two parallel rims; the oblique
# rolling angle of the deck
DISC_A, DISC_C, OBLIQUE_DEG = 1e-3, 4e-4, 30.0


def sym_eig(K):
    """Eigenvalues lo <= hi and the unit eigenvector of lo of a symmetric
    2x2 matrix ((k11, k12), (k12, k22))."""
    (k11, k12), (_, k22) = K
    m, h = 0.5 * (k11 + k22), 0.5 * (k11 - k22)
    d = math.hypot(h, k12)
    lo, hi = m - d, m + d
    if d == 0.0:
        return lo, hi, None
    x, y = k12, lo - k11
    if math.hypot(lo - k22, k12) > math.hypot(x, y):
        x, y = lo - k22, k12
    ln = math.hypot(x, y)
    return lo, hi, (x / ln, y / ln)


def patch(Ki, Kj, Estar, delta):
    """(a, b, F, major axis or None) of the Hertz contact of two bodies
    with curvature tensors Ki, Kj (in the plane x, y) at overlap delta."""
    K = [[Ki[0][0] + Kj[0][0], Ki[0][1] + Kj[0][1]], [Ki[1][0] + Kj[1][0], Ki[1][1] + Kj[1][1]]]
    lo, hi, axis = sym_eig(K)
    a, b, F = elliptic_contact(1.0 / lo, 1.0 / hi, Estar, delta)
    if lo == hi:
        b = a
    return a, b, F, axis


def axis_ratios():
    """The axis ratios g = a_x / b_y the decks need: the disc's patch rolled
    along its major axis, along its minor one, and at 30 degrees (effective
    ratio), with the c33 factor of that rolling angle."""
    Estar = 1e9 / (2 * (1 - NU ** 2))
    a, b, _ = elliptic_contact(DISC_A, DISC_C ** 2 / DISC_A, Estar, 2e-6)
    ca, sa = math.cos(math.radians(OBLIQUE_DEG)), math.sin(math.radians(OBLIQUE_DEG))
    r = b / a
    return [a / b, b / a, math.hypot(ca, r * sa) / math.hypot(sa, r * ca)]


def load_coefficients():
    """{g: (c11, c22, c23, c33)} at nu = 0.25: the deck ratios
    (rolling_creep_coef.csv) and a/b = 1 (kalker.csv)."""
    table = {}
    with open(os.path.join(HERE, "kalker.csv")) as f:
        for row in csv.reader(l for l in f if not l.startswith("#")):
            if row[0] == "node" and float(row[1]) == 1.0 and float(row[2]) == NU:
                table[1.0] = tuple(float(v) for v in row[3:7])
    with open(COEF_CSV) as f:
        for row in csv.reader(l for l in f if not l.startswith("#")):
            table[float(row[0])] = tuple(float(v) for v in row[2:6])
    return table


def coefficients(table, g):
    """c_ij at g: the entry within 1e-9 of g (none: an error)."""
    for gk, c in table.items():
        if abs(gk - g) <= 1e-9 * g:
            return c
    raise SystemExit("gen_rolling_creep: no coefficients at a/b = %.12g (run --coefficients)" % g)


def rolling_law(Ki, Kj, s, dw, a, b, axis, Fn, G, mu, model, table):
    """The law for n = +z: Ki, Kj curvature tensors, s the slip (x, y), dw
    the relative angular velocity (3), patch a >= b with the major axis,
    friction load Fn. Returns a dict: V, ex, xi, eta, phi, F (x, y), Mz,
    saturation, g."""
    K = [[Ki[r][c] + Kj[r][c] for c in range(2)] for r in range(2)]
    D = [[Ki[r][c] - Kj[r][c] for c in range(2)] for r in range(2)]
    q = (dw[1] + 0.5 * (D[0][0] * s[0] + D[0][1] * s[1]), -dw[0] + 0.5 * (D[1][0] * s[0] + D[1][1] * s[1]))
    det = K[0][0] * K[1][1] - K[0][1] * K[1][0]
    Vb = ((K[1][1] * q[0] - K[0][1] * q[1]) / det, (K[0][0] * q[1] - K[1][0] * q[0]) / det)
    V = math.hypot(*Vb)
    if V == 0.0:   # no rolling direction: the law does not act (the caller compares V with v_min)
        return {"V": 0.0, "ex": None, "xi": math.nan, "eta": math.nan, "phi": math.nan, "F": (0.0, 0.0),
                "Mz": 0.0, "saturation": 0.0, "g": math.nan}
    ex = (Vb[0] / V, Vb[1] / V)
    ey = (-ex[1], ex[0])
    xi, eta, phi = (s[0] * ex[0] + s[1] * ex[1]) / V, (s[0] * ey[0] + s[1] * ey[1]) / V, dw[2] / V
    if a == b:
        g, c33f = 1.0, 1.0
    else:
        ca = min(1.0, abs(ex[0] * axis[0] + ex[1] * axis[1]))
        sa = math.sqrt((1 - ca) * (1 + ca))
        r = b / a
        ha, hc = math.hypot(ca, r * sa), math.hypot(sa, r * ca)
        g, c33f = ha / hc, (ha * hc / r if sa > 0 else 1.0)
    c11, c22, c23, c33 = coefficients(table, g)
    c33 *= c33f
    c = math.sqrt(a * b)
    Fx = -G * c * c * c11 * xi
    Fy = -G * c * c * (c22 * eta + c * c23 * phi)
    Mz = G * c ** 3 * (c23 * eta - c * c33 * phi)
    FL, muF = math.hypot(Fx, Fy), mu * Fn
    if model == "vermeulenJohnson":
        beta = FL / muF
        if beta < 3:
            t = beta / 3
            fac = 1 - t + t * t / 3
            Fx, Fy, Mz = Fx * fac, Fy * fac, Mz * fac
        else:
            Fx, Fy, Mz = muF * Fx / FL, muF * Fy / FL, Mz * muF / FL
    elif FL > muF:
        Fx, Fy = muF * Fx / FL, muF * Fy / FL
    Ms = 3 * math.pi / 16 * muF * a if a == b else 0.375 * muF * a * ellipke(1 - (b / a) ** 2)[1]
    Mz = max(-Ms, min(Ms, Mz))
    F = (Fx * ex[0] + Fy * ey[0], Fx * ex[1] + Fy * ey[1])
    return {"V": V, "ex": ex, "xi": xi, "eta": eta, "phi": phi, "F": F, "Mz": Mz,
            "saturation": min(1.0, math.hypot(Fx, Fy) / muF), "g": g}


def write_coefficients():
    sys.path.insert(0, HERE)
    import gen_kalker
    with open(COEF_CSV, "w") as f:
        f.write("# generated by gen_rolling_creep.py --coefficients: Kalker's linear-theory creep coefficients\n")
        f.write("# (gen_kalker.extrapolate, degrees 8..20 extrapolated) at the axis ratios of the rolling_creep decks,\n")
        f.write("# nu = %g: the disc's patch (a/b of relative radii %g and %g m) rolled along its major axis, its minor\n"
                % (NU, DISC_A, DISC_C ** 2 / DISC_A))
        f.write("# axis and at %g degrees (the law's effective ratio)\n" % OBLIQUE_DEG)
        f.write("# a/b,nu,c11,c22,c23,c33,e11,e22,e23,e33\n")
        for g in axis_ratios():
            r = gen_kalker.extrapolate(g, [NU])[0]
            f.write("%.17g,%g,%s\n" % (g, NU, ",".join("%.12g" % v for v in r)))
            f.flush()


if __name__ == "__main__":
    if sys.argv[1:] == ["--coefficients"]:
        write_coefficients()
    else:
        raise SystemExit(__doc__)
