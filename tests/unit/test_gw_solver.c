/* Full GW solver (Feng Secs. 2-6) against Feng Table 3 and Table 2, the
   Hertz limit, and the explicit law's nodal values (Feng Tables 4-6). */
#include "check.h"
#include "dc/feng_rough.h"
#include "dc/gw_solver.h"
#include "dc/status.h"
#include <time.h>

/* Feng Table 3: P*(alpha, mu = 4), alpha = 0.1, 1, 5 */
static const int t3_m[6] = {5, 10, 20, 50, 100, 200};
static const double t3[6][3] = {
  {0.9701255, 2.0143635, 11.077996}, {0.9770791, 2.0139965, 11.070676},
  {0.9769659, 2.0138868, 11.071660}, {0.9769516, 2.0138709, 11.071798},
  {0.9769507, 2.0138699, 11.071806}, {0.9769506, 2.0138697, 11.071807}};

static void table3(void)
{
  const double alpha[3] = {0.1, 1.0, 5.0};
  /* the paper's choices (dc/gw_solver.h): abar = (1.5 + alpha) (R delta)^1/2
     (in r* units x (alpha'/2)^1/2), force by Eq. 54, F_3/2 by 10 Gauss points */
  printf("Feng Table 3 (mu = 4), P*(alpha) = P/P_h(delta); abar = (1.5 + alpha) a, Eq. 54, F_3/2 by 10 Gauss points\n");
  double worst = 0.0;
  for (int k = 0; k < 6; k++) {
    dc_gw_solver S;
    CHECK(dc_gw_solver_init(&S, t3_m[k]) == DC_OK);
    printf("  m = %3d:", t3_m[k]);
    for (int a = 0; a < 3; a++) {
      dc_gw_solve_opts o = dc_gw_solve_default_opts();
      o.abar = (1.5 + alpha[a]) * sqrt(0.5 / alpha[a]);
      o.force_mode = DC_GW_FORCE_DOMAIN;
      o.f32_mode = DC_GW_F32_GAUSS10;
      dc_gw_solve_result r;
      CHECK(dc_gw_solve(&S, 1.0 / alpha[a], 4.0, &o, &r) == DC_OK);
      printf("  %.7f (paper %.7f, %+.5f%%)", r.Pstar_delta, t3[k][a], 100 * (r.Pstar_delta / t3[k][a] - 1));
      worst = fmax(worst, fabs(r.Pstar_delta / t3[k][a] - 1));
      /* the issue asks for 0.2%; the identified choices give < 1e-5 */
      CHECK_REL(r.Pstar_delta, t3[k][a], 1e-5, "Feng Table 3");
    }
    printf("\n");
    dc_gw_solver_free(&S);
  }
  printf("  worst relative difference from the printed table: %.1e\n", worst);

  /* domain-converged values (m = 200, FORCE_FULL): independent of the
     domain (1.5 and 2.5 x Eq. 60 agree), equal to the paper's m = 200
     values at alpha = 0.1 and 5; at alpha = 1 above it by the pressure the
     paper's domain (2.5 a) cuts from Eq. 54 */
  dc_gw_solver S;
  dc_gw_solver_init(&S, 200);
  printf("  domain-converged (m = 200, force over the whole plane):");
  for (int a = 0; a < 3; a++) {
    double P[2];
    for (int d = 0; d < 2; d++) {
      dc_gw_solve_opts o = dc_gw_solve_default_opts();
      o.domain_scale = d ? 2.5 : 1.5;
      o.f32_mode = DC_GW_F32_GAUSS10;
      dc_gw_solve_result r;
      CHECK(dc_gw_solve(&S, 1.0 / alpha[a], 4.0, &o, &r) == DC_OK);
      P[d] = r.Pstar_delta;
    }
    CHECK_REL(P[1], P[0], 1e-6, "domain-converged");
    dc_gw_solve_opts o = dc_gw_solve_default_opts();
    o.abar = (1.5 + alpha[a]) * sqrt(0.5 / alpha[a]);
    o.f32_mode = DC_GW_F32_GAUSS10;
    dc_gw_solve_result r;   /* the paper's domain, force over the whole plane */
    CHECK(dc_gw_solve(&S, 1.0 / alpha[a], 4.0, &o, &r) == DC_OK);
    printf("  alpha = %g: %.7f (paper %+.4f%%; paper's domain with the outer force %+.4f%%)", alpha[a],
           P[0], 100 * (P[0] / t3[5][a] - 1), 100 * (r.Pstar_delta / t3[5][a] - 1));
    if (a != 1) CHECK_REL(P[0], t3[5][a], 2e-6, "converged = paper at alpha = 0.1, 5");
  }
  printf("\n");
  dc_gw_solver_free(&S);
}

static void table2(void)
{
  /* quadratic convergence (Feng Table 2: mu = 4, m = 100, alpha = 0.01, 0.1, 1) */
  dc_gw_solver S;
  dc_gw_solver_init(&S, 100);
  const double alpha[3] = {0.01, 0.1, 1.0};
  for (int a = 0; a < 3; a++) {
    dc_gw_solve_opts o = dc_gw_solve_default_opts();
    o.tol = 1e-13;   /* rounding floor of ||dp||/||p|| at m = 100: ~1e-14 */
    dc_gw_solve_result r;
    int st = dc_gw_solve(&S, 1.0 / alpha[a], 4.0, &o, &r);
    CHECK(st == DC_OK);
    CHECK(r.iterations <= 9);
    printf("Table 2 alpha = %g:", alpha[a]);
    for (int i = 0; i < r.iterations; i++) printf(" %.2e", r.hist[i]);
    printf("\n");
    /* quadratic: once e < 1e-2, e_{k+1} <= 10 e_k^2 (until rounding) */
    for (int i = 0; i + 1 < r.iterations; i++)
      if (r.hist[i] < 1e-2 && r.hist[i + 1] > 1e-13) CHECK(r.hist[i + 1] <= 10 * r.hist[i] * r.hist[i]);
  }
  dc_gw_solver_free(&S);
}

static void hertz_limit(void)
{
  /* Feng Sec. 4: P* -> 1 as alpha -> 0, deformation error ~ (16 sqrt2 alpha/(3 pi mu))^2/3 */
  dc_gw_solver S;
  dc_gw_solver_init(&S, 100);
  dc_gw_solve_opts o = dc_gw_solve_default_opts();
  dc_gw_solve_result r;
  CHECK(dc_gw_solve(&S, 1e4, 2.0, &o, &r) == DC_OK);
  const double eps = pow(16 * M_SQRT2 * 1e-4 / (3 * M_PI * 2.0), 2.0 / 3.0);
  printf("alpha = 1e-4, mu = 2: P* = %.6f (eps_w = %.2e)\n", r.Pstar_delta, eps);
  CHECK_ABS(r.Pstar_delta, 1.0, 2 * eps, "Hertz limit alpha -> 0");
  dc_gw_solver_free(&S);
}

static void law_nodes(void)
{
  /* the tabulated polynomials interpolate the solver at their nodes: the
     solver must reproduce them (4-digit coefficients: ~1e-3 absolute) */
  dc_gw_solver S;
  dc_gw_solver_init(&S, 40);
  /* nodes: alpha = 1/3, 2/3 (alpha' = 3, 1.5); alpha' = 1/2; -3/4 ... -3 */
  const double aps[] = {3.0, 1.5, 0.5, -0.75, -1.5, -2.25, -3.0};
  double worst = 0;
  for (int i = 0; i < 7; i++) {
    dc_feng_law L;
    dc_feng_init(dc_feng_mu_nodes[i], DC_FENG_TABLE, &L);
    for (int k = 0; k < 7; k++) {
      dc_gw_solve_opts o = dc_gw_solve_default_opts();
      o.domain_scale = 1.5;
      dc_gw_solve_result r;
      CHECK(dc_gw_solve(&S, aps[k], dc_feng_mu_nodes[i], &o, &r) == DC_OK);
      /* undo the alpha' = -3 continuity taper to compare the table's polynomial */
      const double q = aps[k] < 0 ? aps[k] / 3.0 : 0.0;
      const double law = dc_feng_pstar_sigma(&L, aps[k]) + L.p3m3 * q * q * q * q;
      /* the alpha' = -3 node is moved by the continuity taper: skip it */
      if (k == 6) continue;
      /* allowance: 1% plus the rounding of 4-decimal coefficients,
         0.5e-4 sum_k |x|^k over the polynomial's degree, in its variable x */
      const double x = aps[k] >= 1 ? 1.0 / aps[k] : aps[k];
      const int deg = aps[k] >= 1 ? 3 : 4;
      double round = 0, xp = 1;
      for (int d = 0; d <= deg; d++) { round += 0.5e-4 * xp; xp *= fabs(x); }
      if (aps[k] >= 1) round *= aps[k] * sqrt(aps[k]);
      const double err = fabs(law - r.Pstar_sigma);
      worst = fmax(worst, err / r.Pstar_sigma);
      if (err > 0.01 * r.Pstar_sigma) printf("  mu = %g alpha' = %g: law %.4f solver %.4f\n", dc_feng_mu_nodes[i], aps[k], law, r.Pstar_sigma);
      CHECK(err <= 0.01 * r.Pstar_sigma + round);
    }
  }
  printf("explicit law (table) vs solver at the interpolation nodes: worst rel. err %.2e\n", worst);
  dc_gw_solver_free(&S);
}

static void timing(void)
{
  dc_gw_solver S;
  dc_gw_solver_init(&S, 20);
  dc_gw_solve_opts o = dc_gw_solve_default_opts();
  dc_gw_solve_result r;
  const int n = 200;
  clock_t t0 = clock();
  for (int i = 0; i < n; i++) dc_gw_solve(&S, 0.5 + i * 0.01, 4.0, &o, &r);
  const double us = 1e6 * (double)(clock() - t0) / CLOCKS_PER_SEC / n;
  printf("one full solve at m = 20: %.1f us\n", us);
  CHECK(us < 1000.0);
  dc_gw_solver_free(&S);
}

int main(void)
{
  table3();
  table2();
  hertz_limit();
  law_nodes();
  timing();
  return check_summary("gw_solver");
}
