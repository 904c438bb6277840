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

/* A polynomial of degree 15 in x by Estrin's scheme (four levels, against
   Horner's fifteen dependent steps) */
static double md_poly15(const double c[16], double x)
{
  const double x2 = x * x, x4 = x2 * x2, x8 = x4 * x4;
  const double q0 = (c[0] + c[1] * x) + (c[2] + c[3] * x) * x2, q1 = (c[4] + c[5] * x) + (c[6] + c[7] * x) * x2;
  const double q2 = (c[8] + c[9] * x) + (c[10] + c[11] * x) * x2, q3 = (c[12] + c[13] * x) + (c[14] + c[15] * x) * x2;
  return (q0 + q1 * x4) + (q2 + q3 * x4) * x8;
}

/* s + (s^2 - 1) arctan s (MD1's first bracket): the series
   sum_j>=1 (-1)^(j-1) 4j/(4j^2 - 1) s^(2j+1) below s = 1/4 (16 terms:
   the next is below 1e-19 of the first) */
static const double md_g1_series[16] = {
  4.0 / 3.0, -8.0 / 15.0, 12.0 / 35.0, -16.0 / 63.0, 20.0 / 99.0, -24.0 / 143.0, 28.0 / 195.0, -32.0 / 255.0,
  36.0 / 323.0, -40.0 / 399.0, 44.0 / 483.0, -48.0 / 575.0, 52.0 / 675.0, -56.0 / 783.0, 60.0 / 899.0, -64.0 / 1023.0};
static double md_g1_small(double s) { return s * s * s * md_poly15(md_g1_series, s * s); }

/* arctan s below s = 1/4: s sum_k (-1)^k s^2k/(2k + 1), 16 terms (the next
   below 2e-21 of the first) */
static const double md_atan_series[16] = {
  1.0, -1.0 / 3.0, 1.0 / 5.0, -1.0 / 7.0, 1.0 / 9.0, -1.0 / 11.0, 1.0 / 13.0, -1.0 / 15.0,
  1.0 / 17.0, -1.0 / 19.0, 1.0 / 21.0, -1.0 / 23.0, 1.0 / 25.0, -1.0 / 27.0, 1.0 / 29.0, -1.0 / 31.0};

static double md_g1(double s) { return s >= 0.25 ? s + (s * s - 1.0) * atan(s) : md_g1_small(s); }

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

/* The contact branch in the variable s: MD1 is a quadratic in abar,
   A abar^2 + B abar = 1 with A = (lambda/2) g1(s), B = (4 lambda^2/3) g2(s),
   so abar = 2/(B + (B^2 + 4 A)^1/2) and with it Pbar (MD2), Dbar (MD3) and
   dDbar/ds (abar' = -(A' abar^2 + B' abar)/(B^2 + 4 A)^1/2; g1' = 2 s
   arctan s + 2 s^2/(1 + s^2), g2' = arctan s + s/(1 + s^2) - s/(1 +
   s^2)^1/2): one arctangent and two roots. Along the branch Dbar falls
   from +inf (s -> 0: abar -> inf) to the abar -> 0 end (s -> inf), through
   a least value (the fold) where lambda is above about 0.93. */
typedef struct {
  double a, P, D, dD, da, dP;
} md_point;

static void md_at_s(double lambda, double s, md_point *p)
{
  /* below s = 1/4: arctan s from its series, s^2/(q + 1) = q - 1 without its cancellation */
  const int small = s < 0.25;
  const double s2 = s * s, t = small ? s * md_poly15(md_atan_series, s2) : atan(s), q2 = 1.0 + s2, q = sqrt(q2);
  const double iq2 = 1.0 / q2;
  const double g1 = small ? md_g1_small(s) : s + (s2 - 1.0) * t, g2 = s * t - (small ? s2 / (q + 1.0) : q - 1.0);
  const double dg1 = 2.0 * s * (t + s * iq2), dg2 = t + s * iq2 - s * q * iq2;
  const double l43 = 4.0 / 3.0 * lambda, A = 0.5 * lambda * g1, B = l43 * lambda * g2, root = sqrt(B * B + 4.0 * A);
  const double a = 2.0 / (B + root), da = -(0.5 * lambda * dg1 * a + l43 * lambda * dg2) * a / root;
  const double u = l43 * a * s, w = s + q2 * t;
  p->a = a;
  p->P = a * a * (a - lambda * w);
  p->D = a * a - u;
  p->da = da;
  p->dD = 2.0 * a * da - l43 * (da * s + a);
  p->dP = 3.0 * a * a * da - lambda * a * (2.0 * da * w + 2.0 * a * (1.0 + s * t));   /* w' = 2 + 2 s arctan s */
}

int dc_md_branch_s(double lambda, double s, double *abar, double *Pbar, double *Dbar, double *dDds)
{
  if (!lambda_ok(lambda) || !(s >= 1e-30 && s <= 1e30)) return DC_EDOM;
  md_point p;
  md_at_s(lambda, s, &p);
  if (!(isfinite(p.a) && isfinite(p.P) && isfinite(p.D) && isfinite(p.dD))) return DC_ERANGE;
  *abar = p.a;
  *Pbar = p.P;
  *Dbar = p.D;
  *dDds = p.dD;
  return DC_OK;
}

/* Where the zone-only states meet the contact branch: c_z = 8 lambda/(3 pi),
   where the zone's overlap is least, and the branch end's cbar0, Dbar0;
   1 where the zone is stable beyond the end (cbar0 > c_z) */
typedef struct {
  double cz, c0, D0;
} md_ends;

static int md_ends_of(double lambda, md_ends *e)
{
  double P0;
  dc_md_state_zero(lambda, &e->c0, &P0, &e->D0);
  e->cz = 8.0 / (3.0 * M_PI) * lambda;
  return e->c0 > e->cz;
}

/* The fold: the s in (0, inf) where dDbar/ds changes sign (the first s =
   2^k, k from -40, with dDbar/ds >= 0, then bisection), or 0 where the
   branch falls all the way to its end: where the zone-only states are
   stable beyond the end (cbar0 > c_z), the curve of states rises through
   the end and the branch has no fold (at its far end dDbar/ds is rounding) */
static double md_fold_s(double lambda)
{
  md_ends e;
  if (md_ends_of(lambda, &e)) return 0.0;
  md_point p;
  double lo = 0.0, hi = 0.0;
  for (int k = -40; k <= 60; k++) {
    const double s = ldexp(1.0, k);
    md_at_s(lambda, s, &p);
    if (p.dD >= 0.0) {
      hi = s;
      break;
    }
    lo = s;
  }
  if (hi == 0.0) return 0.0;
  for (int it = 0; it < 200 && hi - lo > 4.0 * DBL_EPSILON * hi; it++) {
    const double mid = 0.5 * (lo + hi);
    md_at_s(lambda, mid, &p);
    if (p.dD >= 0.0) hi = mid;
    else lo = mid;
  }
  return 0.5 * (lo + hi);
}

/* The stable branch's state at Dbar >= the separation overlap: Newton in s
   from s0 inside a bracket (s_lo, s_hi) on which Dbar falls from above the
   target to below it (s_hi: the fold, or none), halving the bracket
   (geometrically) where Newton leaves it. Converged when the next Newton
   step is below 1e-7 s: that step is then taken to first order (its
   second-order term is of order 1e-14 of the state) without evaluating
   the branch again. */
static int md_solve(double lambda, double D, double sf, double s0, double *s, md_point *out)
{
  double lo = 0.0, hi = sf > 0.0 ? sf : HUGE_VAL, x = s0 > 0.0 && s0 < hi ? s0 : (hi < HUGE_VAL ? 0.5 * hi : 1.0);
  md_point p;
  for (int it = 0; it < 200; it++) {
    md_at_s(lambda, x, &p);
    const double r = p.D - D;
    if (!(isfinite(r) && isfinite(p.dD))) {   /* beyond the doubles (s too large): back inside the bracket */
      hi = x;
      x = lo > 0.0 ? sqrt(lo * hi) : 0.25 * hi;
      continue;
    }
    const double dx = p.dD < 0.0 ? -r / p.dD : HUGE_VAL;
    if (fabs(dx) <= 1e-7 * x) {
      *s = x + dx;
      p.a += p.da * dx;
      p.P += p.dP * dx;
      p.D = D;
      *out = p;
      return DC_OK;
    }
    if (r > 0.0) lo = x;   /* Dbar falls with s on the stable branch */
    else hi = x;
    double xn = x + dx;
    if (!(xn > lo && xn < hi)) xn = hi < HUGE_VAL ? (lo > 0.0 ? sqrt(lo * hi) : 0.25 * hi) : 4.0 * x;
    if (xn == lo || xn == hi) {   /* the bracket is one ulp wide: at the fold, to rounding */
      *s = x;
      *out = p;
      return DC_OK;
    }
    x = xn;
  }
  return DC_ENOCONV;
}

int dc_md_zone(double lambda, double Dbar, int *zone, double *cbar, double *Pbar)
{
  if (!lambda_ok(lambda) || !(fabs(Dbar) <= 1e30)) return DC_EDOM;
  md_ends e;
  const int stable = md_ends_of(lambda, &e);
  const double disc = e.cz * e.cz + 2.0 * (Dbar + 2.0 / (M_PI * lambda));
  *zone = stable && disc >= 0.0 && Dbar <= e.D0;
  const double c = *zone ? e.cz + sqrt(disc) : 0.0;   /* the stable root of Dbar(cbar) */
  *cbar = c;
  *Pbar = -M_PI / 2.0 * lambda * c * c;
  return DC_OK;
}

double dc_md_reach(double lambda)
{
  if (!lambda_ok(lambda)) return NAN;
  md_ends e;
  return md_ends_of(lambda, &e) ? fmax(1.0, 0.5 * e.cz * e.cz + 2.0 / (M_PI * lambda)) : 1.0;
}

const dc_history_field dc_md_history[DC_MD_CONTACT_NFIELDS] = {
  {"md_phase", 0}, {"md_x", 0}, {"md_s", 0}, {"md_lambda", 0}, {"md_pulloff", 0},
  {"md_sep", 0}, {"md_fold", 0}, {"md_last", 0}, {"md_dsdD", 0}, {"md_curve", 0},
};

/* Enters or keeps the contact branch at D from the guess s0; the fold and
   the separation overlap found on the contact's first entry */
static int md_contact(double D, dc_md_contact *h, double s0, double *Pbar, double *abar)
{
  const double l = h->lambda;
  double Dsep = h->Dsep, sfold = h->sfold;
  if (Dsep == 0.0) {   /* the separation overlap is negative: 0 means not yet found */
    sfold = md_fold_s(l);
    if (sfold > 0.0) {
      md_point p;
      md_at_s(l, sfold, &p);
      Dsep = p.D;
    } else {
      md_ends e;
      md_ends_of(l, &e);
      Dsep = e.D0;
    }
  }
  double s;
  md_point p;
  const int st = md_solve(l, D, sfold, s0, &s, &p);
  if (st != DC_OK) return st;   /* h untouched */
  h->Dsep = Dsep;
  h->sfold = sfold;
  /* ds/dDbar and d^2 s/dDbar^2 from the last two states on the branch, for the next predictor */
  const double dsdD = 1.0 / p.dD, dDs = D - h->Dlast;
  h->curve = h->phase == DC_MD_CONTACT && dDs != 0.0 ? (dsdD - h->dsdD) / dDs : 0.0;
  if (!isfinite(h->curve)) h->curve = 0.0;
  h->phase = DC_MD_CONTACT;
  h->x = p.a;
  h->s = s;
  h->Dlast = D;
  h->dsdD = dsdD;
  *Pbar = p.P;
  *abar = p.a;
  return DC_OK;
}

/* The zone's state at D, or apart */
static void md_zone_or_apart(double D, dc_md_contact *h, double *Pbar, double *abar)
{
  int zone;
  double c, P;
  dc_md_zone(h->lambda, D, &zone, &c, &P);
  h->phase = zone ? DC_MD_ZONE : DC_MD_APART;
  h->x = c;
  h->s = 0.0;
  *Pbar = P;
  *abar = 0.0;
}

int dc_md_step(double Dbar, dc_md_contact *h, double *Pbar, double *abar)
{
  const double l = h->lambda;
  if (!lambda_ok(l) || !(fabs(Dbar) <= 1e30)) return DC_EDOM;
  if (h->phase == DC_MD_CONTACT && Dbar >= h->Dsep) {
    /* on the branch: a second-order predictor from the last two states (its second-order
       term where it is the smaller); h is written only on success */
    const double dD = Dbar - h->Dlast, lin = dD * h->dsdD, quad = 0.5 * h->curve * dD * dD;
    const double s1 = h->s + lin + (fabs(quad) <= fabs(lin) ? quad : 0.0);
    return md_contact(Dbar, h, s1 > 0.0 && s1 <= DBL_MAX ? s1 : 0.25 * h->s, Pbar, abar);
  }
  if (h->phase == DC_MD_APART && Dbar < -2.0 / (M_PI * l)) {
    *Pbar = *abar = 0.0;
    return DC_OK;
  }
  dc_md_contact t = *h;
  int st = DC_OK;
  if (t.phase == DC_MD_CONTACT) {   /* below the separation overlap */
    md_zone_or_apart(Dbar, &t, Pbar, abar);
  } else {
    md_ends e;
    md_ends_of(l, &e);
    /* from apart the zone catches the jump where it is stable there; from the zone the
       contact forms where the overlap passes the branch's end */
    const int to_contact = t.phase == DC_MD_ZONE ? Dbar > e.D0 : !(e.c0 >= 2.0 * e.cz && Dbar <= e.D0);
    if (to_contact) st = md_contact(Dbar, &t, 0.0, Pbar, abar);
    else md_zone_or_apart(Dbar, &t, Pbar, abar);
  }
  if (st == DC_OK) *h = t;
  return st;
}

double dc_md_friction_load(dc_md_contact *h, double Pbar)
{
  if (h->Pc == 0.0) {
    double a;
    if (dc_md_pulloff(h->lambda, &h->Pc, &a) != DC_OK) return NAN;
  }
  return Pbar - 2.0 * h->Pc;
}

int dc_md_sphere_pair_of(double Estar, double w, double z0, dc_md_sphere_pair *p, dc_param_error *err)
{
  if (dc_param_check("equilibriumSeparation", z0, 0.0, 1, HUGE_VAL, 1, "(0, inf) m", err) != DC_OK ||
      dc_param_check("workOfAdhesion", w, 0.0, 1, HUGE_VAL, 1, "(0, inf) J/m^2 (w = 0: no adhesion law)", err) != DC_OK ||
      dc_param_check("youngsModulus (E*)", Estar, 0.0, 1, HUGE_VAL, 1, "(0, inf) Pa", err) != DC_OK)
    return DC_EDOM;
  const double K = 4.0 / 3.0 * Estar, sigma0 = 16.0 * w / (9.0 * sqrt(3.0) * z0);
  dc_md_sphere_pair q;
  q.Lam = 2.0 * sigma0 / cbrt(M_PI * w * K * K);
  q.Cd = cbrt(M_PI * M_PI * w * w / (K * K));
  q.Ca = cbrt(M_PI * w / K);
  q.piw = M_PI * w;
  q.h0 = w / sigma0;
  const double l5 = dc_md_lambda_of_tabor(5.0) / q.Lam, l01 = dc_md_lambda_of_tabor(0.1) / q.Lam;
  q.R_jkr = l5 * l5 * l5;
  q.R_dmt = l01 * l01 * l01;
  if (!(isfinite(q.Lam) && q.Lam > 0.0 && q.Cd > 0.0 && isfinite(q.Cd) && q.Ca > 0.0 && isfinite(q.Ca) &&
        isfinite(q.piw) && q.h0 > 0.0 && isfinite(q.h0) && q.R_dmt > 0.0 && q.R_dmt < q.R_jkr && isfinite(q.R_jkr))) {
    dc_param_check("equilibriumSeparation", z0, 0.0, 1, 0.0, 1, "a range whose scales are finite doubles", err);
    return DC_EDOM;
  }
  *p = q;
  return DC_OK;
}

/* One step in SI units for the sphere of radius R = r3^3: lambda set as
   the contact leaves DC_MD_APART, the scales from r3 */
static int md_si(const dc_md_sphere_pair *p, double r3, double delta, dc_md_contact *h, double *F, double *a)
{
  const double D = delta / (p->Cd * r3);
  if (!(fabs(delta) <= DBL_MAX)) return DC_EDOM;
  if (h->phase == DC_MD_APART) {
    if (!(delta > -p->h0)) {
      *F = *a = 0.0;
      return DC_OK;
    }
    const double l = p->Lam * r3;
    if (!lambda_ok(l) || !(fabs(D) <= 1e30)) return DC_EDOM;
    if (l != h->lambda) h->Dsep = h->Pc = 0.0;   /* the fold and the pull-off of another lambda */
    h->lambda = l;
  }
  double P, ab;
  const int st = dc_md_step(D, h, &P, &ab);
  if (st != DC_OK) return st;
  const double f = P * p->piw * r3 * r3 * r3, rad = ab * p->Ca * r3 * r3;
  if (!(fabs(f) <= DBL_MAX && rad <= DBL_MAX)) return DC_ERANGE;
  *F = f;
  *a = rad;
  return DC_OK;
}

int dc_md_sphere(const dc_md_sphere_pair *p, double R, double delta, dc_md_contact *h, double *F, double *a)
{
  if (!(R > 0.0 && R <= DBL_MAX)) return DC_EDOM;
  /* R is the pair's for the contact's life: its cube root from lambda once formed */
  return md_si(p, h->phase == DC_MD_APART ? cbrt(R) : h->lambda / p->Lam, delta, h, F, a);
}

int dc_md_ellipse(const dc_md_sphere_pair *p, const dc_hertz_geom *g, double delta, dc_md_contact *h, double *F,
                  double *a)
{
  if (!(g->R_force > 0.0 && g->R_force <= DBL_MAX)) return DC_EDOM;
  return md_si(p, cbrt(g->R_force), delta, h, F, a);
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
