/* Classical JKR for spheres (Johnson, Kendall & Roberts 1971), the
   circular limit of the Johnson-Greenwood theory (dc/jkr_sphere.h; the
   derivation is in dc/jkr_elliptic.h). */
#include "dc/jkr_sphere.h"
#include "dc/status.h"
#include "jkr_common.h"
#include <float.h>
#include <math.h>

#include "jkr_sphere_poly.h"

/* Units: C1 = 8 w R^2/(pi E*), a = C1^1/3 x^2, delta = C1^2/3/(2R) dbar,
   F = 8 w R Fbar. With rho = x^-3 the elliptic formulas at g = 1 give
     dbar = 2 x^4 - pi x,   Fbar = 4/(3 pi) x^6 - x^3.
   The inverse x(dbar) is tabulated once for all materials
   (jkr_sphere_poly.h, tests/reference/gen_jkr_sphere_poly.py) in two
   forms: from the separation point up in s = U^1/2 (dc_jkr_sphere, below),
   and at the Hertz-like end, dbar >= 0.575, as psi(kappa) = a/(R
   delta)^1/2 (dc/jkr_sphere.h), kappa = pi 2^-1/4 dbar^-3/4. */

/* The piece of v in [0, n/inv_w] of n uniform pieces (the last one for
   larger v or NaN). */
static inline int uniform_piece(double v, double inv_w, int n)
{
  return v * inv_w < n - 1 ? (int)(v * inv_w) : n - 1;
}

/* The state at contact radius a > 0 in *t (delta from a); DC_ERANGE when
   a double of it overflows. */
static int sphere_fill(double R, double Estar, double w, double a, dc_jkr_state *t)
{
  /* q = (2 pi w a/E*)^1/2: F = 4 E* a^3/(3R) - 2 E* a q, delta = a^2/R - q */
  const double q = sqrt(2.0 * M_PI * w * a / Estar);
  t->contact = 1;
  t->a = t->b = a;
  t->area = M_PI * a * a;
  t->e2 = 0.0;
  t->F = 4.0 * Estar * a * a * a / (3.0 * R) - 2.0 * Estar * a * q;
  t->delta = a * a / R - q;
  /* dF/da = 4 E* a^2/R - 3 E* q, d delta/da = 2a/R - q/(2a) */
  const double num = 4.0 * Estar * a * a / R - 3.0 * Estar * q;
  const double den = 2.0 * a / R - 0.5 * q / a;
  t->kn = dc_jkr_finite_kn_(num, den);
  return dc_jkr_state_finite_(t) ? DC_OK : DC_ERANGE;
}

int dc_jkr_sphere_at_radius(double R, double Estar, double w, double a, dc_jkr_state *s)
{
  if (!(R > 0.0 && Estar > 0.0 && w >= 0.0 && a > 0.0 && isfinite(R) && isfinite(Estar) &&
        isfinite(w) && isfinite(a)))
    return DC_EDOM;
  dc_jkr_state t;
  const int st = sphere_fill(R, Estar, w, a, &t);
  if (st == DC_OK) *s = t;
  return st;
}

/* The two closed forms are evaluated as written when every intermediate is
   a normal number (so they agree to the last bit with the separation test
   of dc_jkr_sphere and with earlier versions); otherwise from the binary
   mantissas and exponents of the arguments (frexp, ldexp), free of
   intermediate overflow and underflow: the result is then infinite or zero
   only when it does not fit in a double itself. */
double dc_jkr_sphere_pulloff(double R, double w)
{
  if (!(R > 0.0 && w >= 0.0 && isfinite(R) && isfinite(w))) return NAN;
  if (w == 0.0) return 0.0;
  const double a1 = 1.5 * M_PI * w, p = a1 * R;
  if (a1 >= DBL_MIN && a1 <= DBL_MAX && p >= DBL_MIN && p <= DBL_MAX) return p;
  int ew, eR;
  const double wm = frexp(w, &ew), Rm = frexp(R, &eR);
  return ldexp(1.5 * M_PI * wm * Rm, ew + eR);
}

double dc_jkr_sphere_delta_break(double R, double Estar, double w)
{
  if (!(R > 0.0 && Estar > 0.0 && w >= 0.0 && isfinite(R) && isfinite(Estar) && isfinite(w))) return NAN;
  if (w == 0.0) return -0.0;
  /* -3/4 (pi^2 w^2 R / E*^2)^1/3, the left-to-right products of that form */
  const double a1 = M_PI * M_PI * w * w, n1 = a1 * R, d1 = Estar * Estar, t = n1 / d1;
  if (a1 >= DBL_MIN && a1 <= DBL_MAX && n1 >= DBL_MIN && n1 <= DBL_MAX && d1 >= DBL_MIN && d1 <= DBL_MAX &&
      t >= DBL_MIN && t <= DBL_MAX)
    return -0.75 * cbrt(t);
  int ew, eR, eE;
  const double wm = frexp(w, &ew), Rm = frexp(R, &eR), Em = frexp(Estar, &eE);
  int e = 2 * ew + eR - 2 * eE;
  const int r = ((e % 3) + 3) % 3;          /* e - r divisible by 3 */
  e -= r;
  const double tm = ldexp(M_PI * M_PI * wm * wm * Rm / (Em * Em), r);
  return -0.75 * ldexp(cbrt(tm), e / 3);
}

int dc_jkr_sphere(double R, double Estar, double w, double delta, dc_jkr_state *s)
{
  double a0, nu;
  const dc_jkr_sphere_pair pr = dc_jkr_sphere_pair_of(Estar, w);
  if (dc_jkr_sphere_nu_(R, pr.c, delta, &a0, &nu) && nu <= DC_JKR_NU_H) {   /* NaN c: not here */
    /* the Hertz-like end (dc/jkr_sphere.h), dF/d delta = (dF/da)/(d delta/da)
       = 2 E* a0 psi (psi^2 + 3)/(3 psi^2 + 1) */
    const double psi = dc_jkr_psi(nu, sqrt(nu)), psi2 = psi * psi;
    const double a = a0 * psi;
    s->contact = 1;
    s->delta = delta;
    s->a = s->b = a;
    s->area = M_PI * a * a;
    s->e2 = 0.0;
    s->F = dc_jkr_sphere_force_(Estar, a0, delta, psi);
    s->kn = 2.0 * Estar * a0 * (psi * (psi2 + 3.0) / (3.0 * psi2 + 1.0));
    return DC_OK;
  }
  if (!(R > 0.0 && Estar > 0.0 && w >= 0.0 && isfinite(R) && isfinite(Estar) && isfinite(w) &&
        isfinite(delta)))
    return DC_EDOM;
  /* inputs within 1e+-60 (every DEM contact): no intermediate leaves the
     doubles, so the range-safe scales and the finiteness test are skipped */
  const int moderate = R > 1e-60 && R < 1e60 && Estar > 1e-60 && Estar < 1e60 && w < 1e60 &&
                       (w > 1e-60 || w == 0.0) && fabs(delta) < 1e60;
  double As, Ds;
  if (moderate) {
    As = w == 0.0 ? 0.0 : dc_jkr_cbrt_scale_(8.0 * w / (M_PI * Estar), R * R);
    Ds = As * As / (2.0 * R);
  } else {
    As = dc_jkr_length_scale_(w, Estar, R);
    Ds = dc_jkr_delta_scale_(As, R);
  }
  /* the adhesion scale itself overflows (w/E* and R far beyond physical
     magnitudes): no state can be computed */
  if (!(Ds <= DBL_MAX)) return DC_ERANGE;
  if (!(Ds > 0.0) || delta > 1e10 * Ds) {
    /* Hertz-dominated (or w = 0): a^2 = R (delta + (2 pi w a/E*)^1/2).
       With a0 = (R delta)^1/2 and t0 = (2 pi w a0/E*)^1/2/delta ~ dbar^-3/4
       <= 3e-8, a = a0 (1 + t0/2) + O(t0^3): the t0^2 terms of the square
       root and of t(a) = t0 (a/a0)^1/2 cancel. */
    if (delta < 0.0) { dc_jkr_zero_state_(delta, s); return DC_OK; }
    if (delta == 0.0) {
      dc_jkr_zero_state_(delta, s);
      if (w == 0.0) s->contact = 1;
      return DC_OK;
    }
    const double Rd = R * delta;
    const double a0 = Rd >= DBL_MIN && Rd <= DBL_MAX ? sqrt(Rd) : sqrt(R) * sqrt(delta);
    const double a = a0 + 0.5 * a0 * sqrt(2.0 * M_PI * w * a0 / Estar) / delta;
    if (!(a > 0.0)) {   /* R delta underflows: every quantity rounds to 0 */
      dc_jkr_zero_state_(delta, s);
      s->contact = 1;
      return DC_OK;
    }
    dc_jkr_state t;
    if (sphere_fill(R, Estar, w, a, &t) != DC_OK) return DC_ERANGE;
    t.delta = delta;
    *s = t;
    return DC_OK;
  }
  /* With x = x_b (1 + y), x_b^3 = pi/8 (the separation point), the quartic
     2 x^4 - pi x = dbar becomes y^2 (y^2 + 4 y + 6) = U, U = (dbar - dbar_b)
     / (2 x_b^4) >= 0: y = s (y/s)(s) from the table in s = U^1/2 up to
     S_H = 2 (dbar = 0.575, nu = 16), and above (inputs beyond 1e+-60 only:
     the others took the Hertz-like end) from psi, x^2 = psi (dbar/2)^1/2
     with nu = pi^2 2^-1/2 dbar^-3/2. */
  const double xb = 0.73229594378076163;       /* (pi/8)^1/3            */
  const double inv2xb4 = 1.7386953397031944;   /* 1/(2 x_b^4) = 4/(pi x_b) */
  const double dbar_b = -1.7254316679264337;   /* 2 x_b^4 - pi x_b = -3/4 pi x_b */
  const double delta_b = Ds * dbar_b;
  /* the separation test agrees with dc_jkr_sphere_delta_break (the
     overlap dc_jkr_in_contact uses) to the last bit: the cbrt is only
     taken below delta_b */
  if (delta < delta_b && delta < dc_jkr_sphere_delta_break(R, Estar, w)) { dc_jkr_zero_state_(delta, s); return DC_OK; }
  /* (from dbar where delta_b itself overflows: Ds beyond DBL_MAX/1.73) */
  const double Uq = isfinite(delta_b) ? (delta - delta_b) / Ds * inv2xb4 : (delta / Ds - dbar_b) * inv2xb4;
  const double U = Uq > 0.0 ? Uq : 0.0;
  double x, c, cm1;   /* x, c = 8 x^3/pi and c - 1, free of cancellation at the separation point */
  if (U <= DC_JKR_S_H * DC_JKR_S_H) {
    const double sU = sqrt(U);
    const int p = uniform_piece(sU, DC_JKR_S_PIECES / DC_JKR_S_H, DC_JKR_S_PIECES);
    double ys, rest;
    dc_poly14(&dc_jkr_poly_s[p][0][0], 1, 1, sU - dc_jkr_poly_s_centre[p], &ys, &rest);
    const double y = sU * ys;
    x = xb + xb * y;
    c = (1.0 + y) * (1.0 + y) * (1.0 + y);
    cm1 = y * (3.0 + y * (3.0 + y));
  } else {
    const double dbar = delta / Ds, nu_d = 6.978864199638879 / (dbar * sqrt(dbar));   /* pi^2 2^-1/2 */
    x = sqrt(dc_jkr_psi(nu_d, sqrt(nu_d)) * sqrt(0.5 * dbar));
    c = 8.0 / M_PI * x * x * x;
    cm1 = c - 1.0;
  }
  const double a = As * x * x;
  dc_jkr_state t;
  t.contact = 1;
  t.a = t.b = a;
  t.area = M_PI * a * a;
  t.e2 = 0.0;
  t.delta = delta;
  /* F = 8 w R (4/(3 pi) x^3 - 1) x^3 = pi w R c (c/6 - 1) */
  t.F = M_PI * w * R * c * (c / 6.0 - 1.0);
  /* kn = (dF/dx)/(d delta/dx) = (8 w R/Ds) x^2 (8x^3 - 3 pi)/(pi (8x^3 - pi)) */
  t.kn = dc_jkr_finite_kn_(8.0 * w * R / (M_PI * Ds) * x * x * (c - 3.0), cm1);
  if (!moderate && !dc_jkr_state_finite_(&t)) return DC_ERANGE;
  *s = t;
  return DC_OK;
}
