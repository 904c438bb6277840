/* Johnson-Greenwood approximate JKR for elliptical contacts and classical
   JKR for spheres (review Eqs. 19-28; derivation, conventions and the seed
   corrections are in dc/jkr_elliptic.h). */
#include "dc/jkr_elliptic.h"
#include "dc/elliptic_integrals.h"
#include "dc/hertz_elliptic.h"
#include "dc/status.h"
#include <float.h>
#include <math.h>
#include <string.h>

#define KN_MAX 1e300

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
  const double a3 = a * a * a;
  const double adh = sqrt(8.0 * M_PI * w * Estar * a3);
  s->contact = 1;
  s->a = s->b = a;
  s->area = M_PI * a * a;
  s->e2 = 0.0;
  s->F = 4.0 * Estar * a3 / (3.0 * R) - adh;
  s->delta = a * a / R - sqrt(2.0 * M_PI * w * a / Estar);
  /* dF/da = 4 E a^2/R - 3/2 adh/a, d delta/da = 2a/R - 1/2 (2 pi w/(E a))^1/2 */
  const double num = 4.0 * Estar * a * a / R - 1.5 * adh / a;
  const double den = 2.0 * a / R - 0.5 * sqrt(2.0 * M_PI * w / (Estar * a));
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
  const double As = cbrt(8.0 * w / (M_PI * Estar)) * cbrt(R * R);
  const double Ds = As * As / (2.0 * R);
  if (!(Ds > 0.0) || delta > 1e10 * Ds) {
    /* Hertz-dominated (or w = 0): a^2 = R (delta + (2 pi w a/E*)^1/2) by
       fixed point; the contraction factor is ~dbar^-3/4 <= 3e-8, so three
       steps from the Hertz radius reach rounding. */
    if (delta < 0.0) { zero_state(delta, s); return DC_OK; }
    if (delta == 0.0) {
      zero_state(delta, s);
      if (w == 0.0) s->contact = 1;
      return DC_OK;
    }
    double a = sqrt(R * delta);
    for (int i = 0; i < 3 && w > 0.0; i++) a = sqrt(R * (delta + sqrt(2.0 * M_PI * w * a / Estar)));
    sphere_fill(R, Estar, w, a, s);
    s->delta = delta;
    return DC_OK;
  }
  if (delta < dc_jkr_sphere_delta_break(R, Estar, w)) { zero_state(delta, s); return DC_OK; }
  const double xb = cbrt(M_PI / 8.0);          /* break: 8 x^3 = pi */
  const double dbar_b = -0.75 * M_PI * xb;     /* 2 xb^4 - pi xb     */
  const double dbar = fmax(delta / Ds, dbar_b);
  /* x^4 - p x - q = 0, p = pi/2, q = dbar/2 (Ferrari). Resolvent cubic
     y^3 + q y - p^2/8 = 0; its largest root y > 0 gives
     x = ((2y)^1/2 + (p (2/y)^1/2 - 2y)^1/2) / 2, the larger real root. */
  const double P = 0.5 * dbar, A = M_PI * M_PI / 64.0;  /* A = p^2/16 */
  const double disc = A * A + P * P * P / 27.0;
  double y;
  if (disc >= 0.0) {
    const double S = sqrt(disc);
    const double u = cbrt(A + S), v = cbrt(A - S);
    y = 2.0 * A / (u * u + v * v + P / 3.0);  /* = u + v without cancellation */
  } else {
    const double r = sqrt(-P / 3.0);
    double c = -3.0 * A / (P * r);            /* cos(3 theta) */
    c = fmin(1.0, fmax(-1.0, c));
    y = 2.0 * r * cos(acos(c) / 3.0);
  }
  const double s2y = sqrt(2.0 * y);
  double x = 0.5 * (s2y + sqrt(fmax(0.0, M_PI / s2y - 2.0 * y)));
  /* one Newton step on 2 x^4 - pi x - dbar (skipped at the double root) */
  const double fp = 8.0 * x * x * x - M_PI;
  if (fp > 1e-6) {
    const double xn = x - (2.0 * x * x * x * x - M_PI * x - dbar) / fp;
    x = fmax(xn, xb);
  } else {
    x = fmax(x, xb);
  }
  const double a = As * x * x;
  const double x3 = x * x * x;
  s->contact = 1;
  s->a = s->b = a;
  s->area = M_PI * a * a;
  s->e2 = 0.0;
  s->delta = delta;
  s->F = 8.0 * w * R * (4.0 / (3.0 * M_PI) * x3 - 1.0) * x3;
  /* kn = (dF/dx)/(d delta/dx) = (8 w R/Ds) x^2 (8x^3 - 3 pi)/(pi (8x^3 - pi)) */
  s->kn = finite_kn(8.0 * w * R / Ds * x * x * (8.0 * x3 - 3.0 * M_PI), M_PI * (8.0 * x3 - M_PI));
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
static void jg_eval_m(const dc_jkr_geom *G, double m, double m1, jg_point *p);
static void jg_eval(const dc_jkr_geom *G, double v, jg_point *p)
{
  jg_point q;
  if (G->use_m1) {
    jg_eval_m(G, 1.0 - v, v, &q);
    q.dg = -q.dg; q.drho = -q.drho; q.dX = -q.dX; q.dY = -q.dY;
    q.dabar = -q.dabar; q.ddbar = -q.ddbar; q.dPbar = -q.dPbar;
  } else {
    jg_eval_m(G, v, 1.0 - v, &q);
  }
  *p = q;
}

static void jg_eval_m(const dc_jkr_geom *G, double m, double m1, jg_point *p)
{
  dc_ellint el;
  if (m <= 0.5) dc_ellint_m(m, &el); else dc_ellint_m1(m1, &el);
  const double K = el.K, D = el.D, B = el.B, C = el.C;
  const double lam = G->lambda, lam2 = G->lam2;
  const double dK = 0.5 * B / m1, dD = 0.5 * (D - C) / m1, dB = 0.5 * C;
  const double dC = dc_C_dm_(m, m1, D, C);

  const double Del = D * B + m1 * C * D + B * C;
  const double dDel = dD * B + D * dB - C * D + m1 * (dC * D + C * dD) + dB * C + B * dC;
  const double lD = lam * Del;
  const double Pi2 = ((1.0 + lam2) * C + D) / lD;
  const double dPi2 = ((1.0 + lam2) * dC + dD) / lD - Pi2 * dDel / Del;
  double Qn, dQn;
  dc_jkr_Qn_(G, m, m1, &el, &Qn, &dQn);
  const double Q = Qn / lD;
  const double dQ = dQn / lD - Q * dDel / Del;
  const double g = sqrt(m1), dg = -0.5 / g;
  const double q4 = sqrt(g);                        /* g^1/2 */
  /* u = 1 - g^1/2 = (1 - g^2)/((1 + g^1/2)(1 + g)): no cancellation */
  const double u = m / ((1.0 + q4) * (1.0 + g));
  p->m1 = m1;
  const double du = 0.25 / (q4 * q4 * q4);
  const double rho = Q / u;
  const double drho = (dQ - rho * du) / u;

  const double X = m1 * Pi2 * K + Q * B - 2.0 * K * rho;
  const double dX = -Pi2 * K + m1 * (dPi2 * K + Pi2 * dK) + dQ * B + Q * dB - 2.0 * (dK * rho + K * drho);
  const double Y = m1 * Pi2 / 3.0 + Q / 3.0 - rho;
  const double dY = (-Pi2 + m1 * dPi2 + dQ) / 3.0 - drho;

  /* abar^3 = g / rho^2, dbar = abar^2 X, Pbar = g Y / rho^2 */
  const double abar = cbrt(g / (rho * rho));
  const double lna = (dg / g - 2.0 * drho / rho) / 3.0;   /* d ln abar/dm */
  p->m = m; p->g = g; p->rho = rho; p->X = X; p->Y = Y;
  p->abar = abar;
  p->dbar = abar * abar * X;
  p->Pbar = g * Y / (rho * rho);
  p->dg = dg; p->drho = drho; p->dX = dX; p->dY = dY;
  p->dabar = abar * lna;
  p->ddbar = abar * abar * (2.0 * lna * X + dX);
  p->dPbar = p->Pbar * (dg / g - 2.0 * drho / rho) + g * dY / (rho * rho);
}

/* Brent's zero finder (zeroin) on the m-derivative of dbar (which = 0) or
   Pbar (which = 1) over [lo, hi] with a sign change. */
static double deriv_of(const dc_jkr_geom *G, double m, int which)
{
  jg_point p;
  jg_eval(G, m, &p);
  return which ? p.dPbar : p.ddbar;
}

static int brent_deriv(const dc_jkr_geom *G, int which, double a, double b, double *root)
{
  double fa = deriv_of(G, a, which), fb = deriv_of(G, b, which);
  if (!(fa < 0.0 && fb > 0.0)) return DC_ENOCONV;
  double c = a, fc = fa, d = b - a, e = d;
  for (int it = 0; it < 200; it++) {
    if ((fb > 0.0) == (fc > 0.0)) { c = a; fc = fa; d = e = b - a; }
    if (fabs(fc) < fabs(fb)) { a = b; b = c; c = a; fa = fb; fb = fc; fc = fa; }
    const double tol = 2.0 * 2.2e-16 * fabs(b) + 1e-300;
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
    a = b; fa = fb;
    b += fabs(d) > tol ? d : (xm > 0.0 ? tol : -tol);
    fb = deriv_of(G, b, which);
  }
  *root = b;
  return DC_ENOCONV;
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
     is not needed: there a failure of dc_hertz_geometry (it returns
     DC_ENOCONV at 1 - ratio = 1e-9 and 1e-15) is not passed on. */
  int st = dc_hertz_geometry(Rmaj, Rmin, &G->hertz);
  const int hertz_ok = st == DC_OK;
  if (!hertz_ok) memset(&G->hertz, 0, sizeof G->hertz);
  G->e2_hertz = G->hertz.e2;
  G->circular = G->l2c < DC_JKR_CIRCULAR_TOL;
  G->a_scale = cbrt(8.0 * w / (M_PI * Estar)) * cbrt(G->Rhat * G->Rhat);
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
    const int done = fabs(step) <= 4.0 * DBL_EPSILON * vH;
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
  st = G->use_m1 ? brent_deriv(G, 0, v1, v0, &vb) : brent_deriv(G, 0, v0, v1, &vb);
  if (st != DC_OK) return st;
  st = G->use_m1 ? brent_deriv(G, 1, v1, vb, &vp) : brent_deriv(G, 1, vb, v1, &vp);
  if (st != DC_OK) return st;
  G->v_break = vb;
  jg_point p;
  jg_eval(G, vb, &p);
  G->e2_break = p.m;
  G->dbar_break = p.dbar;
  G->delta_break = G->delta_scale * p.dbar;
  G->F_break = G->F_scale * p.Pbar;
  const double dbar_b = p.dbar;
  jg_eval(G, vp, &p);
  G->e2_pull = p.m;
  G->delta_pull = G->delta_scale * p.dbar;
  G->F_pull = G->F_scale * p.Pbar;
  /* Hertz end: first-order coefficients and the switch to them */
  jg_eval(G, vH, &p);
  G->pert_X0 = p.X;
  G->pert_g0 = p.g;
  G->pert_X1 = p.dX / p.drho;
  G->pert_g1 = p.dg / p.drho;
  G->pert_P0 = p.Y / (p.X * sqrt(p.X));
  G->pert_P1 = (p.dY * p.X - 1.5 * p.Y * p.dX) / (p.X * p.X * sqrt(p.X)) / p.drho;
  const double rho_sw = 1e-8 * vH * fabs(p.drho);
  G->dbar_switch = cbrt(p.g * p.g) * p.X * pow(rho_sw, -4.0 / 3.0);
  /* Starting values: |v_H - v| = |v_H - v_b|/(1 + c1 d^1/2 + c2 d^3/4),
     d = dbar - dbar_b; c2 from the Hertz asymptote (rho = |drho/dv|
     |v_H - v|, dbar = g^2/3 X rho^-4/3), c1 through the pull-off point. */
  const double span = fabs(vH - vb);
  G->guess_c2 = span * fabs(p.drho) * pow(cbrt(p.g * p.g) * p.X, -0.75);
  const double dp = G->delta_pull / G->delta_scale - dbar_b;
  const double need = span / fabs(vH - vp) - 1.0 - G->guess_c2 * pow(dp, 0.75);
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

int dc_jkr_contact(const dc_jkr_geom *G, double delta, double *hint, dc_jkr_state *s)
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
    const double rho = sqrt(G->pert_g0) * pow(G->pert_X0, 0.75) * pow(dbar_t, -0.75);
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
    if (hint) *hint = G->use_m1 ? g * g : s->e2;
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
    if (hint) *hint = vb;
    return DC_OK;
  }
  double v;
  if (hint && (*hint - vb) * (*hint - vH) < 0.0) {
    v = *hint;
  } else {
    v = vH - (vH - vb) / (1.0 + G->guess_c1 * sqrt(dtarget) + G->guess_c2 * pow(dtarget, 0.75));
  }
  /* Newton on ln(dbar(v) - dbar_b) = ln(dtarget): dbar - dbar_b grows like
     (v - v_b)^2 at the separation point and like |v_H - v|^-4/3 at the
     Hertz end, so its logarithm is close to linear in ln of either
     distance and the iteration neither stalls at the vertical tangent nor
     jumps past the pole. Bracketed: lo has dbar < target, hi dbar > target. */
  const double Lt = log(dtarget);
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
    const double step = -(log(d) - Lt) * d / p.ddbar;
    const double lin = (dbar_t - p.dbar) / p.ddbar;  /* plain Newton step */
    /* converged: the step is below 1e-8 of the distance to either end (ln d
       is smooth on that scale, so the first-order application of the step
       leaves O(1e-16) relative), or
       at the rounding level of dbar(v): near the Hertz end rho, and so
       dbar, carries a relative error ~eps v_H/|v_H - v| (Qn vanishes
       there), which moves the Newton step by ~eps v_H; near the separation
       point dbar - dbar_b carries an absolute error ~eps |dbar_b|, i.e. a
       step of ~eps |dbar_b / ddbar|. The remaining step is applied to first
       order (elliptic_fill). */
    const double scale = fmin(fabs(vH - v), fabs(v - vb));
    const double tol_v = fmax(1e-8 * scale, 16.0 * DBL_EPSILON * (fabs(vH) + fabs(dbar_b / p.ddbar)));
    if (fabs(step) <= tol_v || fabs(hi - lo) <= 4.0 * DBL_EPSILON * fabs(v)) {
      elliptic_fill(G, &p, lin, s);
      s->delta = delta;
      if (hint) *hint = v + lin;
      return DC_OK;
    }
    /* the step is taken in u = ln((v - v_b)/(v_H - v)), in which ln d is
       close to linear at both ends (slope 2 at the separation point, 4/3
       at the Hertz end), so Newton's quadratic error term is small and a
       warm start usually converges in two evaluations; to first order
       this is the step above */
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
  if (hint) *hint = v;
  return DC_ENOCONV;
}
