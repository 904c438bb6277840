/* The adhesive part of the rough contact with circular JKR summits,
   tabulated in (x, eta): see dc/gw_rough_adhesive_table.h. */
#include "dc/gw_rough_adhesive_table.h"
#include "dc/gw_integrals.h"
#include "dc/gw_rough_adhesive.h"
#include "dc/jkr_elliptic.h"
#include "dc/status.h"
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>
#include "gw_rough_adhesive_table_data.h"

#if defined(__GNUC__)
#define ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define ALWAYS_INLINE inline
#endif

/* delta_break / delta_c of a circular JKR summit: -(3/8) pi^4/3 (tested
   against dc_jkr_geometry) */
#define DC_GWA_UB (-0.375 * 4.60115111447049)
/* c_H = 4/(3 pi 2^3/2): the summits' Hertz force n_asp F_s c_H tau^3/2
   F_3/2(h) is the closed form of dc_gw_rough_elliptic */
#define DC_GWA_CH 0.15005271935951767

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

/* 2^(j/32), j < 32, rounded from 40 digits */
const double dc_gwa_exp2_32[32] = {
  1.0,
  1.0218971486541166,
  1.0442737824274138,
  1.0671404006768237,
  1.0905077326652577,
  1.1143867425958924,
  1.1387886347566916,
  1.1637248587775775,
  1.189207115002721,
  1.215247359980469,
  1.241857812073484,
  1.2690509571917332,
  1.2968395546510096,
  1.3252366431597413,
  1.3542555469368927,
  1.383909881963832,
  1.4142135623730951,
  1.4451808069770467,
  1.4768261459394993,
  1.5091644275934228,
  1.5422108254079407,
  1.5759808451078865,
  1.6104903319492543,
  1.645755478153965,
  1.681792830507429,
  1.718619298122478,
  1.7562521603732995,
  1.7947090750031072,
  1.8340080864093424,
  1.8741676341103,
  1.9152065613971474,
  1.9571441241754002

};

/* quintic step: 1 for z <= 0, 0 for z >= 1, and its derivative */
static inline double step_down(double z, double *dz)
{
  if (z <= 0.0) { *dz = 0.0; return 1.0; }
  if (z >= 1.0) { *dz = 0.0; return 0.0; }
  *dz = -30.0 * z * z * (1.0 - z) * (1.0 - z);
  return 1.0 - z * z * z * (10.0 + z * (6.0 * z - 15.0));
}

void dc_gwa_table_kink(double x, double eta, double *C, double *Cx)
{
  const double wl = DC_GWA_KINK_W_HI - DC_GWA_KINK_W_LO, kl = DC_GWA_KINK_K_HI - DC_GWA_KINK_K_LO;
  double dw, dk;
  const double w = step_down((x - DC_GWA_KINK_W_LO) / wl, &dw);
  const double K = step_down((eta - DC_GWA_KINK_K_LO) / kl, &dk);
  *C = 0.0;
  *Cx = 0.0;
  if (K == 0.0 || (w == 0.0 && dw == 0.0)) return;
  const double tau = exp(eta), h = x - DC_GWA_UB / tau;
  const double b = DC_GWA_KINK_B / tau, s = sqrt(1.0 + K * b * b), rs = sqrt(s);
  double F[4], Fs[4];
  dc_gw_F_all(h, F);
  dc_gw_F_all(h / s, Fs);
  const double k = DC_GWA_CH * tau * sqrt(tau);
  const double P = k * (F[DC_GW_F32] - s * rs * Fs[DC_GW_F32]);
  const double Px = 1.5 * k * (rs * Fs[DC_GW_F12] - F[DC_GW_F12]);
  *C = w * P;
  *Cx = w * Px + dw / wl * P;
}

/* eta clamped to the table, its cell (dc_gwa_table_eta_cell, inline) */
static inline void eta_cell(double eta, dc_gwa_table_eta *c) { dc_gwa_table_eta_cell(eta, c); }

/* A contact's eta cell (dc_gwa_table_step_contact) holds only eta until a
   step needs the rest (j < 0): a step that reads the cell the contact kept
   needs none of it. Set up here on first use (the cell is the caller's,
   not const). */
static inline const dc_gwa_table_eta *eta_ready(const dc_gwa_table_eta *c)
{
  if (c->j < 0) eta_cell(c->eta, (dc_gwa_table_eta *)c);
  return c;
}

/* a node pair (rows j and j + 1): L and its x (or u) slope at ue */
static inline void eta_mix(const dc_gwa_table_eta *c, const double *a, const double *e, double *v, double *d)
{
  *v = c->w[0] * a[0] + c->w[1] * a[2] + c->w[2] * e[0] + c->w[3] * e[2];
  *d = c->w[0] * a[1] + c->w[1] * a[3] + c->w[2] * e[1] + c->w[3] * e[3];
}

/* The cubic Hermite polynomial of a cell from its end values v and slopes
   s (in the cell's unit): c0 + c1 t + c2 t^2 + c3 t^3, t in [0, 1] */
static inline void cell_cubic(double v0, double s0, double v1, double s1, double *c)
{
  const double dv = v1 - v0;
  c[0] = v0;
  c[1] = s0;
  c[2] = 3.0 * dv - 2.0 * s0 - s1;
  c[3] = s0 + s1 - 2.0 * dv;
}

/* A contact's cell cache (dc_gwa_table_contact's cell: which, then the
   cubic): the key of deep cell k (near cells: DC_GWA_TABLE_CELL_KEY_NEAR) */
#define CELL_KEY_DEEP(b, k) DC_GWA_TABLE_CELL_KEY_NEAR(b, DC_GWA_TABLE_NNEAR + (k))

/* The contact's cell cache cc (NULL: none) for the cell of this key: its
   cubic when cc holds that cell; else NULL, with the cell to be formed in
   cc's slot (*tmp) from the eta cell set up (*c) */
static ALWAYS_INLINE const double *cell_kept(double *cc, double key, double **tmp, const dc_gwa_table_eta **c)
{
  if (!cc) return NULL;
  if (cc[0] == key) return cc + 1;
  cc[0] = key;
  *tmp = cc + 1;
  *c = eta_ready(*c);
  return NULL;
}

/* near cell i (nodes i, i + 1) at c's eta, from the contact's cell cache
   cc when there is one and it holds the cell (else formed there, or in tmp
   without one) */
static ALWAYS_INLINE const double *near_cell(int b, int i, const dc_gwa_table_eta *c, double *cc, double *tmp)
{
  const double *kept = cell_kept(cc, DC_GWA_TABLE_CELL_KEY_NEAR(b, i), &tmp, &c);
  if (kept) return kept;
  const double dx = 1.0 / DC_GWA_TABLE_X_PER_UNIT;
  double v0, d0, v1, d1;
  eta_mix(c, dc_gwa_table_near[b][c->j][i], dc_gwa_table_near[b][c->j + 1][i], &v0, &d0);
  eta_mix(c, dc_gwa_table_near[b][c->j][i + 1], dc_gwa_table_near[b][c->j + 1][i + 1], &v1, &d1);
  cell_cubic(v0, d0 * dx, v1, d1 * dx, tmp);
  return tmp;
}

/* deep cell k (row j's nodes k, k + 1; row j + 1's three places shallower) */
static inline const double *deep_cell(int b, int k, const dc_gwa_table_eta *c, double *cc, double *tmp)
{
  const double *kept = cell_kept(cc, CELL_KEY_DEEP(b, k), &tmp, &c);
  if (kept) return kept;
  const double du = 1.0 / DC_GWA_TABLE_U_PER_UNIT;
  const int sh = DC_GWA_TABLE_U_PER_UNIT / DC_GWA_TABLE_ETA_PER_UNIT;
  double v0, d0, v1, d1;
  eta_mix(c, dc_gwa_table_deep[b][c->j][k], dc_gwa_table_deep[b][c->j + 1][k - sh], &v0, &d0);
  eta_mix(c, dc_gwa_table_deep[b][c->j][k + 1], dc_gwa_table_deep[b][c->j + 1][k + 1 - sh], &v1, &d1);
  cell_cubic(v0, d0 * du, v1, d1 * du, tmp);
  return tmp;
}

/* near region: L and dL/dx at x in [X_LO, X_HI] */
static ALWAYS_INLINE void near_interp(int b, double x, const dc_gwa_table_eta *c, double *cc,
                                       double *L, double *Lx)
{
  const double cx = (x - DC_GWA_TABLE_X_LO) * DC_GWA_TABLE_X_PER_UNIT;
  int i = (int)cx;
  if (i < 0) i = 0;
  if (i > DC_GWA_TABLE_NNEAR - 1) i = DC_GWA_TABLE_NNEAR - 1;
  double tmp[4], Lc;
  dc_gwa_cubic(near_cell(b, i, c, cc, tmp), cx - i, L, &Lc);
  *Lx = Lc * DC_GWA_TABLE_X_PER_UNIT;
}

/* deep region: bicubic in (u, eta), u = ln(-x) + eta, whose nodes on row
   j + 1 are those of row j three places shallower; x < 0 */
static void deep_interp(int b, double x, const dc_gwa_table_eta *c, double *cc, double *L,
                        double *Lx)
{
  const double de = 1.0 / DC_GWA_TABLE_ETA_PER_UNIT;
  const int sh = DC_GWA_TABLE_U_PER_UNIT / DC_GWA_TABLE_ETA_PER_UNIT;
  if (cc) c = eta_ready(c);
  const double cu = DC_GWA_TABLE_U_PER_UNIT * (log(x / DC_GWA_TABLE_X_B) + c->ue * de) - DC_GWA_TABLE_K_MIN;
  int m = (int)cu;
  if (m < sh) m = sh;
  if (m > DC_GWA_TABLE_NDEEP - 2) m = DC_GWA_TABLE_NDEEP - 2;
  double tmp[4], Lc;
  dc_gwa_cubic(deep_cell(b, m, c, cc, tmp), cu - m, L, &Lc);
  *Lx = Lc * DC_GWA_TABLE_U_PER_UNIT / x;
}

/* L = ln(-T) and dL/dx on the table's x range */
static inline void table_L(int b, double x, const dc_gwa_table_eta *c, double *cc, double *L,
                           double *Lx)
{
  if (x >= DC_GWA_TABLE_BLEND_HI) { near_interp(b, x, c, cc, L, Lx); return; }
  if (x <= DC_GWA_TABLE_BLEND_LO) { deep_interp(b, x, c, cc, L, Lx); return; }
  double Ln, Lnx, Ld, Ldx, dw;
  const double bl = DC_GWA_TABLE_BLEND_HI - DC_GWA_TABLE_BLEND_LO;
  const double w = step_down((x - DC_GWA_TABLE_BLEND_LO) / bl, &dw);   /* weight of deep */
  near_interp(b, x, c, cc, &Ln, &Lnx);
  deep_interp(b, x, c, cc, &Ld, &Ldx);
  *L = Ln + w * (Ld - Ln);
  *Lx = Lnx + w * (Ldx - Lnx) + dw / bl * (Ld - Ln);
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

/* G and dG/dx beyond the table (x > X_HI, x < x_end), unchecked */
static void reduced_beyond(int b, double x, const dc_gwa_table_eta *c, double *cc, double *G,
                           double *Gx)
{
  double L, Lx;
  if (x > DC_GWA_TABLE_X_HI) {
    /* L continued linearly (C1); the kink term vanishes here */
    near_interp(b, DC_GWA_TABLE_X_HI, c, cc, &L, &Lx);
    *G = -exp(L + Lx * (x - DC_GWA_TABLE_X_HI));
    *Gx = *G * Lx;
    return;
  }
  /* every summit pressed: one summit at the mean compression */
  const double x_end = dc_gwa_table_x_deep(DC_GWA_TABLE_K_END);
  const double tau = exp(c->eta), shift = b == DC_GW_UNLOADING ? DC_GWA_UB : 0.0;
  double g, gd, g0, gd0, C = 0.0, Cx;
  deep_interp(b, x_end, c, cc, &L, &Lx);
  if (b == DC_GW_UNLOADING) dc_gwa_table_kink(x_end, c->eta, &C, &Cx);
  const double d = -tau * x + shift;
  if (!(d <= DBL_MAX)) { *G = -M_PI / 8.0; *Gx = 0.0; return; }   /* beyond the doubles: the limit g = -pi/8 */
  summit_g(-tau * x_end + shift, &g0, &gd0);
  summit_g(d, &g, &gd);
  const double q = x_end / x, q2 = q * q, corr = (-exp(L) - C - g0) * q2 * sqrt(sqrt(q2 * q2 * q2 / q));
  *G = g + corr;
  *Gx = -tau * gd - 2.75 * corr / x;
}

/* G and dG/dx, unchecked, in the eta cell c */
/* kc (may be NULL): C and dC/dx of dc_gwa_table_kink at (x, c->eta) on
   unloading, 0 on loading (for the elliptic summits' correction) */
static void reduced_any(int b, double x, const dc_gwa_table_eta *c, double *cc, double *G,
                        double *Gx, double *kc)
{
  if (kc) kc[0] = kc[1] = 0.0;
  if (x > DC_GWA_TABLE_X_HI || x < dc_gwa_table_x_deep(DC_GWA_TABLE_K_END)) {
    reduced_beyond(b, x, c, cc, G, Gx);
    if (kc && b == DC_GW_UNLOADING) dc_gwa_table_kink(x, c->eta, &kc[0], &kc[1]);
    return;
  }
  double L, Lx;
  table_L(b, x, c, cc, &L, &Lx);
  *G = -dc_gwa_exp(L);
  *Gx = *G * Lx;
  if (b == DC_GW_UNLOADING && x < DC_GWA_KINK_W_HI && c->eta < DC_GWA_KINK_K_HI) {
    double C, Cx;
    dc_gwa_table_kink(x, c->eta, &C, &Cx);
    *G -= C;
    *Gx -= Cx;
    if (kc) { kc[0] = C; kc[1] = Cx; }
  }
}

/* reduced_any with the common case inline: the near region above the
   blend, without the kink term (the same operations, the same bits) */
static ALWAYS_INLINE void reduced(int b, double x, const dc_gwa_table_eta *c, double *cc,
                                  double *G, double *Gx, double *kc)
{
  if (x >= DC_GWA_TABLE_BLEND_HI && x <= DC_GWA_TABLE_X_HI &&
      !(b == DC_GW_UNLOADING && x < DC_GWA_KINK_W_HI && c->eta < DC_GWA_KINK_K_HI)) {
    double L, Lx;
    near_interp(b, x, c, cc, &L, &Lx);
    *G = -dc_gwa_exp(L);
    *Gx = *G * Lx;
    if (kc) kc[0] = kc[1] = 0.0;
    return;
  }
  reduced_any(b, x, c, cc, G, Gx, kc);
}

int dc_gwa_table_reduced(int branch, double x, double eta, double *G, double *dGdx)
{
  if (!(isfinite(x) && isfinite(eta) && (branch == DC_GW_LOADING || branch == DC_GW_UNLOADING))) return DC_EDOM;
  dc_gwa_table_eta c;
  eta_cell(eta, &c);
  double g, gx;
  reduced(branch, x, &c, NULL, &g, &gx, NULL);
  if (!(isfinite(g) && isfinite(gx))) return DC_ERANGE;
  *G = g;
  *dGdx = gx;
  return DC_OK;
}

int dc_gwa_table_radius_init(const dc_gwa_table_pair *p, double R, dc_gwa_table_radius *r)
{
  if (!(R > 0.0 && isfinite(R))) return DC_EDOM;
  dc_gwa_table_radius q = {0};
  q.R = R;
  if (p->w > 0.0) {
    const double r3 = cbrt(R);
    q.Fs = p->F_coef * R;
    q.db = -p->ub * p->dc_coef * r3;
    q.D = q.db * p->inv_sigma;
    q.reach = q.db + DC_GWA_TABLE_X_HI * p->sigma;
    eta_cell(p->ln_sigma_dc - log(R) / 3.0, &q.cell);
    if (!(isfinite(q.Fs) && isfinite(q.cell.eta))) return DC_ERANGE;
  }
  *r = q;
  return DC_OK;
}

/* The circular table's G, dG/dx and the kink term's C, dC/dx (0 on
   loading) at (x, eta) on branch b: what the elliptic correction's deep
   tail reads (dc_gwa_table_circle_fn). */
static void circle_at(int b, double x, double eta, double *G, double *Gx, double *C, double *Cx)
{
  *C = *Cx = 0.0;
  if (b == DC_GW_UNLOADING) dc_gwa_table_kink(x, eta, C, Cx);
  dc_gwa_table_reduced(b, x, eta, G, Gx);
}

/* branch force at overlap delta, unchecked inputs; 0 on success */
static ALWAYS_INLINE int branch_force(const dc_gwa_table_pair *p, const dc_gwa_table_radius *r, double *cc, int b,
                                      double delta, double *F, double *kn)
{
  double x = -delta * p->inv_sigma;   /* h */
  if (b == DC_GW_UNLOADING) {
    x -= r->D;
    if (isnan(x)) x = -(delta + r->D * p->sigma) * p->inv_sigma;   /* h and D both overflowed: summed first */
  }
  double G, Gx;
  if (r->ell.on) {
    double kc[2];
    reduced(b, x, &r->cell, cc, &G, &Gx, kc);
    dc_gwa_table_ell_apply(&r->ell, b, x, r->cell.eta, kc, circle_at, &G, &Gx);
  } else {
    reduced(b, x, &r->cell, cc, &G, &Gx, NULL);
  }
  *F = r->Fs * G;
  *kn = -r->Fs * Gx * p->inv_sigma;
  return isfinite(*F) && isfinite(*kn) ? DC_OK : DC_ERANGE;
}

int dc_gwa_table_force(const dc_gwa_table_pair *p, double R, int branch, double delta, double *F, double *kn)
{
  if (!(R > 0.0 && isfinite(R) && isfinite(delta) && (branch == DC_GW_LOADING || branch == DC_GW_UNLOADING)))
    return DC_EDOM;
  if (p->w == 0.0) { *F = 0.0; *kn = 0.0; return DC_OK; }
  dc_gwa_table_radius r;
  const int st = dc_gwa_table_radius_init(p, R, &r);
  if (st != DC_OK) return st;
  double f, k;
  if (branch_force(p, &r, NULL, branch, delta, &f, &k) != DC_OK) return DC_ERANGE;
  *F = f;
  *kn = k;
  return DC_OK;
}

double dc_gwa_table_reach(const dc_gwa_table_pair *p, double R)
{
  return -p->ub * p->dc_coef * cbrt(R) + DC_GWA_TABLE_X_HI * p->sigma;
}

/* J(v) = int_0^v e^(h t - t^2/2) dt = P(h - v < S < h)/phi(h) for a standard
   normal S, by its series sum_n He_n(h) v^(n+1)/(n+1)! (He_n the Hermite
   polynomials) to n = 6, for (|h| + 3) v < 1/2: the rest is below 4e-7
   relative (He_7(h) v^8/8! <= ((|h| + 3) v)^7 v/8!, J >= v e^(-|h| v - v^2/2)),
   far inside the band law's own error */
static double band_series(double h, double v)
{
  const double h2 = h * h;
  const double he2 = h2 - 1.0, he3 = h * (h2 - 3.0), he4 = h2 * (h2 - 6.0) + 3.0, he5 = h * (h2 * (h2 - 10.0) + 15.0),
               he6 = h2 * (h2 * (h2 - 15.0) + 45.0) - 15.0;
  return v * (1.0 + v * (h / 2.0 + v * (he2 / 6.0 + v * (he3 / 24.0 + v * (he4 / 120.0 + v * (he5 / 720.0 +
                                                                                            v * (he6 / 5040.0)))))));
}

/* P(a < S < b), a < b, from the tail away from 0 (no cancellation in
   either tail), with eb = erfc(|b|/2^1/2) given: the band's two masses
   share their upper end b = h */
static double normal_mass(double a, double b, double eb)
{
  if (a >= 0.0) return 0.5 * (erfc(a * M_SQRT1_2) - eb);
  if (b <= 0.0) return 0.5 * (eb - erfc(-a * M_SQRT1_2));
  return 1.0 - 0.5 * (eb + erfc(-a * M_SQRT1_2));
}

/* The weight of the unloading branch in the partly attached band: of the
   summits the unloading branch counts as attached (heights between h - D
   and h, stretched less than |delta_break|), the Gaussian fraction that
   touched (above h_min): w = J(h - h_min)/J(D), and dw/d delta = -(dw/dh)
   / sigma, dw/dh = (phi(h) - w (phi(h) - phi(h - D)))/P(h - D < S < h) =
   (1 + w expm1(h D - D^2/2))/J(D). Exact where the summits' tensile force
   is the same at every stretch: it is -0.52 F_s at touch, -0.59 at most
   and -0.33 at separation (tests/unit/test_gw_rough_adhesive_table.c
   measures the rest against the attached summits' integral). Where the
   band holds no summit to speak of (all of it beyond 12 sigma of the mean
   plane: a mass below 2e-33) or a result leaves the doubles: w = xi,
   dw/d delta = -1/|delta_break|, the limit for D -> 0. Narrow bands take
   J's series, the others erfc. */
static void band_weight(double h, double hmin, double D, double xi, double sigma, double db, double *w, double *dwdd)
{
  double ww = -1.0, d = NAN;
  if (h < -12.0 || h - D > 12.0) {
    /* the band holds a Gaussian mass below 2e-33: any weight gives the
       same force; the limit below */
  } else if ((fabs(h) + 3.0) * D < 0.5) {
    const double JD = band_series(h, D), q = band_series(h, h - hmin) / JD;
    ww = q < 1.0 ? q : 1.0;
    d = -(1.0 + ww * expm1(h * D - 0.5 * D * D)) / JD / sigma;
  } else {
    const double eh = erfc(fabs(h) * M_SQRT1_2), Dn = normal_mass(h - D, h, eh);
    if (Dn > 0.0) {
      const double q = normal_mass(hmin, h, eh) / Dn, ph = 0.3989422804014327 * exp(-0.5 * h * h),
                   pd = 0.3989422804014327 * exp(-0.5 * (h - D) * (h - D));
      ww = q < 1.0 ? q : 1.0;
      d = -((ph - ww * (ph - pd)) / Dn) / sigma;
    }
  }
  if (!(ww >= 0.0 && isfinite(d))) {
    ww = xi;
    d = -1.0 / db;
  }
  *w = ww;
  *dwdd = d;
}

/* the step, with the last cell kept in the contact's cache cc, or (cc
   NULL) every cell formed at each call */
static ALWAYS_INLINE int step(const dc_gwa_table_pair *p, const dc_gwa_table_radius *r, double *cc, double delta,
                              double *hist, dc_gwa_table_out *o)
{
  if (!(isfinite(delta) && isfinite(hist[0]) && isfinite(hist[1]))) return DC_EDOM;
  if (p->w == 0.0 || dc_gwa_table_apart(p, delta, hist)) { o->F = 0.0; o->kn = 0.0; o->weight = 0.0; return DC_OK; }
  const int touched = hist[0] != 0.0;
  double dmax = touched ? hist[1] : delta;
  if (delta > dmax) dmax = delta;
  const double db = r->db;   /* |delta_break| */
  const double xi = (dmax - delta) / db;
  double F, kn, wgt;
  if (!(xi > 0.0)) {
    if (branch_force(p, r, cc, DC_GW_LOADING, delta, &F, &kn) != DC_OK) return DC_ERANGE;
    wgt = 0.0;
  } else if (xi >= 1.0) {
    if (branch_force(p, r, cc, DC_GW_UNLOADING, delta, &F, &kn) != DC_OK) return DC_ERANGE;
    wgt = 1.0;
  } else {
    double FL, kL, FU, kU;
    if (branch_force(p, r, cc, DC_GW_LOADING, delta, &FL, &kL) != DC_OK) return DC_ERANGE;
    if (branch_force(p, r, cc, DC_GW_UNLOADING, delta, &FU, &kU) != DC_OK) return DC_ERANGE;
    double dw;   /* dw/d delta */
    band_weight(-delta * p->inv_sigma, -dmax * p->inv_sigma, r->D, xi, p->sigma, db, &wgt, &dw);
    F = FL + wgt * (FU - FL);
    kn = kL + wgt * (kU - kL) + dw * (FU - FL);
    if (!(isfinite(F) && isfinite(kn))) return DC_ERANGE;
  }
  /* the lowest attached summit beyond x = X_HI: every summit separated */
  const double x_u = -delta * p->inv_sigma - r->D;   /* h - D */
  if (wgt == 1.0 && x_u > DC_GWA_TABLE_X_HI) { hist[0] = 0.0; hist[1] = 0.0; }
  else { hist[0] = 1.0; hist[1] = dmax; }
  o->F = F; o->kn = kn; o->weight = wgt;
  return DC_OK;
}

int dc_gwa_table_step_radius(const dc_gwa_table_pair *p, const dc_gwa_table_radius *r, double delta, double *hist,
                             dc_gwa_table_out *o)
{
  return step(p, r, NULL, delta, hist, o);
}

const dc_history_field dc_gwa_table_contact_history[DC_GWA_TABLE_CONTACT_NFIELDS] = {
  {"gwa_R", 0}, {"gwa_db", 0}, {"gwa_eta", 0}, {"gwa_cell", 0},
  {"gwa_cell_c0", 0}, {"gwa_cell_c1", 0}, {"gwa_cell_c2", 0}, {"gwa_cell_c3", 0},
};

int dc_gwa_table_contact_init(const dc_gwa_table_pair *p, double R, dc_gwa_table_contact *c)
{
  dc_gwa_table_radius r;
  const int st = dc_gwa_table_radius_init(p, R, &r);
  if (st != DC_OK) return st;
  dc_gwa_table_contact q = {0};
  q.R = r.R;
  q.db = r.db;
  q.eta = r.cell.eta;
  *c = q;
  return DC_OK;
}

/* The radius set up from the record: the same operations as
   dc_gwa_table_radius_init without the cube root and the logarithm; the
   eta cell set up from the stored eta, clamped (clamping again changes
   nothing), only if the step forms a cell. */
int dc_gwa_table_step_contact_any(const dc_gwa_table_pair *p, dc_gwa_table_contact *c, double delta, double *hist,
                                  dc_gwa_table_out *o)
{
  dc_gwa_table_radius r;
  r.R = c->R;
  r.Fs = p->F_coef * c->R;
  r.db = c->db;
  r.D = c->db * p->inv_sigma;
  r.reach = 0.0;   /* not read by the step */
  r.cell.eta = c->eta;
  r.cell.j = -1;
  r.ell.on = 0;   /* circular summits */
  return step(p, &r, c->cell, delta, hist, o);
}

int dc_gwa_table_step(const dc_gwa_table_pair *p, double R, double delta, double *hist, dc_gwa_table_out *o)
{
  if (!(R > 0.0 && isfinite(R) && isfinite(delta) && isfinite(hist[0]) && isfinite(hist[1]))) return DC_EDOM;
  dc_gwa_table_radius r;
  const int st = dc_gwa_table_radius_init(p, R, &r);
  if (st != DC_OK) return st;
  return dc_gwa_table_step_radius(p, &r, delta, hist, o);
}
