#!/usr/bin/env python3
"""Regression: rough tangential contact (tangential cmd_tangential with
tangentialRoughness on over gw_rough gwElliptic on; inputs/rough_shear).
- A rough sphere (R = 1 mm) held on a smooth wall at overlap d0 and sheared
  at constant load, sigma/delta from 0.01 to 10 and before touch (d0 < 0):
  the normal force is the GW closed form 4/3 E* R^1/2 sigma^3/2 F_3/2(h)
  and the tangential force follows Mindlin's virgin curve
  F = mu Fn [1 - (1 - k u / (3/2 mu Fn))^3/2] to gross sliding at mu Fn,
  with the summits' stiffness k = 8 a_r / (2 s0 - s1), a_r = (R sigma)^1/2
  F_1/2(h) (review Eq. 83): F_1/2, F_3/2 from the mpmath quadrature of
  tests/reference/rough_shear.csv, the rest evaluated here;
- the smooth limit: sigma = 0 gives the smooth cmd_tangential run bit for
  bit, sigma = 1e-9 delta within 1e-12; before touch the smooth law has no
  patch (no tangential force);
- three rough ellipsoids held on the wall and moved along their contact
  ellipse's axes and at 45 degrees, and a pair of rough ellipsoid tips
  moved across each other (in.rough_shear_superquadric): Mindlin's no-slip
  stiffnesses of the summits' ellipse (review Eqs. 56-59) with the contact's
  eccentricity, elliptic Hertz geometry evaluated here (regress.py).
Usage: check_rough_shear.py WORKDIR"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from regress import ROOT, elliptic_contact, mindlin_ellipse, mindlin_ellipse_force, mindlin_virgin, run, start, table

work, _, c = start()
E, nu, mu, R = 5e6, 0.3, 0.5, 1e-3
G = E / (2 * (1 + nu))
Estar = 1.0 / (2 * (1 - nu ** 2) / E)
s0, s1 = 2 / G, 2 * nu / G
F = {}
for line in open(os.path.join(ROOT, "tests", "reference", "rough_shear.csv")):
    if line[0] in "#h":
        continue
    h, f12, f32 = line.strip().split(",")
    F[h] = (float(f12), float(f32))


def shear(tag, sigma, d0, s, tset=None):
    variables = {"sigma": sigma, "d0": d0, "s": "%.12g" % s}
    if tset is not None:
        variables["tset"] = tset
    d = os.path.join(work, tag)
    run("rough_shear/in.rough_shear", d, variables=variables, tag=tag)
    return table(os.path.join(d, "shear.txt"))


# the sphere at constant load, sigma/delta 0.01 .. 10 and before touch
cases = [("1e-8", "1e-6", "-100"), ("1e-7", "1e-6", "-10"), ("1e-6", "1e-6", "-1"), ("3e-6", "1e-6", "-1/3"),
         ("1e-5", "1e-6", "-0.1"), ("1e-6", "-1e-6", "1")]
for sig, d0, h in cases:
    sigma, delta = float(sig), float(d0)
    f12, f32 = F[h]
    Fn = 4.0 / 3.0 * Estar * math.sqrt(R) * sigma ** 1.5 * f32   # circle: Rc^1/2 gamma = R^1/2
    k = 8 * math.sqrt(R * sigma) * f12 / (2 * s0 - s1)
    us = 1.5 * mu * Fn / k
    rows = shear("sphere_%s_%s" % (sig, d0), sig, d0, math.ceil(2.5 * us / 1e-9) * 1e-9)
    tag = "sigma/delta %g, h %s" % (sigma / delta, h)
    c.true(max(abs(r[2] - (R - delta)) for r in rows) < 1e-15,
           "%s: the sphere held at z = R - d0 while sheared" % tag)
    worst_n = max(abs(r[4] / Fn - 1) for r in rows)
    c.true(worst_n < 1e-9, "%s: normal force %.9g N vs the GW closed form %.9g N: worst %.3g (tol 1e-9)"
           % (tag, rows[0][4], Fn, worst_n))
    worst_t = 0.0
    for r in rows:
        u = r[1]
        want = mu * Fn * (1 - (1 - u / us) ** 1.5) if u < us else mu * Fn
        worst_t = max(worst_t, abs(-r[3] - want) / (mu * Fn))
    c.true(worst_t < 1e-9, "%s: tangential force vs Mindlin's virgin curve with the summits' stiffness %.6g N/m "
           "(slip at %.4g m, %d rows): worst %.3g mu Fn (tol 1e-9)" % (tag, k, us, len(rows), worst_t))
    c.true(abs(-rows[-1][3] / (mu * Fn) - 1) < 1e-12, "%s: gross sliding at mu Fn" % tag)
    if delta > 0:
        a_s = math.sqrt(R * delta)
        print("     %s: summits' stiffness / smooth Mindlin stiffness at the same overlap = %.6f"
              % (tag, math.sqrt(R * sigma) * f12 / a_s))
    else:
        smooth = shear("sphere_before_touch_smooth", sig, d0, 2e-6, tset="")
        c.true(all(r[3] == 0.0 for r in smooth) and smooth[0][4] > 0,
               "before touch: the smooth law (no patch) gives no friction, the summits %.4g N at sliding"
               % (mu * Fn))

# smooth limit
on = shear("smooth_on", "0", "1e-6", 2e-6)
off = shear("smooth_off", "0", "1e-6", 2e-6, tset="")
c.true(on == off, "sigma = 0: tangentialRoughness on equals the smooth cmd_tangential run bit for bit (%d rows)"
       % len(on))
tiny = shear("smooth_tiny", "1e-15", "1e-6", 2e-6)
worst = max(max(abs(a[3] - b[3]) / abs(b[4]), abs(a[4] / b[4] - 1)) for a, b in zip(tiny, off))
c.true(len(tiny) == len(off) and worst < 1e-12,
       "sigma = 1e-9 delta: the smooth run within %.3g of the normal force (tol 1e-12)" % worst)

# rough ellipsoids: the summits' elliptic patch
a1, b1, c1 = 1.0e-3, 0.6e-3, 1.5e-3
a2, b2, c2 = 1.5e-3, 0.6e-3, 1.0e-3   # the pair, a axis along x


def summits(R1, R2, sigma, f12, f32):
    """The summits' semi-axis a_r = (R_asp sigma)^1/2 F_1/2 (R_asp = a^2/delta
    of the smooth contact), the axis ratio b/a and the GW closed-form force
    4/3 E* R_force^1/2 sigma^3/2 F_3/2 of relative radii R1, R2, from elliptic
    Hertz at an overlap of 1 um (any overlap gives the same three)."""
    ds = 1e-6
    a_s, b_s, F_s = elliptic_contact(R1, R2, Estar, ds)
    a_r = math.sqrt(a_s * a_s / ds * sigma) * f12
    return a_r, b_s / a_s, 4.0 / 3.0 * Estar * math.sqrt((0.75 * F_s / Estar) ** 2 / ds ** 3) * sigma ** 1.5 * f32


s = 2e-7
for sig, d0, h in (("1e-6", "5e-6", "-5"), ("1e-6", "-1e-6", "1")):
    sigma = float(sig)
    a_r, ratio, Fn = summits(a1 * a1 / c1, b1 * b1 / c1, sigma, *F[h])
    k_major, k_minor = mindlin_ellipse(a_r, ratio, nu, G)
    d = os.path.join(work, "ellipsoids_%s" % d0)
    run("rough_shear/in.rough_shear_superquadric", d, variables={"sigma": sig, "d0": d0, "s": s}, tag="ellipsoids")
    for r in table(os.path.join(d, "shear.txt")):
        if r[0] > 3:   # the pair, below
            continue
        Fx, Fy, Ft = mindlin_ellipse_force(k_major, k_minor, s, r[1], mu * Fn)
        want = (Fx, Fy)
        tag = "ellipsoid, h %s, %g deg" % (h, r[1])
        c.rel(r[7], Fn, 1e-9, "%s: normal force vs the GW closed form" % tag)
        err = math.hypot(r[5] - want[0], r[6] - want[1]) / Ft
        c.true(err < 1e-9, "%s: tangential force (%.6g, %.6g) N vs Mindlin on the summits' ellipse (%.6g, %.6g): "
               "%.3g (tol 1e-9)" % (tag, r[5], r[6], want[0], want[1], err))
    # the pair of rough tips (atoms 4, 5; contact sigma 2^1/2 sigma): 5 moved along y by s, across the
    # contact ellipse's minor axis (relative radii (b2^2/a2)/2 along y, (c2^2/a2)/2 along z). The
    # contact point leaves the tips as 5 moves: the normal turns by about s/(2 b2^2/a2) (found here
    # in the x-y plane, where the tips' ellipse section is a2, b2, and the force split along it);
    # the overlap and the radii there move by O(s^2): a tolerance of 1e-3 (the smooth law's
    # stiffness differs from the summits' by 1.1 % at this h, all of it before touch)
    hp = {"5e-6": "-5/sqrt2", "-1e-6": "1/sqrt2"}[d0]
    a_rp, gp, Fnp = summits(0.5 * c2 ** 2 / a2, 0.5 * b2 ** 2 / a2, math.sqrt(2) * sigma, *F[hp])
    k_minor_p = mindlin_ellipse(a_rp, gp, nu, G)[1]
    Ftp = mindlin_virgin(k_minor_p * s, mu * Fnp)
    rows_p = {int(r[0]): r for r in table(os.path.join(d, "shear.txt")) if r[0] > 3}
    r4, r5 = rows_p[4], rows_p[5]
    Mx, My = 0.5 * (r5[2] - r4[2]), 0.5 * (r5[3] - r4[3])   # the midpoint from atom 4's centre
    normal = lambda t: (math.cos(t) / a2, math.sin(t) / b2)
    def off(t):   # (M - p) x n on atom 4's section: zero where the normal points at the midpoint
        nx, ny = normal(t)
        return (Mx - a2 * math.cos(t)) * ny - (My - b2 * math.sin(t)) * nx
    lo, hi = -0.1, 0.1
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if (off(mid) > 0) == (off(lo) > 0) else (lo, mid)
    nx, ny = normal(0.5 * (lo + hi))
    nl = math.hypot(nx, ny)
    nx, ny = nx / nl, ny / nl
    fn5, ft5 = r5[5] * nx + r5[6] * ny, -r5[5] * ny + r5[6] * nx
    c.true(abs(fn5 / Fnp - 1) < 1e-3, "ellipsoid pair, h %s: normal force %.6g N vs the GW closed form %.6g N "
           "(normal turned by %.3g rad): %.2g (tol 1e-3)" % (hp, fn5, Fnp, math.atan2(ny, nx), abs(fn5 / Fnp - 1)))
    c.true(abs(-ft5 / Ftp - 1) < 1e-3, "ellipsoid pair, h %s: tangential force %.6g N vs Mindlin on the summits' "
           "ellipse (minor axis) %.6g N: %.2g (tol 1e-3)" % (hp, -ft5, Ftp, abs(-ft5 / Ftp - 1)))
c.finish()
