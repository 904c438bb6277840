/* Rough contact with elliptic adhesive (JKR) summits, tabulated: the
   circular table of dc/gw_rough_adhesive_table.h at the elliptic summit's
   matched scales, times a correction tabulated in (ln rho, xi(x), eta);
   see the header's "Elliptic summits". */
#include "dc/gw_rough_adhesive_table.h"
#include "dc/gw_rough_adhesive.h"
#include "dc/status.h"
#include <float.h>
#include <math.h>
#include "gw_rough_adhesive_elliptic_data.h"

/* Catmull-Rom weights of the nodes k-1 .. k+2 at t in [0, 1] of cell k */
static inline void cr_weights(double t, double *w)
{
  const double t2 = t * t, t3 = t2 * t;
  w[0] = 0.5 * (-t + 2.0 * t2 - t3);
  w[1] = 0.5 * (2.0 - 5.0 * t2 + 3.0 * t3);
  w[2] = 0.5 * (t + 4.0 * t2 - 3.0 * t3);
  w[3] = 0.5 * (t3 - t2);
}

/* and their derivatives in t */
static inline void cr_slopes(double t, double *d)
{
  const double t2 = t * t;
  d[0] = 0.5 * (-1.0 + 4.0 * t - 3.0 * t2);
  d[1] = 0.5 * (-10.0 * t + 9.0 * t2);
  d[2] = 0.5 * (1.0 + 8.0 * t - 9.0 * t2);
  d[3] = 0.5 * (3.0 * t2 - 2.0 * t);
}

/* cell and weights of coordinate u (in cells from the grid's start) on n cells */
static inline int cr_cell(double u, int n, double *w)
{
  int k = (int)u;
  if (k < 0) k = 0;
  if (k > n - 1) k = n - 1;
  cr_weights(u - k, w);
  return k;
}

/* weights of the nodes l0 .. l3 at t in [0, 1] of the cell [l1, l2]: cubic
   Hermite with three-point slopes, exact for quadratics (Catmull-Rom where
   the cells are even) */
static void hermite3_weights(double l0, double l1, double l2, double l3, double t, double *w)
{
  const double h = l2 - l1;
  const double t2 = t * t, t3 = t2 * t;
  const double h00 = 2.0 * t3 - 3.0 * t2 + 1.0, h10 = t3 - 2.0 * t2 + t, h01 = 3.0 * t2 - 2.0 * t3, h11 = t3 - t2;
  /* h times the slope at l1 (from l0, l1, l2) and at l2 (from l1, l2, l3) */
  double a = l1 - l0, c = h;
  const double p0 = -c / (a * (a + c)) * h, p1 = (c - a) / (a * c) * h, p2 = a / (c * (a + c)) * h;
  a = h;
  c = l3 - l2;
  const double q1 = -c / (a * (a + c)) * h, q2 = (c - a) / (a * c) * h, q3 = a / (c * (a + c)) * h;
  w[0] = h10 * p0;
  w[1] = h00 + h10 * p1 + h11 * q1;
  w[2] = h01 + h10 * p2 + h11 * q2;
  w[3] = h11 * q3;
}

/* cell and weights of the nodes i-1 .. i+2 at -ln rho = L on a branch's ln
   rho grid (n2 its NR2) */
static inline int ln_rho_cell(double L, int n2, double *w)
{
  const double h1 = dc_gwae_L_node(1, n2), L1 = dc_gwae_L_node(DC_GWAE_NR1, n2);
  const double h2 = dc_gwae_L_node(DC_GWAE_NR1 + 1, n2) - L1;
  const double u = L < L1 ? L / h1 : DC_GWAE_NR1 + (L - L1) / h2;
  int i = (int)u;
  if (i > DC_GWAE_NR1 + n2 - 1) i = DC_GWAE_NR1 + n2 - 1;
  const double t = u - i;
  if (i + 1 < DC_GWAE_NR1 || i > DC_GWAE_NR1)
    cr_weights(t, w);
  else
    hermite3_weights(dc_gwae_L_node(i - 1, n2), dc_gwae_L_node(i, n2), dc_gwae_L_node(i + 1, n2),
                     dc_gwae_L_node(i + 2, n2), t, w);
  return i;
}

/* d/d eta at unloading row n as weights c[0..4] of the rows r0 .. r0+4:
   five-point where rows n-2 .. n+2 are evenly spaced table rows, one-sided
   ones on the table's rows at its ends (the ghost rows are extrapolated),
   else three-point on the rows' own spacing (at the seam: the slopes of
   hermite3_weights) */
static void eta_slope_u(int n, int n1, double *c, int *r0)
{
  static const double end0[5] = {-22.0, 36.0, -18.0, 4.0, 0.0}, end1[5] = {-3.0, -10.0, 18.0, -6.0, 1.0};
  for (int m = 0; m < 5; m++) c[m] = 0.0;
  if (n <= 1 || n >= DC_GWAE_NETA_U - 1) {   /* 4 (5) points, error ~h^3 (h^4); sixths as twelfths */
    const int lo = n <= 1;
    const double h = dc_gwae_eta_node_u(lo ? 1 : n) - dc_gwae_eta_node_u(lo ? 0 : n - 1), q = 1.0 / (12.0 * h);
    const double *e = (lo ? n == 0 : n == DC_GWAE_NETA_U) ? end0 : end1;
    for (int m = 0; m < 5; m++) c[m] = lo ? e[m] * q : -e[4 - m] * q;
    *r0 = lo ? 0 : DC_GWAE_NETA_U - 4;
    return;
  }
  if ((n - 2 >= 0 && n + 2 <= n1) || (n - 2 >= n1 && n + 2 <= DC_GWAE_NETA_U)) {
    const double h = dc_gwae_eta_node_u(n + 1) - dc_gwae_eta_node_u(n), q = 1.0 / (12.0 * h);
    c[0] = q; c[1] = -8.0 * q; c[3] = 8.0 * q; c[4] = -q;
    *r0 = n - 2;
    return;
  }
  const double a = dc_gwae_eta_node_u(n) - dc_gwae_eta_node_u(n - 1), b = dc_gwae_eta_node_u(n + 1) - dc_gwae_eta_node_u(n);
  c[0] = -b / (a * (a + b));
  c[1] = (b - a) / (a * b);
  c[2] = a / (b * (a + b));
  *r0 = n - 1;
}

/* first row (array index: ghost row first) and weights of six unloading
   rows at eta (in the table's range): cubic Hermite between rows j and j+1
   with the slopes of eta_slope_u (error ~h^4 where five-point, against
   Catmull-Rom's ~h^3; C1 in eta) */
static inline int eta_cell_u(double eta, double *w)
{
  const int n1 = (int)((DC_GWAE_ETA_MID_U - DC_GWA_TABLE_ETA_LO) * DC_GWAE_ETA_PER_UNIT_U + 0.5);
  const double u = eta < DC_GWAE_ETA_MID_U ? (eta - DC_GWA_TABLE_ETA_LO) * DC_GWAE_ETA_PER_UNIT_U
                                           : n1 + (eta - DC_GWAE_ETA_MID_U) * (DC_GWAE_ETA_PER_UNIT_U / 2);
  int j = (int)u;
  if (j < 0) j = 0;
  if (j > DC_GWAE_NETA_U - 1) j = DC_GWAE_NETA_U - 1;
  const double t = u - j, t2 = t * t, t3 = t2 * t;
  const double h00 = 2.0 * t3 - 3.0 * t2 + 1.0, h01 = 3.0 * t2 - 2.0 * t3;
  if ((j >= 2 && j + 3 <= n1) || (j - 2 >= n1 && j + 3 <= DC_GWAE_NETA_U)) {
    /* both slopes five-point: the weights of rows j-2 .. j+3 directly */
    const double g10 = (t3 - 2.0 * t2 + t) * (1.0 / 12.0), g11 = (t3 - t2) * (1.0 / 12.0);
    w[0] = g10;
    w[1] = g11 - 8.0 * g10;
    w[2] = h00 - 8.0 * g11;
    w[3] = h01 + 8.0 * g10;
    w[4] = 8.0 * g11 - g10;
    w[5] = -g11;
    return j - 1;
  }
  const double H = dc_gwae_eta_node_u(j + 1) - dc_gwae_eta_node_u(j);
  const double h10 = (t3 - 2.0 * t2 + t) * H, h11 = (t3 - t2) * H;
  /* rows base .. base+5, within the rows -1 .. NETA+1 stored */
  const int base = j - 2 < -1 ? -1 : (j - 2 > DC_GWAE_NETA_U - 4 ? DC_GWAE_NETA_U - 4 : j - 2);
  double c[5];
  int r0;
  for (int m = 0; m < 6; m++) w[m] = 0.0;
  w[j - base] += h00;
  w[j + 1 - base] += h01;
  eta_slope_u(j, n1, c, &r0);
  for (int m = 0; m < 5; m++)
    if (c[m] != 0.0) w[r0 + m - base] += h10 * c[m];
  eta_slope_u(j + 1, n1, c, &r0);
  for (int m = 0; m < 5; m++)
    if (c[m] != 0.0) w[r0 + m - base] += h11 * c[m];
  return base + 1;
}

int dc_gwa_table_radius_init_elliptic(const dc_gwa_table_pair *p, double R_major, double R_minor,
                                      dc_gwa_table_radius *r)
{
  if (!(R_major >= R_minor && R_minor > 0.0 && R_major <= DBL_MAX)) return DC_EDOM;
  dc_gwa_table_radius q = {0};
  q.R = R_major;
  if (p->w > 0.0) {
    dc_gwa_table_ell *e = &q.ell;   /* q is zeroed */
    e->on = 1;
    e->rho = R_minor / R_major;
    if (e->rho < DC_GWAE_RHO_MIN) e->rho = DC_GWAE_RHO_MIN;
    const double L = -log(e->rho);
    /* the scales, uniform and finer in ln rho */
    double ws[4], s[4] = {0.0, 0.0, 0.0, 0.0};
    const int ks = cr_cell(L / dc_gwae_L_node(1, 1) * DC_GWAE_SCALE_PER_CELL, DC_GWAE_NRS * DC_GWAE_SCALE_PER_CELL, ws);
    for (int n = 0; n < 4; n++)
      for (int c = 0; c < 4; c++) s[c] += ws[n] * dc_gwae_scale[ks + n][c];
    e->ke = s[2];
    e->lr_inf = s[3];
    const double u = L / dc_gwae_L_node(1, 1);
    if (u < DC_GWAE_NR1 - 1) {   /* the branches' grids agree and are even */
      e->i[0] = e->i[1] = (int)u;
      cr_weights(u - e->i[0], e->wr[0]);
      for (int n = 0; n < 4; n++) e->wr[1][n] = e->wr[0][n];
    } else {
      e->i[0] = ln_rho_cell(L, DC_GWAE_NR2_L, e->wr[0]);
      e->i[1] = ln_rho_cell(L, DC_GWAE_NR2_U, e->wr[1]);
    }
    /* the circle of R_major's scales (dc_gwa_table_radius_init) times the
       matched ones': delta_c = dc_coef R^1/3 e^s0, F_s = 8 w n_asp R e^s1 */
    const double l3 = log(R_major) / 3.0;
    q.Fs = p->F_coef * R_major * exp(s[1]);
    q.db = -p->ub * p->dc_coef * exp(l3 + s[0]);
    q.D = q.db * p->inv_sigma;
    q.reach = q.db + DC_GWA_TABLE_X_HI * p->sigma;
    dc_gwa_table_eta_cell(p->ln_sigma_dc - l3 - s[0], &q.cell);
    const double eta = q.cell.eta, lo = DC_GWA_TABLE_ETA_LO;
    e->j[0] = cr_cell((eta - lo) * DC_GWAE_ETA_PER_UNIT_L, DC_GWAE_NETA_L, e->we[0]);
    e->j[1] = eta_cell_u(eta, e->we[1]);
    /* |ub| / tau is D unless eta was clamped */
    e->zs = eta == p->ln_sigma_dc - l3 - s[0] ? 1.0 / (q.D + DC_GWAE_Z_D0) : dc_gwae_z_scale(eta);
    if (!(isfinite(q.Fs) && isfinite(q.db) && isfinite(q.reach) && isfinite(eta))) return DC_ERANGE;
  }
  *r = q;
  return DC_OK;
}

void dc_gwa_table_ell_apply(const dc_gwa_table_ell *e, int b, double x, double eta, const double *kc,
                            dc_gwa_table_circle_fn circle, double *G, double *Gx)
{
  double dxi, xi = dc_gwae_xi(x, &dxi);
  const int deep = xi < DC_GWAE_XI_LO;
  if (deep) { xi = DC_GWAE_XI_LO; dxi = 0.0; }
  double z = xi, zlo = DC_GWAE_XI_LO;
  int nz = DC_GWAE_NXI;
  if (b == DC_GW_UNLOADING) {
    zlo -= DC_GWAE_Z_OFF;
    nz = DC_GWAE_NZ_U;
    if (deep) z = zlo;
    else if (xi <= DC_GWAE_XI_HI) z = dc_gwae_z(x, e->zs, &dxi);
    else { z = dc_gwae_z(DC_GWAE_XI_HI, e->zs, &dxi); dxi = 0.0; }   /* r held at x > 8 */
  }
  if (z > DC_GWAE_XI_HI) { z = DC_GWAE_XI_HI; dxi = 0.0; }   /* r held beyond the grid */
  double wx[4], dx[4];
  const double ux = (z - zlo) * DC_GWAE_XI_PER_UNIT;
  const int k = cr_cell(ux, nz, wx);
  cr_slopes(ux - k, dx);
  /* the 4 (unloading 6) x 4 (eta, ln rho) nodes mixed, at the 4 xi nodes */
  double a[4] = {0.0, 0.0, 0.0, 0.0};
  const int nj = b == DC_GW_UNLOADING ? 6 : 4;
  for (int jj = 0; jj < nj; jj++)
    for (int ii = 0; ii < 4; ii++) {
      const double w = e->we[b][jj] * e->wr[b][ii];
      const float *row = b == DC_GW_UNLOADING ? dc_gwae_unload[e->j[1] + jj][e->i[1] + ii] + k
                                              : dc_gwae_load[e->j[0] + jj][e->i[0] + ii] + k;
      for (int kk = 0; kk < 4; kk++) a[kk] += w * row[kk];
    }
  double lr = wx[0] * a[0] + wx[1] * a[1] + wx[2] * a[2] + wx[3] * a[3];
  double lrx = (dx[0] * a[0] + dx[1] * a[1] + dx[2] * a[2] + dx[3] * a[3]) * DC_GWAE_XI_PER_UNIT * dxi;
  const double r = exp(lr);
  if (deep) {
    /* below x_lo the kink-free ratio R = G_ell/G (the kink term's d^-1/2
       would spoil its tail) as two terms of one summit's series in d^-3/4,
       s = (x_lo/x)^3/4: R = r_oo + A s + B s^2, A and B from R at x_lo and
       its slope from the four nodes there; the grid's own slope
       (Catmull-Rom, ~1 % off) joined C1 by D s^K (s - 1), which fades
       within a third of the cell */
    enum { K = 12 };
    double Gl, Gxl, Cl = 0.0, Cxl = 0.0, dxl;
    dc_gwae_xi(dc_gwae_x_lo, &dxl);   /* dz/dx there too (z's other terms below 1e-70) */
    circle(b, dc_gwae_x_lo, eta, &Gl, &Gxl, &Cl, &Cxl);
    /* d ln r/dx at x_lo: four-point (error ~h^3) and Catmull-Rom */
    const double l4 = (-2.0 * a[0] - 3.0 * a[1] + 6.0 * a[2] - a[3]) * (DC_GWAE_XI_PER_UNIT / 6.0) * dxl;
    const double lc = (a[2] - a[0]) * (0.5 * DC_GWAE_XI_PER_UNIT) * dxl;
    const double Tl = Gl + Cl, Rl = (r * Tl - e->ke * Cl) / Gl, ri = exp(e->lr_inf);
    const double Rx4 = (r * (l4 * Tl + Gxl + Cxl) - e->ke * Cxl - Rl * Gxl) / Gl;
    /* dR/ds at s = 1 is -dR/dx x_lo/(3/4) */
    const double B = -Rx4 * dc_gwae_x_lo / 0.75 - (Rl - ri), A = Rl - ri - B;
    const double D = -r * Tl / Gl * (lc - l4) * dc_gwae_x_lo / 0.75;
    const double s = pow(dc_gwae_x_lo / x, 0.75), s2 = s * s, s4 = s2 * s2, sK1 = s4 * s4 * s2 * s;   /* s^(K-1) */
    const double R = ri + s * (A + B * s) + D * sK1 * s * (s - 1.0);
    const double Rs = A + 2.0 * B * s + D * sK1 * ((K + 1) * s - K);
    *Gx = *Gx * R - 0.75 * s / x * Rs * *G;
    *G *= R;
    return;
  }
  const double C = kc[0], Cx = kc[1];
  const double T = *G + C, Tx = *Gx + Cx;
  *G = r * T - e->ke * C;
  *Gx = r * (lrx * T + Tx) - e->ke * Cx;
}
