/* Feng explicit law (Eq. 75, Tables 4-6): every tabulated mu reproduced,
   continuity at alpha = 1, alpha' = 0 and alpha' = -3 for both variants and
   mu across [1, 50], stiffness = dP/d delta, Hertz for sigma = 0, domain. */
#include "check.h"
#include "dc/feng_rough.h"
#include "dc/status.h"

static double P(const dc_feng_law *L, double delta, double sigma)
{
  double p, k;
  dc_feng_force(L, 1e9, 1e-3, sigma, delta, &p, &k);
  return p;
}

int main(void)
{
  /* tabulated mu: the table variant reproduces Tables 4-6. The node
     alpha = 1 is shared with Case II, whose 4-decimal sum can differ from
     Table 4's by 1e-4 (mu = 20, 35, 50); moving that node by D changes the
     cubic by D L_3(alpha) = D (4.5 a^3 - 4.5 a^2 + a), exactly. */
  for (int i = 0; i < 7; i++) {
    dc_feng_law L;
    CHECK(dc_feng_init(dc_feng_mu_nodes[i], DC_FENG_TABLE, &L) == DC_OK);
    double D = 0;
    for (int k = 0; k < 3; k++) D += dc_feng_table_II[k][i];
    for (int k = 0; k < 4; k++) D -= dc_feng_table_I[k][i];
    CHECK(fabs(D) <= 1.5e-4);
    const double shift[4] = {0, D, -4.5 * D, 4.5 * D};
    for (int k = 0; k < 4; k++) CHECK_ABS(L.b1[k], dc_feng_table_I[k][i] + shift[k], 1e-12, "Table 4");
    for (int k = 0; k < 3; k++) CHECK_ABS(L.b2[k], dc_feng_table_II[k][i], 1e-12, "Table 5");
    for (int k = 0; k < 5; k++) CHECK_ABS(L.b3[k], dc_feng_table_III[k][i], 1e-12, "Table 6");
    /* fitted formulas vs the table (they are least-squares fits: report) */
    dc_feng_law Lf;
    dc_feng_init(dc_feng_mu_nodes[i], DC_FENG_FITTED, &Lf);
    printf("mu = %4g: fitted - table: P1*(1/2) %+.4f  P2*(1/2) %+.4f  P3*(-3/2) %+.4f\n",
           dc_feng_mu_nodes[i], dc_feng_P1(&Lf, 0.5) - dc_feng_P1(&L, 0.5),
           dc_feng_pstar_sigma(&Lf, 0.5) - dc_feng_pstar_sigma(&L, 0.5),
           dc_feng_pstar_sigma(&Lf, -1.5) - dc_feng_pstar_sigma(&L, -1.5));
    CHECK_ABS(dc_feng_pstar_sigma(&Lf, 0.5), dc_feng_pstar_sigma(&L, 0.5), 0.05, "fitted ~ table, Case II");
  }
  /* continuity at the case boundaries, both variants, mu across the range */
  const double sigma = 1e-6;
  for (int v = 0; v < 2; v++)
    for (double mu = 1.0; mu <= 50.0; mu *= 1.17) {
      dc_feng_law L;
      CHECK(dc_feng_init(mu, v, &L) == DC_OK);
      const double scale = P(&L, sigma, sigma);
      const double b[3] = {1.0, 0.0, -3.0};
      for (int k = 0; k < 3; k++) {
        const double d = b[k] * sigma, e = 1e-9 * sigma;
        CHECK_ABS(P(&L, d - e, sigma), P(&L, d + e, sigma), 1e-7 * scale, "continuity at a case boundary");
      }
    }
  /* stiffness = dP/d delta in each case; sigma = 0 is Hertz */
  dc_feng_law L;
  dc_feng_init(7.0, DC_FENG_TABLE, &L);
  const double ds[] = {3e-6, 0.4e-6, -1e-6, -2.9e-6};
  for (int k = 0; k < 4; k++) {
    double p, kn, pp, pm, kk;
    dc_feng_force(&L, 1e9, 1e-3, sigma, ds[k], &p, &kn);
    dc_feng_force(&L, 1e9, 1e-3, sigma, ds[k] + 1e-12, &pp, &kk);
    dc_feng_force(&L, 1e9, 1e-3, sigma, ds[k] - 1e-12, &pm, &kk);
    CHECK_REL(kn, (pp - pm) / 2e-12, 1e-5, "kn = dP/d delta");
  }
  double p, kn;
  CHECK(dc_feng_force(&L, 1e9, 1e-3, 0.0, 1e-6, &p, &kn) == DC_OK);
  CHECK_REL(p, 4.0 / 3 * 1e9 * sqrt(1e-3) * pow(1e-6, 1.5), 1e-15, "sigma = 0: Hertz");
  CHECK(dc_feng_force(&L, 1e9, 1e-3, sigma, -3.5 * sigma, &p, &kn) == DC_OK && p == 0.0);
  CHECK(dc_feng_force(&L, 1e9, 1e-3, 0.0, -1e-6, &p, &kn) == DC_OK && p == 0.0 && kn == 0.0);
  /* Case III as evaluated: Table 6's quartic minus the taper P3*(-3) (alpha'/3)^4 */
  for (double ap = -2.9; ap < 0.0; ap += 0.3) {
    double q = 0.0;
    for (int k = 4; k >= 0; k--) q = q * ap + L.b3[k];
    q -= L.p3m3 * pow(ap / 3.0, 4);
    dc_feng_force(&L, 1e9, 1e-3, sigma, ap * sigma, &p, &kn);
    CHECK_ABS(p / (4.0 / 3 * 1e9 * sqrt(1e-3) * pow(sigma, 1.5)), fmax(q, 0.0), 1e-14, "Case III with taper");
  }
  /* the bound pair (plugin hot path) is the same kernel */
  dc_feng_pair pr;
  CHECK(dc_feng_pair_init(&L, 1e9, sigma, &pr) == DC_OK);
  CHECK(dc_feng_pair_init(&L, 1e9, 0.0, &pr) == DC_EDOM);
  dc_feng_pair_init(&L, 1e9, sigma, &pr);
  for (int k = 0; k < 4; k++) {
    double p2, k2;
    dc_feng_force(&L, 1e9, 1e-3, sigma, ds[k], &p, &kn);
    dc_feng_pair_force(&pr, sqrt(1e-3), ds[k], &p2, &k2);
    CHECK(p == p2 && kn == k2);
  }
  /* domain */
  CHECK(dc_feng_init(0.99, DC_FENG_TABLE, &L) == DC_EDOM);
  CHECK(dc_feng_init(50.01, DC_FENG_FITTED, &L) == DC_EDOM);
  CHECK(dc_feng_init(NAN, DC_FENG_FITTED, &L) == DC_EDOM);
  CHECK(dc_feng_init(5, 7, &L) == DC_EDOM);
  /* random laws and overlaps (fixed seed): mu in [1, 50], both variants,
     delta from -4 sigma to 1000 sigma: finite, non-negative force */
  unsigned long long x = 88172645463325252ull;
  int bad = 0;
  for (int k = 0; k < 100000; k++) {
    const double mu = 1.0 + 49.0 * check_uniform(&x), u = check_uniform(&x);
    const double d = sigma * (-4.0 + 1e3 * u * u);
    if (dc_feng_init(mu, k & 1 ? DC_FENG_FITTED : DC_FENG_TABLE, &L) != DC_OK ||
        dc_feng_force(&L, 1e9, 1e-3, sigma, d, &p, &kn) != DC_OK || !(isfinite(p) && isfinite(kn) && p >= 0.0)) {
      if (bad < 5) printf("random Feng: mu %g delta/sigma %g: P %g\n", mu, d / sigma, p);
      bad++;
    }
  }
  CHECK(bad == 0);
  return check_summary("feng_rough");
}
