/* Johnson-Greenwood approximate JKR for elliptical contacts and classical
   JKR for spheres (review Eqs. 19-28; derivation, conventions and the seed
   corrections are in dc/jkr_elliptic.h). */
#include "dc/jkr_elliptic.h"
#include "dc/elliptic_integrals.h"
#include "dc/hertz_elliptic.h"
#include "dc/status.h"
#include "jkr_extrema_guess.h"
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#define KN_MAX 1e300

/* Cube root of a positive normal double, to < 1 ulp (the libm cbrt costs
   ~30 ns here, through frexp/scalbn). Exponent/3 by integer arithmetic on
   the high word (~6% error), a degree-4 polynomial correction in r = t^3/x
   (fdlibm's cbrt coefficients, ~23 bits), rounding of t to 21 bits so that
   t^2 is exact, and one Halley-like step t + t (x/t^2 - t)/(2t + x/t^2),
   exact to rounding. Zero, subnormal, huge and non-finite x go to cbrt(). */
static inline double dc_jkr_cbrt_(double x)
{
  if (!(x >= DBL_MIN && x <= DBL_MAX)) return cbrt(x);
  uint64_t u;
  memcpy(&u, &x, sizeof u);
  u = ((u >> 32) / 3 + 715094163u) << 32;       /* (1023 - 1023/3 - 0.03306235651) 2^20 */
  double t;
  memcpy(&t, &u, sizeof t);
  double r = (t * t) * (t / x);
  t = t * ((1.87595182427177009643 + r * (-1.88497979543377169875 + r * 1.621429720105354466140)) +
           ((r * r) * r) * (-0.758397934778766047437 + r * 0.145996192886612446982));
  memcpy(&u, &t, sizeof u);
  u = (u + 0x80000000u) & 0xffffffffc0000000ull;
  memcpy(&t, &u, sizeof t);
  const double s = t * t;
  r = x / s;
  r = (r - t) / ((t + t) + r);
  return t + t * r;
}

/* (p q)^1/3 for p, q > 0, as one cube root when p q is a normal number,
   else as the product of two (w/E* and R^2 can be far apart). */
static inline double dc_jkr_cbrt_scale_(double p, double q)
{
  const double pq = p * q;
  if (pq >= DBL_MIN && pq <= DBL_MAX) return dc_jkr_cbrt_(pq);
  return cbrt(p) * cbrt(q);
}

/* ------------------------------------------------------------------ */
/* Classical JKR for spheres.                                          */
/* Units: C1 = 8 w R^2/(pi E*), a = C1^1/3 x^2, delta = C1^2/3/(2R) dbar,
   F = 8 w R Fbar. With rho = x^-3 the elliptic formulas at g = 1 give
     dbar = 2 x^4 - pi x,   Fbar = 4/(3 pi) x^6 - x^3.                  */

static double finite_kn(double num, double den)
{
  if (den > 0.0 && num < KN_MAX * den) return num / den;
  return num >= 0.0 ? KN_MAX : -KN_MAX;
}

static void sphere_fill(double R, double Estar, double w, double a, dc_jkr_state *s)
{
  /* q = (2 pi w a/E*)^1/2: F = 4 E* a^3/(3R) - 2 E* a q, delta = a^2/R - q */
  const double q = sqrt(2.0 * M_PI * w * a / Estar);
  s->contact = 1;
  s->a = s->b = a;
  s->area = M_PI * a * a;
  s->e2 = 0.0;
  s->F = 4.0 * Estar * a * a * a / (3.0 * R) - 2.0 * Estar * a * q;
  s->delta = a * a / R - q;
  /* dF/da = 4 E* a^2/R - 3 E* q, d delta/da = 2a/R - q/(2a) */
  const double num = 4.0 * Estar * a * a / R - 3.0 * Estar * q;
  const double den = 2.0 * a / R - 0.5 * q / a;
  s->kn = finite_kn(num, den);
}

int dc_jkr_sphere_at_radius(double R, double Estar, double w, double a, dc_jkr_state *s)
{
  if (!(R > 0.0 && Estar > 0.0 && w >= 0.0 && a > 0.0 && isfinite(R) && isfinite(Estar) &&
        isfinite(w) && isfinite(a)))
    return DC_EDOM;
  sphere_fill(R, Estar, w, a, s);
  return DC_OK;
}

double dc_jkr_sphere_pulloff(double R, double w) { return 1.5 * M_PI * w * R; }

double dc_jkr_sphere_delta_break(double R, double Estar, double w)
{
  return -0.75 * cbrt(M_PI * M_PI * w * w * R / (Estar * Estar));
}

static void zero_state(double delta, dc_jkr_state *s)
{
  memset(s, 0, sizeof *s);
  s->delta = delta;
}

int dc_jkr_sphere(double R, double Estar, double w, double delta, dc_jkr_state *s)
{
  if (!(R > 0.0 && Estar > 0.0 && w >= 0.0 && isfinite(R) && isfinite(Estar) && isfinite(w) &&
        isfinite(delta)))
    return DC_EDOM;
  const double As = dc_jkr_cbrt_scale_(8.0 * w / (M_PI * Estar), R * R);
  const double Ds = As * As / (2.0 * R);
  if (!(Ds > 0.0) || delta > 1e10 * Ds) {
    /* Hertz-dominated (or w = 0): a^2 = R (delta + (2 pi w a/E*)^1/2).
       With a0 = (R delta)^1/2 and t0 = (2 pi w a0/E*)^1/2/delta ~ dbar^-3/4
       <= 3e-8, a = a0 (1 + t0/2) + O(t0^3): the t0^2 terms of the square
       root and of t(a) = t0 (a/a0)^1/2 cancel. */
    if (delta < 0.0) { zero_state(delta, s); return DC_OK; }
    if (delta == 0.0) {
      zero_state(delta, s);
      if (w == 0.0) s->contact = 1;
      return DC_OK;
    }
    const double a0 = sqrt(R * delta);
    const double a = a0 + 0.5 * a0 * sqrt(2.0 * M_PI * w * a0 / Estar) / delta;
    sphere_fill(R, Estar, w, a, s);
    s->delta = delta;
    return DC_OK;
  }
  /* With x = x_b (1 + y), x_b^3 = pi/8 (the separation point), the quartic
     2 x^4 - pi x = dbar becomes y^2 (y^2 + 4 y + 6) = U, U = (dbar - dbar_b)
     / (2 x_b^4) >= 0. In p = y^2 + 2 y it reads p k(p) = U^1/2 with k =
     (1 + 2/(1 + (1 + p)^1/2)^2)^1/2 falling from 1.5^1/2 to 1; the rational
     p ~ s (k0 b + s)/(b + s), s = U^1/2, k0 = 1.5^-1/2, b = 3.69 is within
     2.5e-3 of the root for every U >= 0, and two Halley steps on the
     quartic then reach rounding (2.5e-3 -> 5e-9 -> 2e-16, checked over U in
     [1e-64, 1e20]). No transcendental call; one cube root for the scale. */
  const double xb = 0.73229594378076163;       /* (pi/8)^1/3            */
  const double inv2xb4 = 1.7386953397031944;   /* 1/(2 x_b^4) = 4/(pi x_b) */
  const double dbar_b = -1.7254316679264337;   /* 2 x_b^4 - pi x_b = -3/4 pi x_b */
  const double delta_b = Ds * dbar_b;
  /* the separation test agrees with dc_jkr_sphere_delta_break (the
     overlap dc_jkr_in_contact uses) to the last bit: the cbrt is only
     taken below delta_b */
  if (delta < delta_b && delta < dc_jkr_sphere_delta_break(R, Estar, w)) { zero_state(delta, s); return DC_OK; }
  const double U = fmax(0.0, (delta - delta_b) / Ds * inv2xb4);
  double y = 0.0;
  if (U > 0.0) {
    const double sU = sqrt(U);
    const double p = sU * (0.81649658092772603 * 3.69 + sU) / (3.69 + sU);
    y = p / (1.0 + sqrt(1.0 + p));
    for (int i = 0; i < 2; i++) {
      /* Halley on P = y^2 (y^2 + 4y + 6) - U: P' = 4y (y^2 + 3y + 3),
         P'' = 12 (y^2 + 2y + 1) */
      const double y2 = y * y;
      const double P = y2 * (y2 + 4.0 * y + 6.0) - U;
      const double P1 = 4.0 * y * (y2 + 3.0 * y + 3.0);
      const double P2 = 12.0 * (y2 + 2.0 * y + 1.0);
      y -= 2.0 * P * P1 / (2.0 * P1 * P1 - P * P2);
    }
    if (!(y > 0.0)) y = 0.0;
  }
  const double x = xb + xb * y;
  const double c = (1.0 + y) * (1.0 + y) * (1.0 + y);   /* 8 x^3 / pi */
  const double a = As * x * x;
  s->contact = 1;
  s->a = s->b = a;
  s->area = M_PI * a * a;
  s->e2 = 0.0;
  s->delta = delta;
  /* F = 8 w R (4/(3 pi) x^3 - 1) x^3 = pi w R c (c/6 - 1) */
  s->F = M_PI * w * R * c * (c / 6.0 - 1.0);
  /* kn = (dF/dx)/(d delta/dx) = (8 w R/Ds) x^2 (8x^3 - 3 pi)/(pi (8x^3 - pi)),
     with 8x^3/pi - 1 = y (3 + 3y + y^2) free of cancellation at the
     separation point */
  s->kn = finite_kn(8.0 * w * R / (M_PI * Ds) * x * x * (c - 3.0), y * (3.0 + y * (3.0 + y)));
  return DC_OK;
}

/* ------------------------------------------------------------------ */
/* Elliptic contacts: the state as a function of m = e^2.               */

typedef struct {
  double m, m1, g, rho, X, Y, abar, dbar, Pbar; /* values                    */
  double dg, drho, dX, dY, dabar, ddbar, dPbar; /* d/dm                      */
} jg_point;

/* dC/dm = (D - (4 - 3m) C)/(2 m (1-m)) (from dK/dm = B/(2 m1), dD/dm =
   (D - C)/(2 m1), dB/dm = C/2). The numerator cancels to O(m) as m -> 0
   (relative error ~6e-16/m), so below m = 0.05 the Taylor series of dC/dm
   is used instead: coefficients (n+1) c_(n+1) of C = sum c_n m^n, from the
   series of K and E (c_0 = pi/16, c_1 = 3 pi/64, ...); 13 terms leave
   < 1e-17 relative at m = 0.05. Both branches: <= 1.2e-14 relative. */
static double dc_C_dm_(double m, double m1, double D, double C)
{
  if (m < 0.05) {
    static const double c[13] = {
      0.14726215563702156, 0.23009711818284618, 0.28186896977398658, 0.3171025909957349,
      0.34258404920074931, 0.36185440196829146, 0.37693166871697027, 0.3890473294971586,
      0.39899456235362004, 0.40730694906932046, 0.41435649241859716, 0.42041040221042731,
      0.42566553223805765};
    double s = c[12];
    for (int n = 11; n >= 0; n--) s = s * m + c[n];
    return s;
  }
  return (D - (4.0 - 3.0 * m) * C) / (2.0 * m * m1);
}

/* Qn = lambda Delta Q = (1 - lambda^2) B - m (D - C) = m1 D - lambda^2 B
   (the two are equal since B - m (D - C) = m1 D), and its derivative
   dQn/dm = -((1 + lambda^2) C + D)/2 = -lambda Delta Pi2 / 2. Qn vanishes at
   the Hertz shape (lambda^2 = m1 D/B, the Hertz relation), so the form is
   chosen whose terms are smallest there: for m < 1/2 both terms of the
   first are O(m); for slender ellipses both terms of the second are
   O(m1 K), whereas those of the first are O(1) and would leave an absolute
   error of ~eps in Q against Y = O(m1 Pi2) (a 4e-10 relative error of F at
   R_minor/R_major = 1e-5). */
static void dc_jkr_Qn_(const dc_jkr_geom *G, double m, double m1, const dc_ellint *el,
                       double *Qn, double *dQn)
{
  *Qn = m < 0.5 ? G->l2c * el->B - m * (el->D - el->C) : m1 * el->D - G->lam2 * el->B;
  *dQn = -0.5 * ((1.0 + G->lam2) * el->C + el->D);
}

/* Review Eqs. 19-23 in the cancellation-free Q/u form (header comment),
   with their derivatives in the solver variable v: v = m = e^2, or, for
   slender contacts (e2_hertz > 1/2), v = m1 = 1 - e^2, which keeps full
   relative precision of b/a when it is small. */
static void jg_eval_m(const dc_jkr_geom *G, double m, double m1, double sv, jg_point *p);
static inline void jg_eval(const dc_jkr_geom *G, double v, jg_point *p)
{
  if (G->use_m1) jg_eval_m(G, 1.0 - v, v, -1.0, p);
  else jg_eval_m(G, v, 1.0 - v, 1.0, p);
}

/* sv = dm/dv: the derivatives are returned in the solver variable v */
static void jg_eval_m(const dc_jkr_geom *G, double m, double m1, double sv, jg_point *p)
{
  /* The values (Pi2, Q, rho, abar, dbar, Pbar) are formed with true
     divisions; the derivatives, which only steer Newton's method and give
     kn, use reciprocals computed once (one rounding more, and fewer
     dependent divisions on the path). */
  dc_ellint el;
  if (m <= 0.5) dc_ellint_m(m, &el); else dc_ellint_m1(m1, &el);
  const double K = el.K, D = el.D, B = el.B, C = el.C;
  const double lam = G->lambda, lam2 = G->lam2;
  const double im1 = 1.0 / m1;
  const double dK = 0.5 * B * im1, dD = 0.5 * (D - C) * im1, dB = 0.5 * C;
  const double dC = dc_C_dm_(m, m1, D, C);

  const double Del = D * B + m1 * C * D + B * C;
  const double dDel = dD * B + D * dB - C * D + m1 * (dC * D + C * dD) + dB * C + B * dC;
  const double lD = lam * Del;
  const double ilD = 1.0 / lD, dlnDel = dDel / Del;
  const double Pi2 = ((1.0 + lam2) * C + D) / lD;
  const double dPi2 = ((1.0 + lam2) * dC + dD) * ilD - Pi2 * dlnDel;
  double Qn, dQn;
  dc_jkr_Qn_(G, m, m1, &el, &Qn, &dQn);
  const double Q = Qn / lD;
  const double dQ = dQn * ilD - Q * dlnDel;
  const double g = sqrt(m1);
  const double q4 = sqrt(g);                        /* g^1/2 */
  const double ig = 1.0 / g, dg = -0.5 * ig;
  /* u = 1 - g^1/2 = (1 - g^2)/((1 + g^1/2)(1 + g)): no cancellation */
  const double uden = (1.0 + q4) * (1.0 + g);
  const double u = m / uden, iu = uden / m;
  p->m1 = m1;
  const double du = 0.25 * ig / q4;
  const double rho = Q / u;
  const double drho = (dQ - rho * du) * iu;
  const double irho = 1.0 / rho;

  const double X = m1 * Pi2 * K + Q * B - 2.0 * K * rho;
  const double dX = -Pi2 * K + m1 * (dPi2 * K + Pi2 * dK) + dQ * B + Q * dB - 2.0 * (dK * rho + K * drho);
  const double Y = m1 * Pi2 / 3.0 + Q / 3.0 - rho;
  const double dY = (-Pi2 + m1 * dPi2 + dQ) / 3.0 - drho;

  /* abar^3 = g / rho^2, dbar = abar^2 X, Pbar = g Y / rho^2 */
  const double grr = g / (rho * rho);
  const double abar = dc_jkr_cbrt_(grr);
  const double dln = dg * ig - 2.0 * drho * irho;          /* d ln(g/rho^2)/dm */
  const double lna = dln * (1.0 / 3.0);                     /* d ln abar/dm */
  p->m = m; p->g = g; p->rho = rho; p->X = X; p->Y = Y;
  p->abar = abar;
  p->dbar = abar * abar * X;
  p->Pbar = grr * Y;
  p->dg = sv * dg; p->drho = sv * drho; p->dX = sv * dX; p->dY = sv * dY;
  p->dabar = sv * abar * lna;
  p->ddbar = sv * abar * abar * (2.0 * lna * X + dX);
  p->dPbar = sv * grr * (Y * dln + dY);
}

/* The v-derivative of dbar (which = 0) or Pbar (which = 1) at v; the
   point is kept in *p. */
static double deriv_of(const dc_jkr_geom *G, double v, int which, jg_point *p)
{
  jg_eval(G, v, p);
  return which ? p->dPbar : p->ddbar;
}

/* Brent's zero finder (zeroin) on that derivative over [a, b] with a sign
   change (fa < 0 < fb given, *pa_in and *pb the points at a and b); the
   root's point is returned in *pb. */
static int brent_deriv(const dc_jkr_geom *G, int which, double a, double b, double fa, double fb,
                       const jg_point *pa_in, jg_point *pb, double *root)
{
  if (!(fa < 0.0 && fb > 0.0)) return DC_ENOCONV;
  double c = a, fc = fa, d = b - a, e = d;
  jg_point pa = *pa_in, pc = pa;
  for (int it = 0; it < 200; it++) {
    if ((fb > 0.0) == (fc > 0.0)) { c = a; fc = fa; pc = pa; d = e = b - a; }
    if (fabs(fc) < fabs(fb)) {
      a = b; b = c; c = a; fa = fb; fb = fc; fc = fa;
      pa = *pb; *pb = pc; pc = pa;
    }
    /* 1e-12 relative in v: the extremal values (delta_break, F_pull) are
       then exact to rounding (second order), e2_break and e2_pull to ~1e-12 */
    const double tol = 1e-12 * fabs(b) + 1e-300;
    const double xm = 0.5 * (c - b);
    if (fabs(xm) <= tol || fb == 0.0) { *root = b; return DC_OK; }
    if (fabs(e) >= tol && fabs(fa) > fabs(fb)) {
      double s = fb / fa, pp, q;
      if (a == c) { pp = 2.0 * xm * s; q = 1.0 - s; }
      else {
        const double qq = fa / fc, r = fb / fc;
        pp = s * (2.0 * xm * qq * (qq - r) - (b - a) * (r - 1.0));
        q = (qq - 1.0) * (r - 1.0) * (s - 1.0);
      }
      if (pp > 0.0) q = -q; else pp = -pp;
      if (2.0 * pp < fmin(3.0 * xm * q - fabs(tol * q), fabs(e * q))) { e = d; d = pp / q; }
      else { d = xm; e = d; }
    } else { d = xm; e = d; }
    a = b; fa = fb; pa = *pb;
    b += fabs(d) > tol ? d : (xm > 0.0 ? tol : -tol);
    fb = deriv_of(G, b, which, pb);
  }
  *root = b;
  return DC_ENOCONV;
}

/* Bracket [lo, hi] around the guess of extremum `which` (0: separation,
   1: pull-off), half-width `hw` (relative), clipped to [vmin, vmax]. The
   guess: ln(v/v_H) from jkr_extrema_guess.h (the library's own searches at
   16 ratios per decade) by 4-point Lagrange interpolation in log10 of the
   ratio, within 4e-7 of the extremum; it only places the bracket, the
   search finds the extremum to rounding. */
static void ext_bracket(const dc_jkr_geom *G, int which, double hw, double vmin, double vmax,
                        double *lo, double *hi)
{
  double u = -DC_JKR_GUESS_PER_DECADE * log10(G->lam2);
  if (!(u > 0.0)) u = 0.0;
  if (u > DC_JKR_GUESS_ROWS - 1) u = DC_JKR_GUESS_ROWS - 1;
  int i = (int)u - 1;
  if (i < 0) i = 0;
  if (i > DC_JKR_GUESS_ROWS - 4) i = DC_JKR_GUESS_ROWS - 4;
  const double f = u - i;   /* position in the stencil rows i .. i+3, in [0, 3] */
  const int col = (G->use_m1 ? 2 : 0) + which;
  const double y0 = dc_jkr_extrema_guess[i][col], y1 = dc_jkr_extrema_guess[i + 1][col];
  const double y2 = dc_jkr_extrema_guess[i + 2][col], y3 = dc_jkr_extrema_guess[i + 3][col];
  const double lg = -(f - 1) * (f - 2) * (f - 3) / 6 * y0 + f * (f - 2) * (f - 3) / 2 * y1 -
                    f * (f - 1) * (f - 3) / 2 * y2 + f * (f - 1) * (f - 2) / 6 * y3;
  const double g = G->v_hertz * exp(lg);
  *lo = fmax(vmin, g * (1.0 - hw));
  *hi = fmin(vmax, g * (1.0 + hw));
}

/* Brent on the derivative `which` from a bracket around the tabulated
   guess, widened (x8) until the derivative changes sign, else over the
   full range [vmin, vmax]. */
static int find_extremum(const dc_jkr_geom *G, int which, double vmin, double vmax, double *root,
                         jg_point *p)
{
  jg_point plo;
  for (double hw = 4e-6; hw < 1.0; hw *= 8.0) {
    double lo, hi;
    ext_bracket(G, which, hw, vmin, vmax, &lo, &hi);
    if (!(lo < hi)) continue;
    const double flo = deriv_of(G, lo, which, &plo);
    if (!(flo < 0.0)) continue;
    const double fhi = deriv_of(G, hi, which, p);
    if (fhi > 0.0) return brent_deriv(G, which, lo, hi, flo, fhi, &plo, p, root);
  }
  const double flo = deriv_of(G, vmin, which, &plo);
  const double fhi = deriv_of(G, vmax, which, p);
  return brent_deriv(G, which, vmin, vmax, flo, fhi, &plo, p, root);
}

int dc_jkr_geometry(double R1, double R2, double Estar, double w, dc_jkr_geom *G)
{
  if (!(R1 > 0.0 && R2 > 0.0 && isfinite(R1) && isfinite(R2) && Estar > 0.0 && isfinite(Estar) &&
        w >= 0.0 && isfinite(w)))
    return DC_EDOM;
  const double Rmaj = fmax(R1, R2), Rmin = fmin(R1, R2);
  if (Rmin / Rmaj < DC_JKR_RATIO_MIN) return DC_EDOM;
  memset(G, 0, sizeof *G);
  G->R_major = Rmaj;
  G->R_minor = Rmin;
  G->Rhat = sqrt(Rmaj) * sqrt(Rmin);
  G->lambda = sqrt(Rmin / Rmaj);
  G->lam2 = Rmin / Rmaj;
  G->l2c = (Rmaj - Rmin) / Rmaj;
  G->Estar = Estar;
  G->w = w;
  /* The w = 0 contact is dc_hertz_contact with this geometry. For w > 0 it
     only gives the starting value of the Hertz shape, which near the circle
     (1 - ratio < 1e-3) is not needed: a failure there is not passed on. */
  int st = dc_hertz_geometry(Rmaj, Rmin, &G->hertz);
  const int hertz_ok = st == DC_OK;
  if (!hertz_ok) memset(&G->hertz, 0, sizeof G->hertz);
  G->e2_hertz = G->hertz.e2;
  G->circular = G->l2c < DC_JKR_CIRCULAR_TOL;
  G->a_scale = dc_jkr_cbrt_scale_(8.0 * w / (M_PI * Estar), G->Rhat * G->Rhat);
  G->delta_scale = G->a_scale * G->a_scale / (2.0 * G->Rhat);
  G->F_scale = 8.0 * w * G->Rhat;
  if (!(G->delta_scale > 0.0)) {  /* w = 0 (or w/E* so small it underflows) */
    if (!hertz_ok) return st;
    G->w = 0.0;
    G->a_scale = G->delta_scale = G->F_scale = 0.0;
    G->e2_break = G->e2_pull = G->e2_hertz;
    return DC_OK;
  }
  if (G->circular) {
    const double R = G->Rhat;
    G->delta_break = dc_jkr_sphere_delta_break(R, Estar, w);
    G->F_break = -5.0 / 6.0 * M_PI * w * R;
    G->F_pull = -dc_jkr_sphere_pulloff(R, w);
    /* pull-off at a^3 = 9 pi w R^2/(8 E*): delta = a^2/R - (2 pi w a/E*)^1/2 */
    const double ap = cbrt(9.0 * M_PI * w * R * R / (8.0 * Estar));
    G->delta_pull = ap * ap / R - sqrt(2.0 * M_PI * w * ap / Estar);
    return DC_OK;
  }
  /* Solver variable v (e^2, or 1 - e^2 for slender contacts), and the
     Hertz state as the zero of Qn (dc_jkr_Qn_) by Newton's method. Start:
     dc_hertz_geometry's e^2, except near the circle, where that comes from
     the ratio R_minor/R_major and so carries an absolute error ~eps (all
     of e^2 ~ 4/3 (1 - ratio) at 1 - ratio = 1e-9 and below); there Qn =
     l2c pi/4 - 3 pi m/16 + O(m^2, l2c m) gives e^2 = 4/3 l2c. */
  if (!hertz_ok && !(G->l2c < 1e-3)) return st;
  G->use_m1 = G->e2_hertz > 0.5;
  double vH = G->use_m1 ? G->hertz.m1 : G->hertz.e2;
  if (G->l2c < 1e-3) vH = 4.0 / 3.0 * G->l2c;
  for (int i = 0;; i++) {
    const double m = G->use_m1 ? 1.0 - vH : vH, m1 = G->use_m1 ? vH : 1.0 - vH;
    dc_ellint el;
    if (m <= 0.5) dc_ellint_m(m, &el); else dc_ellint_m1(m1, &el);
    double Qn, dQn;
    dc_jkr_Qn_(G, m, m1, &el, &Qn, &dQn);
    const double step = (G->use_m1 ? -1.0 : 1.0) * Qn / dQn;
    double vn = vH - step;
    if (!(vn > 0.0 && vn < 1.0)) vn = vn <= 0.0 ? 0.5 * vH : 0.5 * (1.0 + vH);
    if (i == 40 || !isfinite(vn)) return DC_ENOCONV;
    /* Newton is quadratic: once the step is at the rounding level of Qn
       (which can leave it a few eps above 4 eps vH for ever, seen at
       R_minor/R_major = 0.0772), applying it is exact to rounding */
    const int done = fabs(step) <= 64.0 * DBL_EPSILON * vH;
    vH = vn;
    if (done) break;
  }
  G->v_hertz = vH;
  G->e2_hertz = G->use_m1 ? 1.0 - vH : vH;
  /* Extrema of dbar and Pbar on the family: dbar -> 0- and Pbar -> 0-
     for a vanishing contact (e^2 -> 0), both -> +oo at the Hertz end. In v
     the derivative is < 0 towards the vanishing contact when v = e^2 and
     > 0 when v = 1 - e^2. */
  const double v0 = G->use_m1 ? 1.0 - 1e-6 * G->e2_hertz : 1e-6 * vH;  /* near e^2 = 0 */
  const double v1 = G->use_m1 ? vH * (1.0 + 1e-6) : vH * (1.0 - 1e-6);  /* near Hertz   */
  double vb, vp;
  jg_point p, pp;
  st = find_extremum(G, 0, fmin(v0, v1), fmax(v0, v1), &vb, &p);
  if (st != DC_OK) return st;
  st = find_extremum(G, 1, fmin(vb, v1), fmax(vb, v1), &vp, &pp);
  if (st != DC_OK) return st;
  G->v_break = vb;
  G->e2_break = p.m;
  G->dbar_break = p.dbar;
  G->delta_break = G->delta_scale * p.dbar;
  G->F_break = G->F_scale * p.Pbar;
  const double dbar_b = p.dbar;
  p = pp;
  G->e2_pull = p.m;
  G->delta_pull = G->delta_scale * p.dbar;
  G->F_pull = G->F_scale * p.Pbar;
  /* Hertz end: first-order coefficients and the switch to them */
  jg_eval(G, vH, &p);
  G->pert_X0 = p.X;
  G->pert_g0 = p.g;
  G->pert_rho0 = sqrt(p.g) * sqrt(p.X) * sqrt(sqrt(p.X));   /* g0^1/2 X0^3/4 */
  G->pert_X1 = p.dX / p.drho;
  G->pert_g1 = p.dg / p.drho;
  G->pert_P0 = p.Y / (p.X * sqrt(p.X));
  G->pert_P1 = (p.dY * p.X - 1.5 * p.Y * p.dX) / (p.X * p.X * sqrt(p.X)) / p.drho;
  const double rho_sw = 1e-8 * vH * fabs(p.drho);
  const double g23X = dc_jkr_cbrt_(p.g * p.g) * p.X, crs = dc_jkr_cbrt_(rho_sw);
  G->dbar_switch = g23X / (crs * crs * crs * crs);   /* g^2/3 X rho_sw^-4/3 */
  /* Starting values: |v_H - v| = |v_H - v_b|/(1 + c1 d^1/2 + c2 d^3/4),
     d = dbar - dbar_b; c2 from the Hertz asymptote (rho = |drho/dv|
     |v_H - v|, dbar = g^2/3 X rho^-4/3), c1 through the pull-off point. */
  const double span = fabs(vH - vb);
  G->guess_c2 = span * fabs(p.drho) / (sqrt(g23X) * sqrt(sqrt(g23X)));   /* (g^2/3 X)^-3/4 */
  const double dp = G->delta_pull / G->delta_scale - dbar_b;
  const double need = span / fabs(vH - vp) - 1.0 - G->guess_c2 * sqrt(dp) * sqrt(sqrt(dp));
  G->guess_c1 = need > 0.0 ? need / sqrt(dp) : 0.0;
  return DC_OK;
}

static void elliptic_fill(const dc_jkr_geom *G, const jg_point *p, double s_m, dc_jkr_state *s)
{
  /* s_m: remaining Newton correction in the solver variable, applied to
     first order */
  const double sg = G->use_m1 ? -1.0 : 1.0;   /* dm/dv */
  const double g = p->g + p->dg * s_m;
  const double abar = p->abar + p->dabar * s_m;
  s->contact = 1;
  s->a = G->a_scale * abar;
  s->b = g * s->a;
  s->area = M_PI * s->a * s->b;
  s->e2 = p->m + sg * s_m;
  s->F = G->F_scale * (p->Pbar + p->dPbar * s_m);
  s->delta = G->delta_scale * (p->dbar + p->ddbar * s_m);
  s->kn = finite_kn(sg * G->F_scale * p->dPbar, sg * G->delta_scale * p->ddbar);
}

int dc_jkr_at_eccentricity(const dc_jkr_geom *G, double e2, dc_jkr_state *s)
{
  if (G->circular || G->w == 0.0 || !(e2 > 0.0 && e2 < G->e2_hertz)) return DC_EDOM;
  jg_point p;
  const double sg = G->use_m1 ? -1.0 : 1.0;
  jg_eval(G, G->use_m1 ? 1.0 - e2 : e2, &p);
  if (!(p.rho > 0.0)) return DC_ERANGE;
  elliptic_fill(G, &p, 0.0, s);
  if (sg * p.ddbar <= 0.0) s->kn = finite_kn(-sg * G->F_scale * p.dPbar, -sg * G->delta_scale * p.ddbar);
  return DC_OK;
}

int dc_jkr_in_contact(const dc_jkr_geom *G, int was_in_contact, double delta)
{
  return delta >= 0.0 || (was_in_contact && delta >= G->delta_break);
}

/* The hint after a converged solve at v (ln d = Lt): the slope du/dL of
   u = ln((v - v_b)/(v_H - v)) against L = ln(dbar - dbar_b). */
static void set_hint(dc_jkr_hint *h, double v, double vb, double vH, double Lt, double d, double ddbar)
{
  h->v = v;
  h->L = Lt;
  const double dudv = (vH - vb) / ((v - vb) * (vH - v));
  const double s = dudv * d / ddbar;
  h->dudL = isfinite(s) && s > 0.0 ? s : 0.0;
}

int dc_jkr_contact(const dc_jkr_geom *G, double delta, dc_jkr_hint *hint, dc_jkr_state *s)
{
  if (!isfinite(delta)) return DC_EDOM;
  if (G->w == 0.0) {
    if (delta < 0.0) { zero_state(delta, s); return DC_OK; }
    dc_hertz_state h;
    int st = dc_hertz_contact(&G->hertz, G->Estar, delta, &h);
    if (st != DC_OK) return st;
    s->contact = 1; s->F = h.F; s->delta = delta; s->a = h.a; s->b = h.b;
    s->area = h.area; s->e2 = G->e2_hertz; s->kn = h.kn;
    return DC_OK;
  }
  if (G->circular) return dc_jkr_sphere(G->Rhat, G->Estar, G->w, delta, s);
  if (delta < G->delta_break) { zero_state(delta, s); return DC_OK; }
  const double dbar_t = delta / G->delta_scale;
  if (dbar_t > G->dbar_switch) {
    /* first order in rho ~ dbar^-3/4 < 3e-8: the neglected O(rho^2) is
       below rounding */
    const double rho = G->pert_rho0 / (sqrt(dbar_t) * sqrt(sqrt(dbar_t)));
    const double X = G->pert_X0 + G->pert_X1 * rho;
    const double g = G->pert_g0 + G->pert_g1 * rho;
    const double Fd = G->F_scale * dbar_t * sqrt(dbar_t);
    s->contact = 1;
    s->delta = delta;
    s->F = Fd * (G->pert_P0 + G->pert_P1 * rho);
    s->a = G->a_scale * sqrt(dbar_t / X);
    s->b = g * s->a;
    s->area = M_PI * s->a * s->b;
    s->e2 = (1.0 - g) * (1.0 + g);
    s->kn = (1.5 * s->F - 0.75 * Fd * G->pert_P1 * rho) / delta;
    if (hint) { hint->v = G->use_m1 ? g * g : s->e2; hint->dudL = 0.0; }
    return DC_OK;
  }
  const double vH = G->v_hertz, vb = G->v_break;
  jg_point p;
  const double dbar_b = G->dbar_break;
  const double dtarget = dbar_t - dbar_b;
  if (!(dtarget > 0.0)) {   /* exactly at the separation point */
    jg_eval(G, vb, &p);
    elliptic_fill(G, &p, 0.0, s);
    s->delta = delta;
    if (hint) { hint->v = vb; hint->dudL = 0.0; }
    return DC_OK;
  }
  double v;
  const double Lt = log(dtarget);
  if (hint && (hint->v - vb) * (hint->v - vH) < 0.0) {
    v = hint->v;
    /* predictor: u linear in L from the previous solve (u(L) is close to
       linear, so this is usually within the 1e-8 tolerance below and one
       evaluation suffices) */
    if (hint->dudL > 0.0 && isfinite(hint->L)) {
      const double du = hint->dudL * (Lt - hint->L);
      if (fabs(du) < 1.0) {
        const double rn = (v - vb) / (vH - v) * exp(du);
        const double vn = (vb + vH * rn) / (1.0 + rn);
        if ((vn - vb) * (vn - vH) < 0.0) v = vn;
      }
    }
  } else {
    const double sd = sqrt(dtarget);
    v = vH - (vH - vb) / (1.0 + sd * (G->guess_c1 + G->guess_c2 * sqrt(sd)));
  }
  /* Newton on ln(dbar(v) - dbar_b) = ln(dtarget): dbar - dbar_b grows like
     (v - v_b)^2 at the separation point and like |v_H - v|^-4/3 at the
     Hertz end, so its logarithm is close to linear in ln of either
     distance and the iteration neither stalls at the vertical tangent nor
     jumps past the pole. Bracketed: lo has dbar < target, hi dbar > target. */
  double lo = vb, hi = vH;
  for (int it = 0; it < 60; it++) {
    jg_eval(G, v, &p);
    const double d = p.dbar - dbar_b;
    const double sgn = vH > vb ? 1.0 : -1.0;   /* dbar increases along sgn */
    if (!(d > 0.0) || !(sgn * p.ddbar > 0.0) || !(p.rho > 0.0)) {
      /* rounding at either end of the bracket: bisect */
      if (!(p.rho > 0.0)) hi = v; else lo = v;
      v = 0.5 * (lo + hi);
      continue;
    }
    if (p.dbar > dbar_t) hi = v; else lo = v;
    const double lin = (dbar_t - p.dbar) / p.ddbar;  /* plain Newton step */
    const double step = -(log(d) - Lt) * d / p.ddbar;
    const double scale = fmin(fabs(vH - v), fabs(v - vb));
    const double tol_v = fmax(1e-8 * scale, 16.0 * DBL_EPSILON * (fabs(vH) + fabs(dbar_b / p.ddbar)));
    if (fabs(step) <= tol_v || fabs(hi - lo) <= 4.0 * DBL_EPSILON * fabs(v)) {
      elliptic_fill(G, &p, lin, s);
      s->delta = delta;
      if (hint) set_hint(hint, v + lin, vb, vH, Lt, dtarget, p.ddbar);
      return DC_OK;
    }
    /* the step is taken in u = ln((v - v_b)/(v_H - v)), in which ln d is
       close to linear at both ends (slope 2 at the separation point, 4/3
       at the Hertz end), so Newton's quadratic error term is small and a
       warm start usually converges in two evaluations (plain Newton steps
       in v, even within a few per cent of the root, need three); to first
       order this is the step above */
    const double r = (v - vb) / (vH - v);
    const double du = step * (vH - vb) / ((v - vb) * (vH - v));
    const double rn = r * exp(du);
    double vn = (vb + vH * rn) / (1.0 + rn);
    if (!((vn - lo) * (vn - hi) < 0.0)) vn = 0.5 * (lo + hi);
    v = vn;
  }
  jg_eval(G, v, &p);
  elliptic_fill(G, &p, (dbar_t - p.dbar) / p.ddbar, s);
  s->delta = delta;
  if (hint) { hint->v = v; hint->dudL = 0.0; }
  return DC_ENOCONV;
}
