/* Maugis-Dugdale adhesion of spheres and the DMT limit (dc/maugis_dugdale.h). */
#include "dc/maugis_dugdale.h"
#include "dc/root_find.h"
#include "dc/status.h"
#include <float.h>
#include <math.h>

double dc_md_lambda_of_tabor(double mu_T)
{
  return 32.0 / (9.0 * sqrt(3.0)) * cbrt(9.0 / (16.0 * M_PI)) * mu_T;
}

/* s + (s^2 - 1) arctan s (MD1's first bracket): the series
   sum_j>=1 (-1)^(j-1) 4j/(4j^2 - 1) s^(2j+1) below s = 1/4 (16 terms:
   the next is below 1e-19 of the first) */
static double md_g1(double s)
{
  if (s >= 0.25) return s + (s * s - 1.0) * atan(s);
  const double s2 = s * s;
  double sum = 0.0;
  for (int j = 16; j >= 1; j--) sum = (j & 1 ? 1.0 : -1.0) * 4.0 * j / (4.0 * j * j - 1.0) + s2 * sum;
  return s * s2 * sum;
}

/* s arctan s - (1 + s^2)^1/2 + 1 (MD1's second bracket), without the cancellation */
static double md_g2(double s) { return s * atan(s) - s * s / (sqrt(1.0 + s * s) + 1.0); }

/* the domain: lambda in [1e-10, 1e10], abar in [1e-20, 1e20] */
static int lambda_ok(double l) { return l >= 1e-10 && l <= 1e10; }
static int abar_ok(double a) { return a >= 1e-20 && a <= 1e20; }

typedef struct {
  double c1, c2;   /* lambda abar^2 / 2, 4 lambda^2 abar / 3 */
} md1_ctx;

static double md1(double s, void *ctx, int slot)
{
  (void)slot;
  const md1_ctx *c = (const md1_ctx *)ctx;
  return c->c1 * md_g1(s) + c->c2 * md_g2(s) - 1.0;
}

int dc_md_state(double lambda, double abar, double *m, double *Pbar, double *Dbar)
{
  if (!lambda_ok(lambda) || !abar_ok(abar)) return DC_EDOM;
  md1_ctx c = {0.5 * lambda * abar * abar, 4.0 / 3.0 * lambda * lambda * abar};
  /* MD1 increases with s from -1 at s = 0: a bracket by doubling */
  double hi = 1.0, fhi = md1(hi, &c, 1);
  for (int k = 0; fhi <= 0.0; k++) {
    if (k > 2100 || !isfinite(fhi)) return DC_ENOCONV;
    hi *= 2.0;
    fhi = md1(hi, &c, 1);
  }
  dc_root_result r;
  if (dc_root_brent_ends(md1, &c, 0.0, hi, -1.0, fhi, 4.0 * DBL_EPSILON, 0.0, 400, &r) != DC_OK) return DC_ENOCONV;
  const double s = r.x, m2 = 1.0 + s * s, t = atan(s);
  *m = sqrt(m2);
  *Pbar = abar * abar * (abar - lambda * (s + m2 * t));   /* MD2 */
  *Dbar = abar * (abar - 4.0 / 3.0 * lambda * s);        /* MD3 */
  return DC_OK;
}

int dc_md_state_zero(double lambda, double *cbar, double *Pbar0, double *Dbar0)
{
  if (!lambda_ok(lambda)) return DC_EDOM;
  /* A c^2 + B c - 1 = 0, the positive root without cancellation */
  const double A = M_PI / 4.0 * lambda, B = 4.0 / 3.0 * lambda * lambda * (M_PI / 2.0 - 1.0);
  const double c = 2.0 / (B + sqrt(B * B + 4.0 * A));
  *cbar = c;
  *Pbar0 = -M_PI / 2.0 * lambda * c * c;
  *Dbar0 = -4.0 / 3.0 * lambda * c;
  return DC_OK;
}

/* Pbar (which = 0) or Dbar (which = 1) on the contact branch at abar (abar
   below the domain: the abar -> 0 end) */
static double md_branch(double lambda, double abar, int which)
{
  double m, P, D;
  if (abar < 1e-20) {
    dc_md_state_zero(lambda, &m, &P, &D);
    return which ? D : P;
  }
  if (dc_md_state(lambda, abar, &m, &P, &D) != DC_OK) return NAN;
  return which ? D : P;
}

/* The least Pbar or Dbar of the contact branch over abar >= 0 and where it
   occurs (0: the abar -> 0 end): the least of 97 samples on [0, 3] (JKR's
   extremes lie at abar = (3/2)^1/3 = 1.145 and 6^-1/3 = 0.55, MD's below
   them), then golden section on the bracket around it. */
static int md_branch_min(double lambda, int which, double *vmin, double *amin)
{
  enum { NS = 96 };
  const double top = 3.0;
  int kmin = 0;
  double fmin = md_branch(lambda, 0.0, which);
  for (int k = 1; k <= NS; k++) {
    const double v = md_branch(lambda, top * k / NS, which);
    if (!isfinite(v)) return DC_ENOCONV;
    if (v < fmin) { fmin = v; kmin = k; }
  }
  double lo = top * (kmin > 0 ? kmin - 1 : 0) / NS, hi = top * (kmin < NS ? kmin + 1 : NS) / NS;
  const double g = 0.5 * (3.0 - sqrt(5.0));
  double x1 = lo + g * (hi - lo), x2 = hi - g * (hi - lo);
  double f1 = md_branch(lambda, x1, which), f2 = md_branch(lambda, x2, which);
  for (int it = 0; it < 200 && hi - lo > 1e-12 * (1.0 + hi); it++) {
    if (f1 <= f2) {
      hi = x2; x2 = x1; f2 = f1;
      x1 = lo + g * (hi - lo);
      f1 = md_branch(lambda, x1, which);
    } else {
      lo = x1; x1 = x2; f1 = f2;
      x2 = hi - g * (hi - lo);
      f2 = md_branch(lambda, x2, which);
    }
  }
  double a = f1 <= f2 ? x1 : x2, v = f1 <= f2 ? f1 : f2;
  if (kmin == 0) {   /* the least may be the abar -> 0 end */
    const double v0 = md_branch(lambda, 0.0, which);
    if (v0 <= v) { v = v0; a = 0.0; }
  }
  if (!isfinite(v)) return DC_ENOCONV;
  *vmin = v;
  *amin = a;
  return DC_OK;
}

int dc_md_pulloff(double lambda, double *Pbarc, double *abarc)
{
  if (!lambda_ok(lambda)) return DC_EDOM;
  return md_branch_min(lambda, 0, Pbarc, abarc);
}

int dc_md_separation(double lambda, double *Dbar_sep, double *abar_sep)
{
  if (!lambda_ok(lambda)) return DC_EDOM;
  return md_branch_min(lambda, 1, Dbar_sep, abar_sep);
}

typedef struct {
  double lambda, D;
} md_overlap_ctx;

static double md_overlap(double abar, void *ctx, int slot)
{
  (void)slot;
  const md_overlap_ctx *c = (const md_overlap_ctx *)ctx;
  return md_branch(c->lambda, abar, 1) - c->D;
}

int dc_md_at_overlap(double lambda, double Dbar, int *contact, double *abar, double *m, double *Pbar)
{
  if (!lambda_ok(lambda) || !(fabs(Dbar) <= 1e30)) return DC_EDOM;
  double Ds, as;
  int st = dc_md_separation(lambda, &Ds, &as);
  if (st != DC_OK) return st;
  if (Dbar < Ds) {
    *contact = 0;
    *abar = *m = *Pbar = 0.0;
    return DC_OK;
  }
  /* Dbar(abar) increases from Dbar_sep at abar_sep: a bracket by doubling, then Brent */
  md_overlap_ctx c = {lambda, Dbar};
  const double lo = as > 1e-20 ? as : 1e-20;
  double flo = md_overlap(lo, &c, 0), hi = fmax(2.0 * lo, 1.0), fhi = md_overlap(hi, &c, 1);
  for (int k = 0; fhi < 0.0; k++) {
    if (k > 200 || !isfinite(fhi)) return DC_ENOCONV;
    hi *= 2.0;
    fhi = md_overlap(hi, &c, 1);
  }
  if (flo > 0.0) flo = 0.0;   /* rounding at the separation point itself */
  dc_root_result r;
  if (dc_root_brent_ends(md_overlap, &c, lo, hi, flo, fhi, 4.0 * DBL_EPSILON, 0.0, 400, &r) != DC_OK) return DC_ENOCONV;
  double D;
  if (r.x <= 1e-20) {
    dc_md_state_zero(lambda, m, Pbar, &D);   /* the abar -> 0 end: m holds cbar there */
    *m = HUGE_VAL;
  } else if ((st = dc_md_state(lambda, r.x, m, Pbar, &D)) != DC_OK) {
    return st;
  }
  *contact = 1;
  *abar = r.x;
  return DC_OK;
}

/* MD1's brackets' derivatives: g1' = 2 s arctan s + 2 s^2/(1 + s^2), g2' = arctan s + s/(1 + s^2) - s/(1 + s^2)^1/2 */
static double md_dg1(double s) { return 2.0 * s * atan(s) + 2.0 * s * s / (1.0 + s * s); }
static double md_dg2(double s) { return atan(s) + s / (1.0 + s * s) - s / sqrt(1.0 + s * s); }

/* MD1's and MD3's residuals at (abar, s) for the overlap D, and the larger
   of them scaled by the sizes of their terms */
static double md_residuals(double lambda, double D, double a, double x, double *r1, double *r2)
{
  const double l2 = lambda * lambda, t1 = 0.5 * lambda * a * a * md_g1(x), t2 = 4.0 / 3.0 * l2 * a * md_g2(x);
  const double u1 = a * a, u2 = 4.0 / 3.0 * lambda * a * x;
  *r1 = t1 + t2 - 1.0;
  *r2 = u1 - u2 - D;
  return fmax(fabs(*r1) / (1.0 + fabs(t1) + fabs(t2)), fabs(*r2) / (fabs(u1) + fabs(u2) + fabs(D) + 1e-300));
}

int dc_md_at_overlap_near(double lambda, double Dbar, double abar0, double s0, double *abar, double *s, double *Pbar)
{
  if (!lambda_ok(lambda) || !abar_ok(abar0) || !(s0 >= 0.0 && s0 <= 1e300) || !(fabs(Dbar) <= 1e30)) return DC_EDOM;
  const double l2 = lambda * lambda;
  double a = abar0, x = s0, r1, r2;
  double norm = md_residuals(lambda, Dbar, a, x, &r1, &r2);
  for (int it = 0; it < 40; it++) {
    if (norm <= 4.0 * DBL_EPSILON) {
      const double m2 = 1.0 + x * x, P = a * a * (a - lambda * (x + m2 * atan(x)));   /* MD2 */
      if (!abar_ok(a) || !isfinite(P)) return DC_ENOCONV;
      *abar = a;
      *s = x;
      *Pbar = P;
      return DC_OK;
    }
    /* J (da, dx) = -(r1, r2) */
    const double j11 = lambda * a * md_g1(x) + 4.0 / 3.0 * l2 * md_g2(x);
    const double j12 = 0.5 * lambda * a * a * md_dg1(x) + 4.0 / 3.0 * l2 * a * md_dg2(x);
    const double j21 = 2.0 * a - 4.0 / 3.0 * lambda * x, j22 = -4.0 / 3.0 * lambda * a;
    const double det = j11 * j22 - j12 * j21;
    if (!(fabs(det) > 0.0) || !isfinite(det)) return DC_ENOCONV;
    const double da = (-r1 * j22 + r2 * j12) / det, dx = (-r2 * j11 + r1 * j21) / det;
    /* halved steps: a trust region (abar within a factor 4, s within 4 s + 1) and a falling residual */
    double step = 1.0, an, xn, r1n = 0.0, r2n = 0.0, nn = HUGE_VAL;
    for (int h = 0;; h++) {
      if (h > 30) return DC_ENOCONV;
      an = a + step * da;
      xn = x + step * dx;
      if (an > 0.25 * a && an < 4.0 * a && xn >= 0.0 && xn <= 4.0 * x + 1.0) {
        nn = md_residuals(lambda, Dbar, an, xn, &r1n, &r2n);
        if (nn < norm || nn <= 4.0 * DBL_EPSILON) break;
      }
      step *= 0.5;
    }
    a = an;
    x = xn;
    r1 = r1n;
    r2 = r2n;
    norm = nn;
  }
  return DC_ENOCONV;
}

double dc_dmt_pulloff(double R_major, double R_minor, double w)
{
  if (!(R_major > 0.0 && R_minor > 0.0 && w >= 0.0 && isfinite(R_major) && isfinite(R_minor) && isfinite(w)))
    return NAN;
  return 2.0 * M_PI * w * sqrt(R_major) * sqrt(R_minor);
}

int dc_dmt_contact(const dc_hertz_geom *g, double Estar, double w, double delta, dc_contact *c)
{
  if (!(w >= 0.0 && isfinite(w) && isfinite(delta) && Estar > 0.0 && isfinite(Estar))) return DC_EDOM;
  const double Fpo = dc_dmt_pulloff(g->R_major, g->R_minor, w);
  if (!isfinite(Fpo)) return DC_ERANGE;
  dc_contact o = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0};
  if (delta > 0.0) {
    dc_hertz_state h;
    const int st = dc_hertz_contact(g, Estar, delta, &h);
    if (st != DC_OK) return st;
    o.F = h.F - Fpo;
    o.kn = h.kn;
    o.area = h.area;
    o.a = h.a;
    o.b = h.b;
    o.F_bound = h.F + Fpo;
    o.formed = 1;
    if (!isfinite(o.F_bound)) return DC_ERANGE;
  }
  *c = o;
  return DC_OK;
}
