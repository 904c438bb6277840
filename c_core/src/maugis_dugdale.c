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

/* MD1's and MD3's residuals and Jacobian at (abar, s) for the overlap D,
   one arctan and one root per point: g1, g2 (MD1's brackets) and their
   derivatives g1' = 2 s arctan s + 2 s^2/(1 + s^2), g2' = arctan s +
   s/(1 + s^2) - s/(1 + s^2)^1/2; norm: the larger residual scaled by the
   sizes of its terms */
typedef struct {
  double r1, r2, norm, j11, j12, j21, j22, t;
} md_point;

static void md_eval(double lambda, double D, double a, double x, md_point *p)
{
  const double l2 = lambda * lambda, x2 = x * x, t = atan(x), q = sqrt(1.0 + x2);
  const double g1 = x < 0.25 ? md_g1(x) : x + (x2 - 1.0) * t, g2 = x * t - x2 / (q + 1.0);
  const double dg1 = 2.0 * x * t + 2.0 * x2 / (1.0 + x2), dg2 = t + x / (1.0 + x2) - x / q;
  const double t1 = 0.5 * lambda * a * a * g1, t2 = 4.0 / 3.0 * l2 * a * g2;
  const double u1 = a * a, u2 = 4.0 / 3.0 * lambda * a * x;
  p->r1 = t1 + t2 - 1.0;
  p->r2 = u1 - u2 - D;
  p->norm = fmax(fabs(p->r1) / (1.0 + fabs(t1) + fabs(t2)), fabs(p->r2) / (fabs(u1) + fabs(u2) + fabs(D) + 1e-300));
  p->j11 = lambda * a * g1 + 4.0 / 3.0 * l2 * g2;
  p->j12 = 0.5 * lambda * a * a * dg1 + 4.0 / 3.0 * l2 * a * dg2;
  p->j21 = 2.0 * a - 4.0 / 3.0 * lambda * x;
  p->j22 = -4.0 / 3.0 * lambda * a;
  p->t = t;
}

/* Newton on MD1 and MD3 from (a, x) (dc_md_at_overlap_near); *stable: the
   root lies where the branch's overlap grows with abar (dD/dabar = -det/j12
   with j12 = dMD1/ds > 0: det < 0) */
static int md_newton(double lambda, double Dbar, double a, double x, double *abar, double *s, double *Pbar, int *stable)
{
  md_point p, pn;
  md_eval(lambda, Dbar, a, x, &p);
  for (int it = 0; it < 40; it++) {
    if (p.norm <= 4.0 * DBL_EPSILON) {
      const double P = a * a * (a - lambda * (x + (1.0 + x * x) * p.t));   /* MD2 */
      if (!abar_ok(a) || !isfinite(P)) return DC_ENOCONV;
      *abar = a;
      *s = x;
      *Pbar = P;
      *stable = p.j11 * p.j22 - p.j12 * p.j21 < 0.0;
      return DC_OK;
    }
    /* J (da, dx) = -(r1, r2) */
    const double det = p.j11 * p.j22 - p.j12 * p.j21;
    if (!(fabs(det) > 0.0) || !isfinite(det)) return DC_ENOCONV;
    const double da = (-p.r1 * p.j22 + p.r2 * p.j12) / det, dx = (-p.r2 * p.j11 + p.r1 * p.j21) / det;
    /* halved steps: a trust region (abar within a factor 4, s within 4 s + 1) and a falling residual */
    double step = 1.0, an, xn;
    for (int h = 0;; h++) {
      if (h > 30) return DC_ENOCONV;
      an = a + step * da;
      xn = x + step * dx;
      if (an > 0.25 * a && an < 4.0 * a && xn >= 0.0 && xn <= 4.0 * x + 1.0) {
        md_eval(lambda, Dbar, an, xn, &pn);
        if (pn.norm < p.norm || pn.norm <= 4.0 * DBL_EPSILON) break;
      }
      step *= 0.5;
    }
    a = an;
    x = xn;
    p = pn;
  }
  return DC_ENOCONV;
}

int dc_md_at_overlap_near(double lambda, double Dbar, double abar0, double s0, double *abar, double *s, double *Pbar)
{
  if (!lambda_ok(lambda) || !abar_ok(abar0) || !(s0 >= 0.0 && s0 <= 1e300) || !(fabs(Dbar) <= 1e30)) return DC_EDOM;
  int stable;
  return md_newton(lambda, Dbar, abar0, s0, abar, s, Pbar, &stable);
}

/* c_z = 8 lambda / (3 pi), where the zone's overlap is least */
static double md_cz(double lambda) { return 8.0 / (3.0 * M_PI) * lambda; }

int dc_md_zone(double lambda, double Dbar, int *zone, double *cbar, double *Pbar)
{
  if (!lambda_ok(lambda) || !(fabs(Dbar) <= 1e30)) return DC_EDOM;
  double c0, P0, D0;
  dc_md_state_zero(lambda, &c0, &P0, &D0);
  const double cz = md_cz(lambda), disc = cz * cz + 2.0 * (Dbar + 2.0 / (M_PI * lambda));
  *zone = c0 > cz && disc >= 0.0 && Dbar <= D0;
  const double c = *zone ? cz + sqrt(disc) : 0.0;   /* the stable root of Dbar(cbar) */
  *cbar = c;
  *Pbar = -M_PI / 2.0 * lambda * c * c;
  return DC_OK;
}

double dc_md_reach(double lambda)
{
  if (!lambda_ok(lambda)) return NAN;
  double c0, P0, D0;
  dc_md_state_zero(lambda, &c0, &P0, &D0);
  const double cz = md_cz(lambda);
  return c0 > cz ? fmax(1.0, 0.5 * cz * cz + 2.0 / (M_PI * lambda)) : 1.0;
}

const dc_history_field dc_md_history[DC_MD_CONTACT_NFIELDS] = {
  {"md_phase", 0}, {"md_x", 0}, {"md_s", 0}, {"md_lambda", 0}, {"md_pulloff", 0},
};

/* The stable contact branch at Dbar from a guess: Newton from a JKR-like
   guess (abar of JKR's Dbar = abar^2 - (2/3) (6 abar)^1/2, Newton in
   u = abar^1/2 from the right of its root) and from a DMT-like one (abar^2
   = Dbar - Dbar0 over the branch end, so abar s -> cbar0 as abar -> 0), the
   likelier first; s from MD3. 1 with the state, 0 if neither converges to
   the stable branch. */
static int md_enter(double lambda, double D, double D0, double *a, double *x, double *P)
{
  const double ustar = pow(6.0, -1.0 / 6.0), k = 2.0 / 3.0 * sqrt(6.0);
  double u = 1.5 + sqrt(sqrt(fmax(D, 0.0)));
  for (int it = 0; it < 60; it++) {
    const double f = u * u * u * u - k * u - D, du = f / (4.0 * u * u * u - k);
    u = fmax(u - du, ustar);
    if (fabs(du) <= 1e-3 * u) break;
  }
  const double a_jkr = u * u, a_dmt = sqrt(fmax(D - D0, 1e-6));
  for (int pass = 0; pass < 2; pass++) {
    const double a0 = (pass == 0) == (lambda >= 1.0) ? a_jkr : a_dmt;
    const double s0 = fmax(0.75 * (a0 * a0 - D) / (lambda * a0), 0.0);
    int stable;
    if (md_newton(lambda, D, a0, s0, a, x, P, &stable) == DC_OK && stable) return 1;
  }
  return 0;
}

/* The state at Dbar after a jump or when Newton from the previous state
   fails (dc_md_step): the contact branch if the contact holds or enters
   it, else the zone, else apart. */
static int md_settle(double D, dc_md_contact *h, double *Pbar, double *abar)
{
  const double l = h->lambda;
  double c0, P0, D0;
  dc_md_state_zero(l, &c0, &P0, &D0);
  const double cz = md_cz(l);
  int to_contact;
  if (h->phase == DC_MD_CONTACT) to_contact = 1;
  else if (h->phase == DC_MD_ZONE) to_contact = D > D0;
  else to_contact = !(c0 >= 2.0 * cz && D <= D0);   /* apart: the zone catches the jump where it is stable */
  if (to_contact) {
    double a, x, P, m;
    int contact = 0;
    if (h->phase != DC_MD_CONTACT && md_enter(l, D, D0, &a, &x, &P)) {
      contact = 1;
    } else {
      const int st = dc_md_at_overlap(l, D, &contact, &a, &m, &P);
      if (st != DC_OK) return st;
      if (contact && !(a > 1e-20)) contact = 0;   /* the branch's end: the zone's state below */
      if (contact) x = sqrt((m - 1.0) * (m + 1.0));
    }
    if (contact) {
      h->phase = DC_MD_CONTACT;
      h->x = a;
      h->s = x;
      *Pbar = P;
      *abar = a;
      return DC_OK;
    }
  }
  int zone;
  double c, P;
  dc_md_zone(l, D, &zone, &c, &P);
  h->phase = zone ? DC_MD_ZONE : DC_MD_APART;
  h->x = c;
  h->s = 0.0;
  *Pbar = P;
  *abar = 0.0;
  return DC_OK;
}

int dc_md_step(double Dbar, dc_md_contact *h, double *Pbar, double *abar)
{
  const double l = h->lambda;
  if (!lambda_ok(l) || !(fabs(Dbar) <= 1e30)) return DC_EDOM;
  if (h->phase == DC_MD_CONTACT) {
    double a, x, P;
    int stable;
    if (abar_ok(h->x) && md_newton(l, Dbar, h->x, h->s, &a, &x, &P, &stable) == DC_OK && stable) {
      h->x = a;
      h->s = x;
      *Pbar = P;
      *abar = a;
      return DC_OK;
    }
  } else if (h->phase == DC_MD_APART && Dbar < -2.0 / (M_PI * l)) {
    *Pbar = *abar = 0.0;
    return DC_OK;
  }
  dc_md_contact t = *h;
  const int st = md_settle(Dbar, &t, Pbar, abar);
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

int dc_md_sphere(const dc_md_sphere_pair *p, double R, double delta, dc_md_contact *h, double *F, double *a)
{
  if (!(R > 0.0 && R <= DBL_MAX)) return DC_EDOM;
  dc_md_contact t = *h;
  if (t.phase == DC_MD_APART) {
    if (!(delta > -p->h0)) {
      *F = *a = 0.0;
      return DC_OK;
    }
    t.lambda = p->Lam * cbrt(R);
    t.Pc = 0.0;
  }
  const double r3 = t.lambda / p->Lam;
  double P, ab;
  const int st = dc_md_step(delta / (p->Cd * r3), &t, &P, &ab);
  if (st != DC_OK) return st;
  const double f = P * p->piw * r3 * r3 * r3, rad = ab * p->Ca * r3 * r3;
  if (!(fabs(f) <= DBL_MAX && rad <= DBL_MAX)) return DC_ERANGE;
  *h = t;
  *F = f;
  *a = rad;
  return DC_OK;
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
