/* The adhesive part of the rough contact with circular JKR summits,
   tabulated in (x, eta): see dc/gw_rough_adhesive_table.h. */
#include "dc/gw_rough_adhesive_table.h"
#include "dc/gw_rough_adhesive.h"
#include "dc/jkr_elliptic.h"
#include "dc/status.h"
#include <float.h>
#include <math.h>
#include "gw_rough_adhesive_table_data.h"

/* delta_break / delta_c of a circular JKR summit: -(3/8) pi^4/3 (tested
   against dc_jkr_geometry) */
#define DC_GWA_UB (-0.375 * 4.60115111447049)

const dc_history_field dc_gwa_table_history[DC_GWA_TABLE_HISTORY_NFIELDS] = {
  {"gwa_touched", 0},
  {"gwa_delta_max", 0},
};

int dc_gwa_table_check(double Estar, double w, double sigma, double n_asp, dc_param_error *err)
{
  if (dc_param_check("youngsModulus (E*)", Estar, 0.0, 1, INFINITY, 1, "(0, inf)", err)) return DC_EDOM;
  if (dc_param_check("workOfAdhesion", w, 0.0, 0, INFINITY, 1, "[0, inf)", err)) return DC_EDOM;
  if (dc_param_check("roughness", sigma, 0.0, 1, INFINITY, 1, "(0, inf)", err)) return DC_EDOM;
  if (dc_param_check("asperityCount", n_asp, 0.0, 1, INFINITY, 1, "(0, inf)", err)) return DC_EDOM;
  return DC_OK;
}

int dc_gwa_table_pair_init(double Estar, double w, double sigma, double n_asp, dc_gwa_table_pair *p)
{
  dc_param_error e;
  if (dc_gwa_table_check(Estar, w, sigma, n_asp, &e) != DC_OK) return DC_EDOM;
  dc_gwa_table_pair q = {0};
  q.Estar = Estar; q.w = w; q.sigma = sigma; q.n_asp = n_asp;
  q.inv_sigma = 1.0 / sigma;
  q.F_coef = 8.0 * (w * n_asp);   /* 8 w alone may overflow */
  if (!isfinite(q.inv_sigma)) return DC_ERANGE;
  if (w > 0.0) {
    q.ub = DC_GWA_UB;
    /* (8 w/(pi E*))^2/3 / 2, from logarithms where the quotient leaves the doubles */
    const double r = 8.0 * w / (M_PI * Estar);
    q.dc_coef = 0.5 * (r >= DBL_MIN && r <= DBL_MAX ? pow(r, 2.0 / 3.0)
                                                     : exp(2.0 / 3.0 * (log(8.0 / M_PI) + log(w) - log(Estar))));
    q.ln_sigma_dc = log(sigma) - log(q.dc_coef);
    if (!(isfinite(q.ln_sigma_dc) && isfinite(q.F_coef) && q.dc_coef > 0.0)) return DC_ERANGE;
  }
  *p = q;
  return DC_OK;
}

/* cubic Hermite on [0, 1]: value and derivative */
static inline void hermite(double t, double f0, double d0, double f1, double d1, double *v, double *dv)
{
  const double t2 = t * t, t3 = t2 * t;
  *v = (2 * t3 - 3 * t2 + 1) * f0 + (t3 - 2 * t2 + t) * d0 + (-2 * t3 + 3 * t2) * f1 + (t3 - t2) * d1;
  if (dv) *dv = (6 * t2 - 6 * t) * f0 + (3 * t2 - 4 * t + 1) * d0 + (-6 * t2 + 6 * t) * f1 + (3 * t2 - 2 * t) * d1;
}

/* dx/dc at node i in the coordinate c of a deep (log2) or near cell */
static inline double node_dxdc(int i, int deep)
{
  if (deep) return -dc_gwa_table_x_node(i) * M_LN2 / DC_GWA_TABLE_PER_OCTAVE;
  return 1.0 / DC_GWA_TABLE_X_PER_UNIT;
}

/* L and dL/dc at node i, eta cell j position u; then across cell i..i+1 */
static void eta_interp(int b, int i, int j, double u, int deep, double *L, double *Lc)
{
  const double de = 1.0 / DC_GWA_TABLE_ETA_PER_UNIT, s = node_dxdc(i, deep);
  const double *a = dc_gwa_table_data[b][j][i], *c = dc_gwa_table_data[b][j + 1][i];
  hermite(u, a[0], a[2] * de, c[0], c[2] * de, L, NULL);
  hermite(u, a[1] * s, a[3] * s * de, c[1] * s, c[3] * s * de, Lc, NULL);
}

/* one summit's fbar - fbar_Hertz at reduced overlap d = delta/delta_c > 0
   on the large-contact branch, and its d/dd. With A = a/a_s:
   d = 2 A^2 - pi A^1/2, fbar = 4/(3 pi) A^3 - A^3/2, fbar_H =
   4/(3 pi) (d/2)^3/2 = 4/(3 pi) A^3 (1 - eps)^3/2, eps = (pi/2) A^-3/2;
   g = (pi/3) T(eps), T = (1 - (1-eps)^3/2 - 3 eps/2)/eps^2 (series for
   small eps: no cancellation). */
static void summit_g(double d, double *g, double *gd)
{
  /* y = A^1/2: 2 y^4 - pi y - d = 0, Newton from the large-d side */
  double y = sqrt(sqrt(0.5 * d));
  y = sqrt(sqrt(0.5 * (d + M_PI * y)));
  for (int k = 0; k < 30; k++) {
    const double f = 2 * y * y * y * y - M_PI * y - d, fp = 8 * y * y * y - M_PI;
    const double dy = f / fp;
    y -= dy;
    if (fabs(dy) <= 1e-16 * y) break;
  }
  const double A = y * y, eps = 0.5 * M_PI / (A * y);
  double T, Tp;
  if (eps < 0.25) {
    double c = 3.0 / 8.0, e = 1.0;
    T = 0.0; Tp = 0.0;
    for (int k = 2; k < 40; k++) {
      T -= c * e;
      if (k > 2) Tp -= (k - 2) * c * e / eps;
      c *= (k - 1.5) / (k + 1);
      e *= eps;
    }
  } else {
    const double q = pow(1.0 - eps, 1.5), q1 = sqrt(1.0 - eps);
    T = (1.0 - q - 1.5 * eps) / (eps * eps);
    Tp = (1.5 * q1 - 1.5) / (eps * eps) - 2.0 * T / eps;
  }
  *g = (M_PI / 3.0) * T;
  /* dg/dd = (dg/deps)(deps/dA)/(dd/dA), deps/dA = -1.5 eps/A, dd/dA = 4A - pi/(2 A^1/2) */
  *gd = (M_PI / 3.0) * Tp * (-1.5 * eps / A) / (4.0 * A - 0.5 * M_PI / y);
}

/* G and dG/dx, unchecked; eta clamped; tau_ub = -ub (unloading shift in d) */
static void reduced(int b, double x, double eta, double *G, double *Gx)
{
  const double emax = DC_GWA_TABLE_ETA_LO + (double)(DC_GWA_TABLE_NETA - 1) / DC_GWA_TABLE_ETA_PER_UNIT;
  if (eta < DC_GWA_TABLE_ETA_LO) eta = DC_GWA_TABLE_ETA_LO;
  if (eta > emax) eta = emax;
  double ue = (eta - DC_GWA_TABLE_ETA_LO) * DC_GWA_TABLE_ETA_PER_UNIT;
  int j = (int)ue;
  if (j > DC_GWA_TABLE_NETA - 2) j = DC_GWA_TABLE_NETA - 2;
  ue -= j;
  const double x_end = dc_gwa_table_x_node(0);
  if (x > DC_GWA_TABLE_X_HI) {
    double L, Lc;
    eta_interp(b, DC_GWA_TABLE_NX - 1, j, ue, 0, &L, &Lc);
    const double Lx = Lc * DC_GWA_TABLE_X_PER_UNIT;
    const double Lv = L + Lx * (x - DC_GWA_TABLE_X_HI);
    *G = -exp(Lv);
    *Gx = *G * Lx;
    return;
  }
  if (x < x_end) {
    /* every summit pressed: one summit at the mean compression; where
       that overflows, the limit g -> -pi/8 (the correction -> 0) */
    const double ub = DC_GWA_UB;
    const double tau = exp(eta), shift = b == DC_GW_UNLOADING ? ub : 0.0, d = -tau * x + shift;
    if (!(d <= DBL_MAX)) { *G = -M_PI / 8.0; *Gx = 0.0; return; }
    double L, Lc, g, gd, g0, gd0;
    eta_interp(b, 0, j, ue, 1, &L, &Lc);
    summit_g(-tau * x_end + shift, &g0, &gd0);
    summit_g(d, &g, &gd);
    const double q = x_end / x, q2 = q * q, corr = (-exp(L) - g0) * q2 * sqrt(sqrt(q2 * q2 * q2 / q));
    *G = g + corr;
    *Gx = -tau * gd - 2.75 * corr / x;
    return;
  }
  int i;
  double t;
  if (x < DC_GWA_TABLE_X_LO) {
    const double c = DC_GWA_TABLE_NDEEP - DC_GWA_TABLE_PER_OCTAVE * log2(x / DC_GWA_TABLE_X_LO);
    i = (int)c;
    if (i < 0) i = 0;
    if (i > DC_GWA_TABLE_NDEEP - 1) i = DC_GWA_TABLE_NDEEP - 1;
    t = c - i;
  } else {
    const double c = (x - DC_GWA_TABLE_X_LO) * DC_GWA_TABLE_X_PER_UNIT;
    i = (int)c;
    if (i > DC_GWA_TABLE_NNEAR - 1) i = DC_GWA_TABLE_NNEAR - 1;
    t = c - i;
    i += DC_GWA_TABLE_NDEEP;
  }
  double L0, Lc0, L1, Lc1, L, Lc;
  const int deep = x < DC_GWA_TABLE_X_LO;
  eta_interp(b, i, j, ue, deep, &L0, &Lc0);
  eta_interp(b, i + 1, j, ue, deep, &L1, &Lc1);
  hermite(t, L0, Lc0, L1, Lc1, &L, &Lc);
  const double dxdc = x < DC_GWA_TABLE_X_LO ? -x * M_LN2 / DC_GWA_TABLE_PER_OCTAVE : 1.0 / DC_GWA_TABLE_X_PER_UNIT;
  *G = -exp(L);
  *Gx = *G * Lc / dxdc;
}

int dc_gwa_table_reduced(int branch, double x, double eta, double *G, double *dGdx)
{
  if (!(isfinite(x) && isfinite(eta) && (branch == DC_GW_LOADING || branch == DC_GW_UNLOADING))) return DC_EDOM;
  double g, gx;
  reduced(branch, x, eta, &g, &gx);
  if (!(isfinite(g) && isfinite(gx))) return DC_ERANGE;
  *G = g;
  *dGdx = gx;
  return DC_OK;
}

/* branch force, unchecked inputs; 0 on success */
static int branch_force(const dc_gwa_table_pair *p, double lnR, double R, int b, double delta,
                        double *F, double *kn)
{
  const double eta = p->ln_sigma_dc - lnR / 3.0;
  const double h = -delta * p->inv_sigma;
  double x = h;
  /* h - D = -(delta + |delta_break|)/sigma, summed first: h and D may both overflow */
  if (b == DC_GW_UNLOADING) x = -(delta - p->ub * p->dc_coef * cbrt(R)) * p->inv_sigma;
  double G, Gx;
  reduced(b, x, eta, &G, &Gx);
  const double Fs = p->F_coef * R;
  *F = Fs * G;
  *kn = -Fs * Gx * p->inv_sigma;
  return isfinite(*F) && isfinite(*kn) ? DC_OK : DC_ERANGE;
}

int dc_gwa_table_force(const dc_gwa_table_pair *p, double R, int branch, double delta, double *F, double *kn)
{
  if (!(R > 0.0 && isfinite(R) && isfinite(delta) && (branch == DC_GW_LOADING || branch == DC_GW_UNLOADING)))
    return DC_EDOM;
  if (p->w == 0.0) { *F = 0.0; *kn = 0.0; return DC_OK; }
  double f, k;
  const int r = branch_force(p, log(R), R, branch, delta, &f, &k);
  if (r != DC_OK) return r;
  *F = f;
  *kn = k;
  return DC_OK;
}

double dc_gwa_table_reach(const dc_gwa_table_pair *p, double R)
{
  return -p->ub * p->dc_coef * cbrt(R) + DC_GWA_TABLE_X_HI * p->sigma;
}

int dc_gwa_table_step(const dc_gwa_table_pair *p, double R, double delta, double *hist, dc_gwa_table_out *o)
{
  if (!(R > 0.0 && isfinite(R) && isfinite(delta) && isfinite(hist[0]) && isfinite(hist[1]))) return DC_EDOM;
  if (p->w == 0.0) { o->F = 0.0; o->kn = 0.0; o->weight = 0.0; return DC_OK; }
  const int touched = hist[0] != 0.0;
  double dmax = touched ? hist[1] : delta;
  if (delta > dmax) dmax = delta;
  const double lnR = log(R);
  const double db = -p->ub * p->dc_coef * exp(lnR / 3.0);   /* |delta_break| */
  const double xi = (dmax - delta) / db;
  double F, kn, wgt;
  if (!(xi > 0.0)) {
    if (branch_force(p, lnR, R, DC_GW_LOADING, delta, &F, &kn) != DC_OK) return DC_ERANGE;
    wgt = 0.0;
  } else if (xi >= 1.0) {
    if (branch_force(p, lnR, R, DC_GW_UNLOADING, delta, &F, &kn) != DC_OK) return DC_ERANGE;
    wgt = 1.0;
  } else {
    double FL, kL, FU, kU;
    if (branch_force(p, lnR, R, DC_GW_LOADING, delta, &FL, &kL) != DC_OK) return DC_ERANGE;
    if (branch_force(p, lnR, R, DC_GW_UNLOADING, delta, &FU, &kU) != DC_OK) return DC_ERANGE;
    wgt = xi * xi * (3.0 - 2.0 * xi);
    const double dw = -6.0 * xi * (1.0 - xi) / db;   /* dw/d delta */
    F = FL + wgt * (FU - FL);
    kn = kL + wgt * (kU - kL) + dw * (FU - FL);
    if (!(isfinite(F) && isfinite(kn))) return DC_ERANGE;
  }
  /* the lowest attached summit beyond x = X_HI: every summit separated */
  const double x_u = -(delta + db) * p->inv_sigma;   /* h - D */
  if (wgt == 1.0 && x_u > DC_GWA_TABLE_X_HI) { hist[0] = 0.0; hist[1] = 0.0; }
  else { hist[0] = 1.0; hist[1] = dmax; }
  o->F = F; o->kn = kn; o->weight = wgt;
  return DC_OK;
}
