/* Writes c_core/src/gw_rough_adhesive_elliptic_data.h: the correction of
   dc/gw_rough_adhesive_table.h for elliptic summits ("Elliptic summits"
   there), from the exact c_core law dc_gw_rough_adhesive with the
   summits of dc_jkr_geometry(1, rho) (E* = w = R_major = n_asp = 1) less
   the closed form dc_gw_rough_elliptic, against the circular table
   dc_gwa_table_reduced at the matched scales:

     r = (G_ell + k_e C) / (G + C)   (loading: C = 0),
     G_ell = (F_adhesive - F_gw_elastic) / F_s,m,  F_s,m = F_break/(-5 pi/48),
     delta_c,m = delta_break / ub, tau = sigma / delta_c,m,
     k_e = F_gw_elastic(h = 0) / (F_s,m c_H tau^3/2 F_3/2(0)),

   stored as ln r in float (7 digits, far below the interpolation error).
   Nodes in ln rho at dc_gwae_L_node (NR1 cells to 1e-4, NR2 per branch
   below); in x at xi nodes (loading) or at z nodes of dc_gwae_z, which
   follow x/D where D is large (unloading; x found by bisection); eta rows
   1/4 apart (loading) or at dc_gwae_eta_node_u (unloading: 1/8 apart up
   to eta = 2, 1/4 above). Ghost nodes (one beyond each end) from the law too, except in
   eta (the circular table is clamped beyond its rows), at x > 8 (the
   circular table's continuation), there extrapolated through three nodes
   (exact for quadratics), and below RHO_MIN (the law's smallest ratio),
   there through four (exact for cubics; three left 1e-4 in the last cell).
   The scales: ln(delta_c,m / delta_c(R_major)), ln(F_s,m / 8 w R_major),
   k_e, ln r_oo (r_oo from one summit's large-compression series, ln_r_oo)
   at SCALE_PER_CELL nodes per cell of ln(1e4)/NR1 on [ln RHO_MIN, 0] (the
   ghost below RHO_MIN through four nodes).
   About 20 s on 2 cores with OpenMP.
   Regenerate (from the repository root, library built in B):
     cc -O2 -fopenmp -std=gnu11 -Wall -Wextra -Ic_core/include tests/reference/gen_gw_rough_adhesive_elliptic.c \
        B/c_core/libdemcontact.a -lgsl -lgslcblas -lm -o /tmp/gen_gwae && \
     /tmp/gen_gwae > c_core/src/gw_rough_adhesive_elliptic_data.h */
#include "dc/gw_integrals.h"
#include "dc/hertz_elliptic.h"
#include "dc/gw_rough.h"
#include "dc/gw_rough_adhesive.h"
#include "dc/gw_rough_adhesive_table.h"
#include "dc/jkr_elliptic.h"
#include "dc/status.h"
#include <gsl/gsl_multifit.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define UB (-0.375 * 4.60115111447049)
#define CH 0.15005271935951767

static void fail(const char *what, double lr, int b, double x, double eta)
{
  fprintf(stderr, "%s at ln rho %g, branch %d, x %g, eta %g\n", what, lr, b, x, eta);
  exit(1);
}

static void geometry(double lr, dc_jkr_geom *g, double *dcm, double *Fsm)
{
  /* the last node, ln RHO_MIN up to rounding, at the law's smallest ratio */
  double rho = exp(lr);
  if (rho < DC_GWAE_RHO_MIN && rho > DC_GWAE_RHO_MIN * (1.0 - 1e-12)) rho = DC_GWAE_RHO_MIN;
  if (dc_jkr_geometry(1.0, rho, 1.0, 1.0, g) != DC_OK) fail("dc_jkr_geometry", lr, 0, 0, 0);
  *dcm = g->delta_break / UB;
  *Fsm = g->F_break / (-5.0 * M_PI / 48.0);
}

/* k_e at ln rho lr */
static double ke_of(double lr)
{
  dc_jkr_geom g;
  double dcm, Fsm, F[4];
  geometry(lr, &g, &dcm, &Fsm);
  dc_gw_rough_state e;
  if (dc_gw_rough_elliptic(&g.hertz, 1.0, 1.0, dcm, 0.0, &e) != DC_OK) fail("closed form", lr, 0, 0, 0);
  dc_gw_F_all(0.0, F);
  return e.F / (Fsm * CH * F[DC_GW_F32]);   /* tau = 1: sigma = delta_c,m */
}

/* ln r_oo at ln rho lr: one summit's adhesive part over F_s,m at infinite
   compression over the circle's -pi/8. It is a series in t = (delta /
   |delta_break|)^-3/4; states of dc_jkr_at_eccentricity at 80 e^2 between
   the Hertz one and t = 0.2 (t log-uniform from t = 0.004), less the Hertz
   force at their delta, fitted by least squares with a polynomial of
   degree 10 in t (ranges 0.1 to 0.4 and degrees 10, 12 agree within
   2e-10). The former value, the ratio at x = -1e4 and eta = 8, carried
   noise of ~1e-4 from the elastic part (a mean compression of 3e7 delta_c). */
static double ln_r_oo(double lr)
{
  dc_jkr_geom g;
  double dcm, Fsm;
  geometry(lr, &g, &dcm, &Fsm);
  if (g.circular) return 0.0;   /* the circle's law: r = 1 */
  enum { N = 80, DEG = 10 };
  const double T = 0.2, t0 = 0.02 * T;
  double t[N], G[N], k = 0.0;
  /* the state at relative distance eps from the Hertz e^2 (1 - e^2 for
     slender contacts); t is nearly proportional to eps */
  for (int pass = 0; pass < 2; pass++)
    for (int i = 0; i < (pass ? N : 1); i++) {
      const double eps = pass ? t0 / k * pow(T / t0, (double)i / (N - 1)) : 1e-3;
      const double e2 = g.use_m1 ? 1.0 - g.v_hertz * (1.0 + eps) : g.e2_hertz * (1.0 - eps);
      dc_jkr_state s;
      dc_hertz_state h;
      if (dc_jkr_at_eccentricity(&g, e2, &s) != DC_OK || dc_hertz_contact(&g.hertz, g.Estar, s.delta, &h) != DC_OK)
        fail("r_oo: summit state", lr, 0, 0, 0);
      const double ti = pow(s.delta / -g.delta_break, -0.75);
      if (!pass) { k = ti / eps; continue; }
      t[i] = ti / T;
      G[i] = (s.F - h.F) / Fsm;
    }
  gsl_matrix *X = gsl_matrix_alloc(N, DEG + 1), *cov = gsl_matrix_alloc(DEG + 1, DEG + 1);
  gsl_vector *y = gsl_vector_alloc(N), *c = gsl_vector_alloc(DEG + 1);
  gsl_multifit_linear_workspace *w = gsl_multifit_linear_alloc(N, DEG + 1);
  for (int i = 0; i < N; i++) {
    for (int j = 0; j <= DEG; j++) gsl_matrix_set(X, i, j, pow(t[i], j));
    gsl_vector_set(y, i, G[i]);
  }
  double chi;
  if (gsl_multifit_linear(X, y, c, cov, &chi, w)) fail("r_oo: fit", lr, 0, 0, 0);
  const double G_oo = gsl_vector_get(c, 0);
  gsl_multifit_linear_free(w);
  gsl_matrix_free(X);
  gsl_matrix_free(cov);
  gsl_vector_free(y);
  gsl_vector_free(c);
  if (!(G_oo < 0.0)) fail("r_oo: not negative", lr, 0, 0, 0);
  return log(G_oo / (-M_PI / 8.0));
}

/* ln r at (ln rho, branch, x, eta) */
static double ln_ratio(double lr, int b, double x, double eta)
{
  dc_jkr_geom g;
  double dcm, Fsm, G, Gx, C = 0.0, Cx = 0.0;
  geometry(lr, &g, &dcm, &Fsm);
  const double sigma = exp(eta) * dcm, D = -g.delta_break / sigma, h = b ? x + D : x;
  dc_gw_adhesive_state s;
  dc_gw_rough_state e;
  if (dc_gw_rough_adhesive(&g, 1.0, sigma, -h * sigma, b, &s) != DC_OK ||
      dc_gw_rough_elliptic(&g.hertz, 1.0, 1.0, sigma, -h * sigma, &e) != DC_OK ||
      dc_gwa_table_reduced(b, x, eta, &G, &Gx) != DC_OK)
    fail("law", lr, b, x, eta);
  if (b == DC_GW_UNLOADING) dc_gwa_table_kink(x, eta, &C, &Cx);
  const double r = ((s.F - e.F) / Fsm + ke_of(lr) * C) / (G + C);
  if (!(r > 0.0 && isfinite(r))) fail("ratio not positive", lr, b, x, eta);
  return log(r);
}

/* x at node k of branch b's grid in row eta (unloading: z(x) = the node's
   z, by bisection; z <= xi and z >= xi - Z_OFF - 1 bracket it) */
static double x_node(int b, int k, double eta)
{
  const double zk = b == DC_GW_UNLOADING ? DC_GWAE_XI_LO - DC_GWAE_Z_OFF + (double)k / DC_GWAE_XI_PER_UNIT
                                         : DC_GWAE_XI_LO + (double)k / DC_GWAE_XI_PER_UNIT;
  if (b != DC_GW_UNLOADING) return dc_gwae_x_of_xi(zk);
  const double zs = dc_gwae_z_scale(eta);
  double lo = dc_gwae_x_of_xi(zk), hi = dc_gwae_x_of_xi(zk + DC_GWAE_Z_OFF + 1.0), dz;
  if (!(dc_gwae_z(lo, zs, &dz) <= zk && dc_gwae_z(hi, zs, &dz) >= zk)) fail("z node not bracketed", 0, b, zk, eta);
  for (int it = 0; it < 1000 && hi - lo > 1e-15 * fabs(lo); it++) {
    const double m = 0.5 * (lo + hi);
    if (dc_gwae_z(m, zs, &dz) < zk) lo = m; else hi = m;
  }
  return 0.5 * (lo + hi);
}

static void branch_table(int b, int ne, int per_unit, int n2, float *t)
{
  const int nr = DC_GWAE_NR1 + n2, NRN = nr + 3, nx = b == DC_GW_UNLOADING ? DC_GWAE_NZ_U : DC_GWAE_NXI,
            NXN = nx + 3;
#define AT(j, i, k) t[((size_t)(j) * NRN + (i)) * NXN + (k)]
  if (fabs(dc_gwae_L_node(nr, n2) + log(DC_GWAE_RHO_MIN)) > 1e-12) fail("the ln rho grid misses RHO_MIN", 0, b, 0, 0);
#pragma omp parallel for schedule(dynamic)
  for (int j = 0; j <= ne; j++)
    for (int i = -1; i <= nr; i++)
      for (int k = -1; k <= nx; k++) {
        const double eta =
            b == DC_GW_UNLOADING ? dc_gwae_eta_node_u(j) : DC_GWA_TABLE_ETA_LO + (double)j / per_unit;
        AT(j + 1, i + 1, k + 1) = (float)ln_ratio(-dc_gwae_L_node(i, n2), b, x_node(b, k, eta), eta);
      }
  for (int j = 1; j <= ne + 1; j++)
    for (int i = 0; i < NRN - 1; i++) {
      float *r = &AT(j, i, 0);
      r[NXN - 1] = 3.0f * r[NXN - 2] - 3.0f * r[NXN - 3] + r[NXN - 4];
    }
  /* the ghost below RHO_MIN (the law stops there): cubic through the last
     four nodes (three, exact for quadratics only, left 1e-4 in the last cell) */
  for (int j = 1; j <= ne + 1; j++)
    for (int k = 0; k < NXN; k++)
      AT(j, NRN - 1, k) = 4.0f * AT(j, NRN - 2, k) - 6.0f * AT(j, NRN - 3, k) + 4.0f * AT(j, NRN - 4, k) -
                          AT(j, NRN - 5, k);
  for (int i = 0; i < NRN; i++)
    for (int k = 0; k < NXN; k++) {
      AT(0, i, k) = 3.0f * AT(1, i, k) - 3.0f * AT(2, i, k) + AT(3, i, k);
      AT(ne + 2, i, k) = 3.0f * AT(ne + 1, i, k) - 3.0f * AT(ne, i, k) + AT(ne - 1, i, k);
    }
#undef AT
}

static void print_table(const char *name, int ne, int nr, int NXN, const float *t)
{
  const int NRN = nr + 3;
  printf("static const float %s[%d][%d][%d] = {\n", name, ne + 3, NRN, NXN);
  for (int j = 0; j < ne + 3; j++) {
    printf("{\n");
    for (int i = 0; i < NRN; i++) {
      printf("{");
      for (int k = 0; k < NXN; k++) printf("%.7g%s", t[((size_t)j * NRN + i) * NXN + k], k + 1 < NXN ? "," : "");
      printf("}%s\n", i + 1 < NRN ? "," : "");
    }
    printf("}%s\n", j + 1 < ne + 3 ? "," : "");
  }
  printf("};\n");
}

int main(void)
{
  const int ne[2] = {DC_GWAE_NETA_L, DC_GWAE_NETA_U}, pu[2] = {DC_GWAE_ETA_PER_UNIT_L, DC_GWAE_ETA_PER_UNIT_U};
  const int n2[2] = {DC_GWAE_NR2_L, DC_GWAE_NR2_U}, nr[2] = {DC_GWAE_NR1 + n2[0], DC_GWAE_NR1 + n2[1]};
  const int nx[2] = {DC_GWAE_NXI, DC_GWAE_NZ_U};
  float *t[2];
  for (int b = 0; b < 2; b++) {
    t[b] = malloc(sizeof(float) * (ne[b] + 3) * (nr[b] + 3) * (nx[b] + 3));
    if (!t[b]) return 1;
    branch_table(b, ne[b], pu[b], n2[b], t[b]);
  }
  const int ns = DC_GWAE_NRS * DC_GWAE_SCALE_PER_CELL;
  const double hs = dc_gwae_L_node(1, 1) / DC_GWAE_SCALE_PER_CELL;
  if (fabs(ns * hs + log(DC_GWAE_RHO_MIN)) > 1e-12) fail("the scales miss RHO_MIN", 0, 0, 0, 0);
  printf("/* Generated by tests/reference/gen_gw_rough_adhesive_elliptic.c: do not edit.\n"
         "   ln r per branch [eta node][ln rho node][xi node (unloading: z)], each with one ghost\n"
         "   node first; the scales per ln rho node (SCALE_PER_CELL per cell of\n"
         "   ln(1e4)/NR1, one ghost first): ln(delta_c,m/delta_c(R_major)), ln(F_s,m/8 w R_major), k_e,\n"
         "   ln r_oo; x_lo = x(XI_LO)\n"
         "   (dc/gw_rough_adhesive_table.h, \"Elliptic summits\"). */\n");
  printf("static const double dc_gwae_x_lo = %.17g;\n", dc_gwae_x_of_xi(DC_GWAE_XI_LO));
  printf("static const double dc_gwae_scale[%d][4] = {\n", ns + 3);
  const double dc1 = 0.5 * pow(8.0 / M_PI, 2.0 / 3.0);   /* delta_c of the circle R = 1 */
  double(*sc)[4] = malloc(sizeof(double[4]) * (ns + 3));
  if (!sc) return 1;
  for (int n = -1; n <= ns; n++) {
    const double lr = -n * hs;
    dc_jkr_geom g;
    double dcm, Fsm;
    geometry(lr, &g, &dcm, &Fsm);
    sc[n + 1][0] = log(dcm / dc1);
    sc[n + 1][1] = log(Fsm / 8.0);
    sc[n + 1][2] = ke_of(lr);
    sc[n + 1][3] = ln_r_oo(lr);
  }
  for (int c = 0; c < 4; c++)   /* the ghost below RHO_MIN */
    sc[ns + 2][c] = 4.0 * sc[ns + 1][c] - 6.0 * sc[ns][c] + 4.0 * sc[ns - 1][c] - sc[ns - 2][c];
  for (int n = 0; n < ns + 3; n++)
    printf("{%.17g,%.17g,%.17g,%.17g}%s\n", sc[n][0], sc[n][1], sc[n][2], sc[n][3], n + 1 < ns + 3 ? "," : "");
  printf("};\n");
  print_table("dc_gwae_load", ne[0], nr[0], nx[0] + 3, t[0]);
  print_table("dc_gwae_unload", ne[1], nr[1], nx[1] + 3, t[1]);
  return 0;
}
